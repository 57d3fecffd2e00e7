#pragma once
// A small analytic walker for tests of the loaders and the normaliser: sinusoidal limb
// swing about a pelvis that progresses at a known speed, in a chosen lab frame. Not the
// project's synthetic population (core/synth); just enough gait to have known answers.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/common/trial.h"

namespace ew::test {

struct AnalyticGait {
  double strideHz = 0.9;
  double speedMps = 1.2;     // 0 = treadmill
  double rateHz = 100.0;
  double durationS = 3.0;
  double headingDeg = 0.0;   // walking direction in the lab, about the up axis
  SignedAxis up{2, 1};       // lab up axis (e.g. {1,1} for Y-up files)
};

// Frames (T x 45) in the lab frame described by `g`, mm.
Eigen::MatrixXd analyticWalkFrames(const AnalyticGait& g);

// The same wrapped as a JointTrial (file "analytic", upAxis left unset).
JointTrial analyticWalkTrial(const AnalyticGait& g);

}  // namespace ew::test
