#pragma once
// Tracking with the walker model in the loop (issue 14; Howe, Leventon & Freeman 1999: "the
// 3D estimate provides feedback to influence the 2D tracking process to favor more likely
// poses"). Track; fit the eigenwalker through the unknown camera to the track's confident
// joints (core/camera/clip_reconstruction.h); track again with the fitted walker drawn back
// through the camera as a prior (TrackerOptions::priorPx): where a joint's flow fails or
// strays from the walk, it is sought near where the walk puts it. Repeated `rounds` times.
// A clip the fit refuses (not walking, too short) keeps the first track, and says why.

#include <string>
#include <vector>

#include "core/eigenwalker/model.h"
#include "video/joint_tracker.h"

namespace ew {

struct ModelLoopOptions {
  int rounds = 2;  // fits and re-tracks after the first track
};

struct ModelLoopRound {
  double reprojectionRmsPx = 0.0;  // the fit to the track before this round
  double strideHz = 0.0, alphaDeg = 0.0;
  // Joint-frames the fitted walker hides behind its own body (core/camera/self_occlusion.h),
  // which this round's track placed where the walk puts them.
  int hiddenJointFrames = 0;
};

struct ModelLoopResult {
  JointTrack track;                   // the last track
  std::vector<ModelLoopRound> rounds;  // one per fit made
  std::string stoppedBecause;         // "" when every round ran; else the fit's refusal
};

// The tracker's errors, and Error(BadArgument) for rounds outside 0-10.
ModelLoopResult trackWithModel(VideoSource& video, const Keyframes& keyframes, const EigenwalkerModel& model,
                               TrackerOptions options = {}, const ModelLoopOptions& loop = {},
                               const TrackProgress& progress = {});

}  // namespace ew
