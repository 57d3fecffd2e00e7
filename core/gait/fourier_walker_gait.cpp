#include "core/gait/fourier_walker_gait.h"

#include <cmath>
#include <numbers>

#include "core/common/errors.h"
#include "core/eigenwalker/fourier.h"
#include "core/gait/gait_events.h"
#include "core/gait/joint_angles.h"

namespace ew {

GaitMeasures measureTwoHarmonicGait(const Eigen::Ref<const Eigen::MatrixXd>& framesX45, double rateHz,
                                    const GaitEventSet& events, const std::string& name) {
  const GaitMeasures asTheFeetSlide = measureGait(framesX45, rateHz, events, std::nullopt, name);
  if (!(asTheFeetSlide.stanceFootSpeedMps > 0)) return asTheFeetSlide;
  GaitMeasures g = measureGait(framesX45, rateHz, events,
                               asTheFeetSlide.stanceFootSpeedMps / kTwoHarmonicStanceSpeedRatio, name);
  g.speedSource = "stance feet of a two-harmonic walker";
  return g;
}

FourierWalkerGait measureFourierWalker(const Eigen::Ref<const Eigen::VectorXd>& w, double strideHz,
                                       std::optional<double> speedMps, const std::string& name) {
  FourierWalkerGait out;
  try {
    if (w.size() != 225 || !(strideHz > 0) || !std::isfinite(strideHz))
      throw Error(ErrorKind::BadArgument, name, "", "no 3D walker to measure");
    const int frames = static_cast<int>(std::lround(kWalkerGaitCycles / strideHz * kWalkerGaitRateHz));
    out.framesMm = synthesizeFrames(w, 2.0 * std::numbers::pi * strideHz, 0.0, frameTimes(frames, kWalkerGaitRateHz));
    const GaitEventSet events = gaitEventsFromKinematics(out.framesMm, kWalkerGaitRateHz);
    out.measures = speedMps ? measureGait(out.framesMm, kWalkerGaitRateHz, events, speedMps, name)
                            : measureTwoHarmonicGait(out.framesMm, kWalkerGaitRateHz, events, name);
    const JointAngles angles = jointAngles(out.framesMm, Eigen::Vector3d::UnitZ(), name);
    out.curves = flexionCycleCurves(angles.degrees, angles.names, kWalkerGaitRateHz, *out.measures);
  } catch (const Error& e) {
    out.measures.reset();
    out.error = e.problem();
  }
  return out;
}

}  // namespace ew
