#pragma once
// A video where the commands take keypoints (issue 52): `reconstruct --input V.mp4`,
// `info V.mp4`, `gait V.mp4` detect the walker with the built-in detector (through the
// detection cache, so a second command on the same video is quick) and go on as with a
// keypoint file. Without the video library (a build without OpenCV) a video is refused
// with that reason.
#include <filesystem>
#include <functional>
#include <string>

#include "core/keypoints/keypoint_trial.h"

namespace ew::cli {

// By the file name's extension (.mp4, .mov, .avi, .mkv, .webm, .m4v, .mpg, .mpeg, .wmv).
bool isVideoFile(const std::filesystem::path& path);

struct VideoDetectionSettings {
  std::string model = "full";  // lite, full, heavy
  bool useCache = true;
  bool tiles = true;
  bool quiet = false;  // no progress lines on stderr
};

// A detection's progress on stderr, a line at each tenth of the frames.
std::function<bool(int done, int total)> detectionProgressOnStderr();

// The keypoint clip of `video` by the built-in detector (progress and timing on stderr).
KeypointFrames detectKeypointFrames(const std::filesystem::path& video, const VideoDetectionSettings& settings,
                                    KeypointOptions& k);

// readKeypointTrial, or for a video the detector's clip cleaned the same way (its size and
// rate the video's).
KeypointTrial keypointTrialOf(const std::filesystem::path& input, KeypointOptions k,
                              const VideoDetectionSettings& settings = {});

// What reading the keypoints noticed (a video that ends early, a joint never seen), as
// "warning: INPUT: …" lines on stderr. Said before a fit: a fit that then fails may fail for it.
void sayKeypointWarnings(const std::string& input, const KeypointTrial& trial);

}  // namespace ew::cli
