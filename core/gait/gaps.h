#pragma once
// Missing samples (NaN) in 15-joint trajectories: short gaps are bridged by linear
// interpolation (a marker hidden for a few frames), long ones mark frames unusable.

#include <Eigen/Core>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ew {

struct GapReport {
  int bridgedGaps = 0;             // gaps filled by interpolation
  int bridgedSamples = 0;          // frames x joints filled
  std::vector<std::string> notes;  // "r_knee: frames 40-44 interpolated"
};

struct OutlierReport {
  int rejectedSamples = 0;         // frames x joints set to NaN
  std::vector<std::string> notes;  // "r_ankle: frame 40, 1000 m from its neighbours"
};

// Coordinates further than this from the origin are no position in any lab (100 km).
inline constexpr double kMaxPlausibleCoordinateMm = 1.0e8;

// How far a joint may sit from the median of the five frames around it before it is a
// glitch: 500 mm plus two frames at 10 m/s (faster than a hand ever moves in walking).
// Smooth motion, even fast, stays close to that median; a marker that jumps for a frame
// or two (a tracking error, a swapped label) does not.
double outlierThresholdMm(double rateHz);

// Sets to NaN every joint sample (all three coordinates) that is not finite, lies beyond
// kMaxPlausibleCoordinateMm, or deviates from the per-coordinate median of frames r-2..r+2
// by more than thresholdMm, so bridgeShortGaps fills it like any short gap.
OutlierReport rejectOutlierSamples(Eigen::MatrixXd& framesX45, double thresholdMm);

// Fills interior NaN runs of at most maxGapFrames per joint (all three coordinates of a
// joint are treated together). Longer runs and runs touching the ends stay NaN.
GapReport bridgeShortGaps(Eigen::MatrixXd& framesX45, int maxGapFrames);

// The same two for other points, 3 columns each, named for the notes (the feet's:
// kFootPointNames); points beyond the matrix's columns are not read.
using PointNames = std::span<const std::string_view>;
OutlierReport rejectOutlierSamples(Eigen::MatrixXd& framesX3P, double thresholdMm, PointNames names);
GapReport bridgeShortGaps(Eigen::MatrixXd& framesX3P, int maxGapFrames, PointNames names);

// Every NaN of one signal filled: linearly between the finite samples around it, held at
// the ends (left all NaN when none is finite). For steps that need every sample, however
// long the gap (a strike finder, a start for a fit), not for data kept as measured.
void fillAllGapsLinearly(Eigen::Ref<Eigen::VectorXd> x);

// Rows with no NaN.
std::vector<bool> completeFrames(const Eigen::MatrixXd& framesX45);

// [begin, end) of the longest run of true values; {0,0} when none.
std::pair<int, int> longestRun(const std::vector<bool>& flags);

}  // namespace ew
