#pragma once
// Missing samples (NaN) in 15-joint trajectories: short gaps are bridged by linear
// interpolation (a marker hidden for a few frames), long ones mark frames unusable.

#include <Eigen/Core>
#include <string>
#include <vector>

namespace ew {

struct GapReport {
  int bridgedGaps = 0;              // gaps filled by interpolation
  int bridgedSamples = 0;           // frames x joints filled
  std::vector<std::string> notes;   // "r_knee: frames 40-44 interpolated"
};

// Fills interior NaN runs of at most maxGapFrames per joint (all three coordinates of a
// joint are treated together). Longer runs and runs touching the ends stay NaN.
GapReport bridgeShortGaps(Eigen::MatrixXd& framesX45, int maxGapFrames);

// Rows with no NaN.
std::vector<bool> completeFrames(const Eigen::MatrixXd& framesX45);

// [begin, end) of the longest run of true values; {0,0} when none.
std::pair<int, int> longestRun(const std::vector<bool>& flags);

}  // namespace ew
