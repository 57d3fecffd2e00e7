#pragma once
// How far a 2D track is from another one of the same clip (a pose estimator's detections,
// or the true projection of a synthetic walker): the pixel distance per joint over the
// frames where both have the joint.

#include <Eigen/Core>
#include <array>

#include "core/common/skeleton.h"

namespace ew {

inline constexpr std::array<bool, kJointCount> allJoints() {
  std::array<bool, kJointCount> a{};
  for (bool& b : a) b = true;
  return a;
}

struct TrackDistance {
  std::array<double, kJointCount> medianPx{}, p95Px{};  // NaN for a joint never in both
  std::array<int, kJointCount> frames{};                // frames where both have it
  double medianAllPx = 0.0, p95AllPx = 0.0;             // over every joint-frame
  int jointFrames = 0;
  // The share of joint-frames within `withinPx` of the reference (the PCK of pose
  // estimation, at a threshold in pixels): per joint (NaN when never in both) and overall.
  double withinPx = 12.0;
  std::array<double, kJointCount> shareWithin{};
  double shareWithinAll = 0.0;
};

// `trackPx`: rows are frames firstFrame, firstFrame + 1, …; `referencePx`: rows are frames
// 0, 1, …; both × 30 pixels, NaN = missing. Frames only one of them has are left out.
// `joints`: which joints count (all by default); `withinPx`: TrackDistance::withinPx.
TrackDistance compareTracks(const Eigen::Ref<const Eigen::MatrixXd>& trackPx, int firstFrame,
                            const Eigen::Ref<const Eigen::MatrixXd>& referencePx,
                            const std::array<bool, kJointCount>& joints = allJoints(),
                            double withinPx = 12.0);

}  // namespace ew
