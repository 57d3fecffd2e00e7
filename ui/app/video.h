#pragma once
// A video in the viewer (docs/VIEWER.md, "Video"): its frames decoded ahead on a worker
// (video/frame_cache.h), the joints the user marks on keyframes (with undo and redo), and
// the joints tracked through a range of frames (video/joint_tracker.h) on a worker. The
// track becomes a keypoint clip (ui/app/clip.h): fitted through the unknown camera like a
// pose estimator's file, its reprojection drawn over the footage.

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include "core/eigenwalker/model.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/tracking/keyframes.h"
#include "ui/app/background_job.h"
#include "ui/app/detection.h"
#include "video/frame_cache.h"
#include "video/joint_tracker.h"
#include "video/model_loop.h"

namespace ew::ui {

// A finished track: what was tracked, from which keyframes, and the trial it makes.
struct TrackedVideo {
  std::filesystem::path video;
  Keyframes keyframes;  // as they were when tracking started
  TrackerKind tracker = TrackerKind::OpticalFlow;
  bool flattenBackground = false;          // asked for; track.background says whether it was done
  bool holdTheTrunk = false;               // TrackerOptions::holdTheTrunk, as asked for
  int modelLoopRounds = 0;                 // asked for (video/model_loop.h); the flow tracker only
  std::vector<ModelLoopRound> loopRounds;  // one per fit the loop made
  std::string loopStopped;                 // why the loop stopped early ("" when it did not)
  VideoHorizon horizon;                    // the video's (readVideoHorizon): the fit holds to it
  JointTrack track;
  std::shared_ptr<const KeypointTrial> trial;  // the track's confident points (trialFromJoints)
  Eigen::VectorXd meanConfidence;              // a frame's mean over the joints (the panel's strip)
  Eigen::VectorXd cumulativeMotionPx;          // core/tracking/track_confidence.h (*Mark next*)
  double seconds = 0.0;
  // The frames the last run tracked (trackAgainBetween's part; the whole range otherwise).
  int ranFirst = 0, ranLast = -1;
  int frames() const { return static_cast<int>(track.jointsPx.rows()); }
  int framesRan() const { return ranLast - ranFirst + 1; }
  bool ranPart() const { return ranFirst != track.firstFrame || ranLast != lastFrame(); }
  int lastFrame() const { return track.firstFrame + frames() - 1; }
};

// The order the guided marking asks for the joints: down the trunk, then each limb from
// the body outwards (METHOD §1 names).
const std::vector<Joint>& markingOrder();

// The 2D view's largest magnification of a video: a 1080p frame's pixel about 8 screen pixels
// wide in a half-HD view.
inline constexpr double kMaxVideoZoom = 16.0;

struct VideoSession {
  std::filesystem::path path;
  std::shared_ptr<FrameCache> frames;
  Keyframes keyframes;
  struct KeyframesStep {
    Keyframes keyframes;        // on the undo stack: before the edit; on the redo stack: after it
    std::uint64_t serial = 0;   // the edit's (ui/app/undo.h nextEditSerial): the app's undo order
    std::uint64_t newestWhenUndone = 0;  // on the redo stack: latestEditSerial() at the undo
  };
  std::vector<KeyframesStep> undo, redo;  // each edit of the keyframes (≤ 200 kept)
  int frame = 0;                       // the frame scrubbed to (0-based)
  bool marking = false;                // clicks in the 2D view place joints on `frame`
  int markStep = 0;                    // index into markingOrder(): the joint asked for next
  int firstFrame = 0, lastFrame = -1;  // the range to track (-1: the video's end)
  TrackerKind tracker = TrackerKind::OpticalFlow;  // which tracker the next track uses
  bool flattenBackground = false;  // the next flow track flattens a still background
  bool holdTheTrunk = false;       // the next flow track holds the shoulders and hips to the trunk
  int modelLoopRounds = 0;         // rounds of the model loop the next flow track runs (0-10)
  std::shared_ptr<const TrackedVideo> tracked;  // the last finished track
  bool trackAgainWhenStopped = false;  // a joint let go while tracking: the running one stops
  std::string trackError;                       // why the last track failed ("" when none)
  // The built-in detector (ui/app/detection.h): the running detection's frames as they come,
  // the last finished one, and why the last could not run.
  std::shared_ptr<LiveDetections> detecting;
  std::shared_ptr<const DetectedVideo> detected;
  std::string detectError;
  // While detecting, the view shows the frame done last, until the user picks a frame.
  bool followDetection = false;
  bool showWalkerWhenFitted = false;  // the detection's first fit goes to the walker's frames
  std::string decodeErrorShown;  // the frame cache's decoding error last put in the banner
  // The frame last drawn and its number: shown while the frame asked for is decoding.
  std::shared_ptr<const cv::Mat> shown;
  int shownIndex = -1;
  double playedFrames = 0.0;  // playback's share of a frame not shown yet (stepsVideoFrames)
  // The 2D view magnified `zoom` times (1: the whole picture) about the video pixel shown at
  // its middle (x right, y down): marking a walker a few hundred pixels tall needs it.
  double zoom = 1.0;
  Eigen::Vector2d zoomCentrePx = Eigen::Vector2d::Zero();

