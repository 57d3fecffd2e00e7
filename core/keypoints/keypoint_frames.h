#pragma once
// What a pose estimator wrote, before any cleaning: per video frame, every person detected,
// each a list of keypoints (x, y in pixels with y down, confidence). Readers for OpenPose,
// AlphaPose and MMPose JSON (docs/KEYPOINTS.md); which skeleton the points follow is
// decided later (keypoint_trial.h), since most files do not say.

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ew {

// One person in one frame: P x 3 (x px, y px down, confidence 0-1). A point the estimator
// did not find has NaN x, y and confidence 0.
struct KeypointDetection {
  Eigen::MatrixX3d points;
  int trackId = -1;  // the estimator's own person id across frames, when it wrote one
};

struct KeypointFrames {
  std::string file;    // the file or folder as given
  std::string format;  // "OpenPose JSON", "AlphaPose JSON", "MMPose JSON"
  int pointCount = 0;  // points per person (the same in every detection)
  std::optional<std::string> layoutHint;  // a layout name the file states (MMPose meta_info)
  std::vector<std::vector<KeypointDetection>> frames;
  std::vector<std::string> warnings;

  int frameCount() const { return static_cast<int>(frames.size()); }
};

// Bounds: files hold real clips, not hours (an hour at 60 fps is 216000 frames).
inline constexpr int kMaxKeypointFrames = 216000;
inline constexpr int kMaxKeypointsPerPerson = 200;
inline constexpr int kMaxPeoplePerFrame = 100;

// True when `path` is a folder of OpenPose JSON files or a .json file (any of the three).
bool looksLikeKeypointInput(const std::filesystem::path& path);

// Reads a keypoint file or folder, telling the format from the content: a folder of per-
// frame files or an object with "people" is OpenPose, a list of {"image_id", "keypoints"}
// AlphaPose, an object or list with "instance_info" / "instances" MMPose. Throws Error(Io)
// for an unreadable path, Error(Malformed) naming the file (and frame) for bad JSON, a
// point count that changes, a keypoint list not a multiple of 3 (2 for MMPose), non-numeric
// or non-finite values, more frames / points / people than the bounds above, and
// Error(BadData) when no frame has anybody in it.
KeypointFrames readKeypointFrames(const std::filesystem::path& path);

// The parsers behind it, on text already read (`name` is what errors say).
KeypointFrames parseOpenPoseFrames(const std::vector<std::pair<std::string, std::string>>& filesAndTexts,
                                   const std::string& name);
KeypointFrames parseAlphaPoseJson(const std::string& text, const std::string& name);
KeypointFrames parseMmposeJson(const std::string& text, const std::string& name);

}  // namespace ew
