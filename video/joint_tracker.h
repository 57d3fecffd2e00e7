#pragma once
// Joints followed through a video from hand-marked keyframes (core/tracking/keyframes.h):
// pyramidal Lucas–Kanade optical flow from frame to frame, checked by tracking back
// (forward–backward error), patch matching against the joint's look on its keyframe, and
// a constant-velocity Kalman filter per joint that carries a joint through frames where
// neither finds it. Every keyframe is tracked forward to the next keyframe and backward to
// the previous one; between two keyframes the two tracks are blended, each weighted by its
// confidence and by how near its keyframe is (docs/TRACKING_DESIGN.md).

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "core/keypoints/keypoint_trial.h"
#include "core/tracking/keyframes.h"
#include "video/video_source.h"

namespace ew {

// The optical-flow tracker (below), or Zou et al.'s appearance tracker
// (video/appearance_tracker.h) run through the same passes and blending.
enum class TrackerKind { OpticalFlow, Appearance };

struct TrackerOptions {
  TrackerKind kind = TrackerKind::OpticalFlow;
  int firstFrame = 0;  // the frames tracked, inclusive
  int lastFrame = -1;  // -1: the video's last frame
  int pyramidLevels = 3;
  // The Lucas–Kanade window and the matched patch as shares of the person's height in
  // pixels (from the first keyframe: head to ankles), so that the tracker sees the same
  // part of a limb in a close-up and in a wide shot.
  double windowShare = 1.0 / 12.0;
  double patchShare = 1.0 / 10.0;
  double searchShare = 1.0 / 20.0;  // how far around the prediction a joint is sought
  // Place each joint where its segment looks as on the keyframe (video/segment_search.h).
  // Off by default: measured worse than each joint's own flow on both the synthetic
  // footage and Pose2Sim's cam01 (docs/TRACKING_DESIGN.md, "Measured").
  bool searchSegments = false;
  // The model loop's prior (video/model_loop.h): where a model fitted to an earlier track
  // puts each joint, one row per tracked frame from firstFrame (30 columns, pixels; NaN or no
  // rows: no say). A joint whose flow fails, or lands more than priorGateShare × the
  // person's height from it, is sought again around it with its keyframe patch, and else
  // placed there at a low confidence. The flow tracker only.
  Eigen::MatrixXd priorPx;
  double priorGateShare = 0.05;
  // Rows as priorPx, 15 columns: 1 where the model's walker hides the joint behind its own body
  // (core/camera/self_occlusion.h). Such a joint is placed where the walk puts it whatever its
  // flow says (its patch shows the segment in front). No rows: none hidden.
  Eigen::MatrixXd priorHidden;
  // Flatten a fixed camera's still background before the flow (video/static_background.h),
  // when the footage shows one. The flow tracker only.
  bool flattenStaticBackground = false;
  // Hold the shoulders and the hips to the trunk: where a joint's flow strays more
  // than 3 % of the person's height from its keyframe place turned and carried with the
  // pelvis→sternum line, it is put there. For a bare or plain upper body that bends but turns
  // little (Pose2Sim's balancing trial); off by default, as it made the synthetic walkers'
  // shoulders worse in side views, where the pelvis under the thighs is the joint tracked worst
  // (docs/TRACKING_DESIGN.md, "Holding the trunk"). The flow tracker only.
  bool holdTheTrunk = false;
  // Grey frames held at once for the backward passes; a longer stretch between keyframes
  // is decoded again in pieces of this size.
  std::size_t frameBufferBytes = std::size_t{512} << 20;
};

// "flow" or "appearance", as the CLI's --tracker and the track file say.
const char* trackerName(TrackerKind kind);
// Error(BadArgument) naming the choices for any other name.
TrackerKind trackerFromName(const std::string& name);

struct JointTrack {
  int firstFrame = 0;
  double fps = 0.0;
  Eigen::MatrixXd jointsPx;    // frames × 30: x, y per joint (METHOD §1), NaN = never marked
  Eigen::MatrixXd confidence;  // frames × 15, 0-1 (1 on a keyframe)
  // "flattened", "off", or why the footage has no still background to flatten.
  std::string background = "off";
  KeypointImageSize imageSize;  // the video's frame (zero: unknown)
};

// The person's height in pixels that sizes the tracker's windows: head to ankles of the first
// keyframe with at least two joints; a third of the frame's height when no keyframe says.
double personHeightPx(const Keyframes& keys, int frameHeightPx);

// Called with the share done (0-1); returning false cancels (Error(BadArgument) "cancelled").
using TrackProgress = std::function<bool(double)>;

// The smallest picture side tracked: the smallest patch matched (9 px) searched 6 px either way
// spans 21 px, and a walker, head to ankles, spans several patches.
inline constexpr int kMinTrackedSidePx = 32;

// Throws Error(BadArgument) for a frame range outside the video or with no keyframe in it,
// or when `progress` cancels; Error(BadData) naming the video for a frame side under
// kMinTrackedSidePx, and from the video source when the stream ends before the frames asked for.
JointTrack trackJoints(VideoSource& video, const Keyframes& keyframes,
                       const TrackerOptions& options = {}, const TrackProgress& progress = {});

// The track as 2D joints to fit (at the video's frame rate, each joint's confidence as a
// detector's score), as the viewer, the model loop and `track --reconstruct` all fit it.
// `file` names the video in errors.
KeypointTrial keypointTrialOf(const JointTrack& track, const std::string& file);

}  // namespace ew