  int frameCount() const { return frames ? frames->frameCount() : 0; }
  double fps() const { return frames ? frames->info().fps : 0.0; }
  // The keyframe on `frame`, if any.
  const Keyframe* keyframeAt(int frame) const;
  // The video's horizon, once a track or a detection has read it; null before.
  const VideoHorizon* horizon() const;
};

// What a track is asked for: a VideoSession's settings when it starts.
struct TrackSettings {
  int first = 0, last = -1;
  TrackerKind tracker = TrackerKind::OpticalFlow;
  bool flattenBackground = false, holdTheTrunk = false;
  int modelLoopRounds = 0;
};
TrackSettings trackSettingsOf(const VideoSession& v, int last);

// Reads and tracks (blocking; the viewer runs it as a background job). `progress` gets the
// share done and returns false to cancel. Throws the tracker's and trialFromJoints' errors.
// `modelLoopRounds` > 0 (the flow tracker): tracked with `model` in the loop (video/model_loop.h).
// `horizon`: the video's, when already read (a detection or an earlier track); read otherwise.
TrackedVideo trackVideo(const std::filesystem::path& video, const Keyframes& keyframes,
                        const TrackSettings& settings,
                        std::shared_ptr<const EigenwalkerModel> model,
                        const std::function<bool(double)>& progress,
                        std::optional<VideoHorizon> horizon = std::nullopt);

// The same frames marked, each joint at the same place (or unmarked on both).
bool sameKeyframes(const Keyframes& a, const Keyframes& b);

// The frames a new track would change when `keyframes` replace the ones `previous` was
// tracked from, with the same settings: from the unchanged keyframe before the first edited
// one (or the range's start) to the unchanged keyframe after the last (or its end). Every
// keyframe is tracked only to its neighbours (video/joint_tracker.h), so the frames outside
// come out the same. Empty when nothing changed, or when the whole range must be tracked
// again: an edit outside the range, other settings or range, the flattened background (a median over the range) or the
// model loop (one fit of the whole track), the appearance tracker, or an edit at or before
// the first keyframe (whose marks size the tracker's windows).
std::optional<std::pair<int, int>> localRetrackRange(const TrackedVideo& previous,
                                                     const Keyframes& keyframes,
                                                     const TrackSettings& settings);

// `previous` with frames [first, last] tracked again from `keyframes` (trackVideo's
// settings), the keyframes now `keyframes`; the fit's trial made again from the whole track.
TrackedVideo trackAgainBetween(const TrackedVideo& previous, const Keyframes& keyframes, int first,
                               int last, const std::function<bool(double)>& progress);

// True for the file names a video has (.mp4, .avi, .mov, .mkv, .webm, .m4v, .mpg, .mpeg).
bool isVideoFile(const std::filesystem::path& path);

// [SECTION] The feature's state
// Everything the viewer keeps of videos, in one place (AppState::video): the video open, the
// track and the detection that run for it, and the detector's choices, which outlast a video.
// Its actions are ui/app/video_actions.h (and video_poll.h), its panels video_controls,
// video_view and input_view_video. A video's fit is the keypoint clip's (ClipFeature, clip.h):
// a track or a detection is fitted as a clip is.
struct VideoFeature {
  std::optional<VideoSession> session;  // the video open (Mode::Clip shows it); none: no video
  BackgroundJob<std::shared_ptr<const TrackedVideo>> track;    // joints tracked through it
  BackgroundJob<std::shared_ptr<const DetectedVideo>> detect;  // people found in it
  // A video opened alone (no keyframe file with it) is handed to the built-in detector.
  bool detectWhenOpens = true;
  PoseModelSize detectorModel =
      PoseModelSize::Full;  // BlazePose's landmark model for the next detection
};

}  // namespace ew::ui
