#include "core/experiments/gait_agreement.h"

#include <cmath>
#include <map>
#include <tuple>

#include "core/common/errors.h"
#include "core/common/statistics.h"
#include "core/gait/fourier_walker_gait.h"
#include "core/gait/gait_measures.h"
#include "core/gait/joint_angles.h"

namespace ew {
namespace {

struct MeasuredSide {
  std::optional<GaitMeasures> measures;
  std::vector<CycleCurve> curves;
};

MeasuredSide measure(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, double rateHz, const GaitSideWalk& walk,
                     const std::string& name) {
  MeasuredSide side;
  try {
    const GaitEventSet events = walk.strideHz ? gaitEventsOfPeriodicWalk(framesMm, rateHz, *walk.strideHz)
                                              : gaitEventsFromKinematics(framesMm, rateHz);
    side.measures = walk.twoHarmonicWalker && !walk.progressionMps
                        ? measureTwoHarmonicGait(framesMm, rateHz, events, name)
                        : measureGait(framesMm, rateHz, events, walk.progressionMps, name);
    const JointAngles angles = jointAngles(framesMm, Eigen::Vector3d::UnitZ(), name);
    side.curves = flexionCycleCurves(angles.degrees, angles.names, rateHz, *side.measures);
  } catch (const Error&) {
    side.measures.reset();  // "could not be measured" is the NaN the row carries
  }
  return side;
}

double valueOf(const MeasuredSide& s, const GaitMeasureName& measure) {
  return s.measures ? gaitMeasureByName(*s.measures, s.curves, measure.key) : NAN;
}

// The RMSE over the cycle between the two sides' curves of this base name ("knee_angle":
// both joints' samples pooled); NaN when neither joint's curve is on both sides.
double curveRmse(const MeasuredSide& truth, const MeasuredSide& recon, const std::string& base) {
  double squares = 0.0;
  Eigen::Index samples = 0;
  for (const char* side : {"_r", "_l"}) {
    const auto find = [&](const MeasuredSide& s) -> const CycleCurve* {
      for (const auto& c : s.curves)
        if (c.name == base + side) return &c;
      return nullptr;
    };
    const CycleCurve* a = find(truth);
    const CycleCurve* b = find(recon);
    if (!a || !b || a->meanDeg.size() != b->meanDeg.size()) continue;
    squares += (a->meanDeg - b->meanDeg).squaredNorm();
    samples += a->meanDeg.size();
  }
  return samples > 0 ? std::sqrt(squares / static_cast<double>(samples)) : NAN;
}

}  // namespace

const std::vector<GaitMeasureName>& agreementMeasures() {
  static const std::vector<GaitMeasureName> names = {
      {"cadence", "steps/min", "cadence_spm"},
      {"stride_length", "m", "stride_length_m"},
      {"step_width", "m", "step_width_m"},
      {"speed", "m/s", "speed_mps"},
      {"stance", "%", "stance_pct"},
      {"double_support", "%", "double_support_pct"},
      {"knee_flexion_range", "deg", "knee_flexion_range_deg"},
      {"hip_flexion_range", "deg", "hip_flexion_range_deg"},
      {"knee_flexion_curve", "deg", "knee_angle", true},
      {"hip_flexion_curve", "deg", "hip_flexion", true}};
  return names;
}

std::string azimuthBand(double alphaDeg) {
  double a = std::fmod(std::abs(alphaDeg), 360.0);
  if (a > 180.0) a = 360.0 - a;
  return a < 30.0 ? "front" : a > 150.0 ? "back" : "side";
}

std::vector<GaitAgreementRow> gaitAgreementRows(const std::string& subject, const std::string& engine,
                                                double angleDeg, const Eigen::Ref<const Eigen::MatrixXd>& truthMm,
                                                const Eigen::Ref<const Eigen::MatrixXd>& reconstructedMm,
                                                double rateHz, const GaitSideWalk& truthWalk,
                                                const GaitSideWalk& reconstructedWalk) {
  const MeasuredSide truth = measure(truthMm, rateHz, truthWalk, subject);
  const MeasuredSide recon = measure(reconstructedMm, rateHz, reconstructedWalk, subject);
  std::vector<GaitAgreementRow> rows;
  for (const auto& m : agreementMeasures()) {
    if (m.curve) {
      const double rmse = truth.measures && recon.measures ? curveRmse(truth, recon, m.key) : NAN;
      rows.push_back({subject, engine, angleDeg, m.name, truth.measures ? 0.0 : NAN, rmse});
    } else {
      rows.push_back({subject, engine, angleDeg, m.name, valueOf(truth, m), valueOf(recon, m)});
    }
  }
  return rows;
}

std::vector<BlandAltmanRow> blandAltman(const std::vector<GaitAgreementRow>& rows) {
  std::vector<BlandAltmanRow> out;
  std::map<std::tuple<std::string, std::string, double, std::string, double, std::string>, size_t> slot;
  std::vector<std::vector<double>> differences, mocap;
  for (const auto& r : rows) {
    const bool view = r.setting == "view";
    const std::string band = view ? "" : azimuthBand(r.angleDeg);
    const auto key = std::make_tuple(r.setting, r.engine, view ? r.angleDeg : 0.0, band, r.noise, r.measure);
    auto [it, added] = slot.emplace(key, out.size());
    if (added) {
      BlandAltmanRow b;
      b.engine = r.engine;
      b.angleDeg = view ? r.angleDeg : NAN;
      b.band = band;
      b.setting = r.setting;
      b.noise = r.noise;
      b.measure = r.measure;
      for (const auto& m : agreementMeasures())
        if (r.measure == m.name) b.unit = m.unit;
      out.push_back(b);
      differences.emplace_back();
      mocap.emplace_back();
    }
    if (std::isfinite(r.mocap) && std::isfinite(r.reconstructed)) {
      differences[it->second].push_back(r.reconstructed - r.mocap);
      mocap[it->second].push_back(r.mocap);
    } else {
      ++out[it->second].unmeasured;
    }
  }
  for (size_t k = 0; k < out.size(); ++k) {
    const auto& d = differences[k];
    BlandAltmanRow& b = out[k];
    b.pairs = static_cast<int>(d.size());
    if (d.empty()) continue;
    const Eigen::Map<const Eigen::VectorXd> dv(d.data(), static_cast<Eigen::Index>(d.size()));
    const Eigen::Map<const Eigen::VectorXd> mv(mocap[k].data(), static_cast<Eigen::Index>(d.size()));
    b.mocapMean = mv.mean();
    b.bias = dv.mean();
    b.meanAbsDifference = dv.cwiseAbs().mean();
    std::vector<double> absolute(d.size());
    for (size_t i = 0; i < d.size(); ++i) absolute[i] = std::abs(d[i]);
    b.medianAbsDifference = percentile(absolute, 0.5);
    b.sd = d.size() > 1 ? std::sqrt((dv.array() - b.bias).square().sum() / (static_cast<double>(d.size()) - 1.0)) : 0.0;
    b.loaLow = b.bias - 1.96 * b.sd;
    b.loaHigh = b.bias + 1.96 * b.sd;
  }
  return out;
}

}  // namespace ew
