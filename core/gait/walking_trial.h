#pragma once
// A trial ready for the method: 15 joints in the canonical frame of METHOD §2 (mm, x right,
// y forward, z up, progression and heading removed), cropped to its steady straight-walking
// window, with its gait cycles.

#include <array>
#include <string>
#include <vector>

#include "core/common/trial.h"
#include "core/gait/steady_window.h"

namespace ew {

struct GaitCycles {
  // Foot strikes in seconds from the start of the window (row 0 of joints.positionsMm).
  std::vector<double> rightStrikesS;
  std::vector<double> leftStrikesS;
  double strideHz = 0.0;   // strides (full gait cycles) per second
  double cycleCount = 0.0; // full cycles covered by the window (may be fractional, >= 1)
  std::string method;      // "file events" or "foot contacts"
};

struct WalkingTrial {
  JointTrial joints;             // canonical frame, cropped to the window
  int windowBegin = 0;           // first row of the window in the loaded trial
  int windowEnd = 0;             // one past the last row
  int loadedFrames = 0;          // rows the loaded trial had before cropping
  GaitCycles cycles;
  double speedMps = 0.0;         // mean horizontal pelvis speed over the window (0 on a treadmill)
  // The straight walking segments found, frames counted in the loaded trial (an
  // out-and-back walk has two); `segment` is the one the window lies in, -1 when the
  // whole trial was used (treadmill, or cropping off).
  std::vector<StraightSegment> segments;
  int segment = -1;
  // Joints not measured are joints.missing (their columns NaN after prepare). Once a model
  // completes the trial (core/eigenwalker/joint_completion.h), their columns hold frames
  // synthesised from the model and they are flagged here: draw them differently and report
  // their errors apart from the measured joints'.
  std::array<bool, kJointCount> modelEstimated{};
};

}  // namespace ew
