#pragma once
// People found in a video by the built-in detector (video/pose_detector.h, issue 52) in the
// viewer (docs/VIEWER.md, "Detecting the walker"): detection runs as a background job whose
// frames are handed to the view as they come (LiveDetections), and its keypoint clip, in the
// MediaPipe-33 layout, is fitted through the unknown camera as a pose estimator's file is.

#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/keypoints/keypoint_frames.h"
#include "video/pose_model_files.h"
#include "video/scene_horizon.h"

namespace ew::ui {

// The detections of a running job, frame by frame as the detecting thread finds them (before
// the left/right consistency, which needs the whole clip): what the 2D view draws meanwhile.
class LiveDetections {
 public:
  // Called on the detecting thread.
  void add(int frame, std::vector<KeypointDetection> people);
  // The people found on `frame` (none when it is not done yet).
  std::vector<KeypointDetection> at(int frame) const;
  int latestFrame() const;  // the frame done last (-1 before the first)

 private:
  mutable std::mutex mutex_;
  std::vector<std::vector<KeypointDetection>> frames_;
  int latest_ = -1;
};

// The horizon a video's own level lines give (video/scene_horizon.h), as `reconstruct` reads
// it: a detected walker's fit holds its camera's height to it, a tracked one's is checked
// against it (ClipSettings::holdToHorizon).
struct VideoHorizon {
  std::optional<SceneHorizon> scene;  // none when the lines do not agree on one …
  std::string whyNone;                // … and why
  std::optional<double> rowPx() const { return scene ? std::optional<double>(scene->rowPx) : std::nullopt; }
};

// Reads it (about 1.6 s on a 1080p video); a failure to read is a reason, not a throw: the
// walker's joints were read, and a horizon is not worth losing them.
VideoHorizon readVideoHorizon(const std::filesystem::path& video);

// A finished detection.
struct DetectedVideo {
  std::filesystem::path video;
  PoseModelSize model = PoseModelSize::Full;
  // The keypoint clip (keypointFramesOf: MediaPipe-33, each person's id as its trackId; frame
  // numbers the video's).
  std::shared_ptr<const KeypointFrames> frames;
  int people = 0;            // persons followed at some point
  int framesRead = 0;        // frames the detector went through
  int framesWithPeople = 0;  // … of which someone was found on
  int widthPx = 0, heightPx = 0;
  double fps = 0.0;
  bool fromCache = false;    // read back from the detection cache (video/detection_cache.h)
  // The horizon the footage's own level lines give (video/scene_horizon.h), read after the
  // people, as `reconstruct` reads it: the fit holds its camera's height to it. Else why none.
  VideoHorizon horizon;
  double seconds = 0.0;
  std::vector<std::string> warnings;
};

// Detects the people in `video` through the detection cache (blocking; the viewer runs it as a
// background job). `live` receives each frame's people as they are found; `progress` gets the
// frames done and the total and returns false to cancel, which throws JobCancelled. Throws what
// detectPoses throws: a video it cannot read, the models missing (missingPoseModelAdvice()).
DetectedVideo detectVideo(const std::filesystem::path& video, PoseModelSize model,
                          const std::shared_ptr<LiveDetections>& live,
                          const std::function<bool(int done, int total)>& progress);

// The video's size and rate as a keypoint clip's KeypointVideo (what the fit reads them from).
KeypointVideo keypointVideoOf(const DetectedVideo& d);

// "BlazePose full: 2 people in 300 frames, 17.2 s (17 frames/s)" / "… (from the cache)".
std::string detectionSummary(const DetectedVideo& d);

}  // namespace ew::ui
