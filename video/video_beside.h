#pragma once
// The video a pose estimator's output was made from, found beside that output: its size is
// what points given as fractions of the image (MediaPipe CSV, YOLO labels) are multiplied by
// and where a camera fit expects the principal point, its rate what a JSON file does not
// store (docs/KEYPOINTS.md, "The video beside the keypoints").

#include <filesystem>
#include <optional>
#include <vector>

#include "core/keypoints/keypoint_frames.h"

namespace ew {

// The names a video of `keypoints` may have, most likely first, where it may stand:
// - Ultralytics' run folder (or its labels/ folder, or one label file): <run>/<prefix>.<ext>,
//   the annotated video it writes there, <prefix> the label files' name before "_<frame>";
// - a keypoint file or folder X (X.csv, X.json, X_json/, X_keypoints/): X.<ext> in the same
//   folder, and in a "videos" folder beside it (Pose2Sim's pose/X_json, videos/X.mp4).
// <ext>: mp4, avi, mov, mkv, webm, m4v (either case).
std::vector<std::filesystem::path> videoCandidatesFor(const std::filesystem::path& keypoints);

// The first candidate that exists and opens as a video: its path, frame size and rate;
// nullopt when none does (a file that fails to open is passed over: the caller's keypoints
// may still carry pixels and a rate, and need neither).
std::optional<KeypointVideo> videoBesideKeypoints(const std::filesystem::path& keypoints);

}  // namespace ew
