#pragma once
// The whole path from 15 joints in file axes to a WalkingTrial (METHOD §2): bridge short
// gaps, take the longest complete run, make z up, find the steady straight-walking
// window, face +y, remove progression, put the feet on the floor, find the gait cycles.

#include <optional>

#include "core/common/trial.h"
#include "core/gait/steady_window.h"
#include "core/gait/walking_trial.h"

namespace ew {

struct PrepareOptions {
  double maxGapS = 0.1;          // longer gaps are not interpolated
  bool cropToSteadyWindow = true;
  SteadyWindowOptions window;
  // Use this straight segment (index into WalkingTrial::segments) instead of the one with
  // the longest steady part.
  std::optional<int> segment;
  bool rejectOutliers = true;    // one-frame glitches become gaps (gaps.h)
};

// Throws Error(BadData) naming the file and the stage ("walking: …") when the trial cannot
// give one walking cycle: no frames, an implausible rate, joints missing throughout, no
// straight segment holding a full cycle. Never reads outside the data for any input.
WalkingTrial prepareWalkingTrial(const JointTrial& joints, const PrepareOptions& options = {});

}  // namespace ew
