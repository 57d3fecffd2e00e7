#pragma once
// A walking video to keypoints with no other tool (issue 52; docs/DETECTOR.md): BlazePose's
// person detector finds people, the landmark model follows each one from frame to frame on a
// crop taken from its previous landmarks, and the result is a keypoint clip in the
// MediaPipe-33 layout, which everything downstream (the unknown-camera fit, the engines, the
// gait report, exports) reads as it reads a MediaPipe CSV.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/keypoints/keypoint_frames.h"
#include "video/blazepose.h"
#include "video/pose_model_files.h"
#include "video/video_source.h"

namespace ew {

// One followed person on one frame.
struct FollowedPose {
  int personId = 0;
  PoseLandmarks landmarks;
};

struct PoseDetectionOptions {
  PoseModelSize model = PoseModelSize::Full;
  // The person detector also on square tiles across a wide (or tall) frame, for people far away.
  bool tiles = true;
  // How often the person detector looks for people not yet followed (and always while nobody
  // is), in seconds of video.
  double searchEverySeconds = 0.5;
  int maxPeople = 8;
  // Below this landmark-model score a person is lost (left the frame, hidden); the track ends
  // there and is never handed to whoever is nearest.
  double minPoseScore = 0.5;
  // Left and right labels made consistent through time (a whole-body swap the model makes on
  // a frame is undone): pose_detector.cpp, fixLeftRight.
  bool fixLeftRight = true;
  // A centred (zero-lag) smoothing of each landmark's path over this span, in seconds: a
  // quadratic Savitzky-Golay fit, which follows a swinging foot's turn instead of cutting
  // it as a causal filter's lag does. 0: none (docs/DETECTOR.md, "Smoothing", measures both).
  double smoothSeconds = 0.0;
  // Frames [firstFrame, lastFrame]; lastFrame −1: to the end.
  int firstFrame = 0;
  int lastFrame = -1;
  // Called after each frame with the frames done and the total; returning false cancels.
  std::function<bool(int done, int total)> progress;
  // Called after each frame with what was found on it (before the left/right consistency,
  // which needs the whole clip): for a live display. Called on the detecting thread.
  std::function<void(int frame, const std::vector<FollowedPose>& poses)> onFrame;
};

struct PoseDetectionRun {
  VideoInfo video;
  PoseModelSize model = PoseModelSize::Full;
  // Per frame of [firstFrame, last frame read], everybody followed on it.
  std::vector<std::vector<FollowedPose>> poses;
  int firstFrame = 0;
  int people = 0;             // persons followed at some point
  int leftRightSwapsUndone = 0;
  bool cancelled = false;     // the progress callback said stop: poses hold the frames done
  // Wall time, seconds: decoding, the landmark model, the person detector, all.
  double decodeSeconds = 0.0, landmarkSeconds = 0.0, personSeconds = 0.0, totalSeconds = 0.0;
  std::vector<std::string> warnings;
};

// Detects and follows people through `videoFile`. Throws what VideoSource throws for a file
// it cannot read, Error(Io) with missingPoseModelAdvice() when the models are missing; a
// video with nobody in it is a run whose frames are empty (people == 0), not an error.
PoseDetectionRun detectPoses(const std::filesystem::path& videoFile, const PoseDetectionOptions& options = {});

// The run as a keypoint clip: MediaPipe-33 points (x, y px, visibility as the confidence; a
// point outside the picture missing),
// one detection per person with its id as trackId, the video's size and rate; frames before
// firstFrame are empty, so frame numbers are the video's.
KeypointFrames keypointFramesOf(const PoseDetectionRun& run);

// Which left/right labels move together: all of them (the model taking the person to face the
// other way), or one limb pair's (a leg or an arm labelled as the other one).
enum class LeftRightGroup { Body, Legs, Arms };

// The swap costs used: a whole-body swap is undone however long it lasts when the labels' travel
// says so; a limb's alone only for a few frames (a 1-3 frame glitch), since legs and arms cross
// in a profile walk and their labels are then for the model to say.
inline constexpr double kBodySwapCost = 0.05;
inline constexpr double kLimbSwapCost = 0.3;

// The left/right labelling of one person's frames that is most consistent through time: a
// two-state path (as the model labelled it, or the group's left/right pairs swapped)
// minimising the points' frame-to-frame travel (in ROI sides) plus `swapCost` for each swapped
// frame. `frames` holds the person's consecutive poses (a gap starts a new path). Returns, per
// frame, whether to swap.
std::vector<bool> consistentLeftRight(const std::vector<const PoseLandmarks*>& frames,
                                      LeftRightGroup group = LeftRightGroup::Body, double swapCost = kBodySwapCost);

// Each landmark's x and y over consecutive poses smoothed by a centred quadratic
// Savitzky-Golay filter of 2 * halfWindow + 1 frames (shrunk at the ends of the run); poses
// of fewer than 2 * halfWindow + 1 frames are left as they are.
void smoothLandmarks(const std::vector<PoseLandmarks*>& frames, int halfWindow);

// Swaps the group's left/right pairs of the MediaPipe-33 layout (Body: all 16).
void swapLeftRight(PoseLandmarks& pose, LeftRightGroup group = LeftRightGroup::Body);

}  // namespace ew
