#pragma once
// The gait of a Fourier walker (METHOD §3: two harmonics, one cycle, progression removed): walked
// in place for kWalkerGaitCycles cycles at kWalkerGaitRateHz, events from its own kinematics
// (gait_events.h), measures and flexion curves as gait_measures.h defines them. The viewer's gait
// report and the semantic axes (core/semantic) measure every walker this one way, so a walker
// synthesised from the model and a recorded one are measured alike.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/gait/gait_measures.h"

namespace ew {

inline constexpr double kWalkerGaitCycles = 4.0;
inline constexpr double kWalkerGaitRateHz = 100.0;

// One walker measured: its measures and curves, or why it could not be.
struct FourierWalkerGait {
  std::optional<GaitMeasures> measures;
  std::vector<CycleCurve> curves;  // flexionCurveNames(), those measured
  Eigen::MatrixXd framesMm;        // the frames measured (in place, canonical frame)
  std::string error;               // why `measures` is empty
};

// w: 225 (phase origin 0); strideHz > 0. speedMps: the walker's progression when known (motion
// capture); without it speed and footprints come from the stance feet. Never throws for a bad
// walker: the reason is in `error`.
FourierWalkerGait measureFourierWalker(const Eigen::Ref<const Eigen::VectorXd>& w, double strideHz,
                                       std::optional<double> speedMps, const std::string& name);

}  // namespace ew
