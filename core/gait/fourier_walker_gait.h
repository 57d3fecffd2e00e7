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

// A two-harmonic walker's stance ankle does not stand still: the two harmonics round its
// sawtooth, so over foot flat (10-30 % of the stride after the strike) it slides back faster
// than the walker walks. Measured on the 30 shared trials (walkers.csv), each fitted with two
// harmonics and measured in place as measureFourierWalker does, against its progression: the
// stance feet read 1.064 times the speed (SD 0.030, 0.971-1.138);
// tests/gait/test_fourier_walker_gait.cpp measures it again, and again leaving each subject
// out. Without it these walkers' strides read 7.3 cm longer than their trials' (1.0 cm shorter
// with it), and the eigenwalker's reconstructions' 12 cm longer than the trials' stance feet
// say (docs/GAIT.md).
inline constexpr double kTwoHarmonicStanceSpeedRatio = 1.064;

// The gait of frames synthesised from a two-harmonic walker walking in place (framesX45 at
// rateHz, events from its own kinematics): measureGait with the walker's progression taken
// from its stance feet ÷ kTwoHarmonicStanceSpeedRatio, which puts the footprints (steps,
// strides) on the floor at that speed. speedSource says so. Throws as measureGait does.
GaitMeasures measureTwoHarmonicGait(const Eigen::Ref<const Eigen::MatrixXd>& framesX45, double rateHz,
                                    const GaitEventSet& events, const std::string& name);

// One walker measured: its measures and curves, or why it could not be.
struct FourierWalkerGait {
  std::optional<GaitMeasures> measures;
  std::vector<CycleCurve> curves;  // flexionCurveNames(), those measured
  Eigen::MatrixXd framesMm;        // the frames measured (in place, canonical frame)
  std::string error;               // why `measures` is empty
};

// w: 225 (phase origin 0); strideHz > 0. speedMps: the walker's progression when known (motion
// capture); without it speed and footprints come from the stance feet, as
// measureTwoHarmonicGait reads them. Never throws for a bad walker: the reason is in `error`.
FourierWalkerGait measureFourierWalker(const Eigen::Ref<const Eigen::VectorXd>& w, double strideHz,
                                       std::optional<double> speedMps, const std::string& name);

}  // namespace ew
