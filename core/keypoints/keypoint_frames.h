#pragma once
// What a pose estimator wrote, before any cleaning: per video frame, every person detected,
// each a list of keypoints (x, y in pixels with y down, confidence). Readers for OpenPose,
// AlphaPose and MMPose JSON (docs/KEYPOINTS.md) and for MediaPipe Pose and DeepLabCut CSV
// (keypoint_csv.cpp); which skeleton the points follow is decided later (keypoint_trial.h),
// since most files do not say.

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ew {

// One person in one frame: P x 3 (x px, y px down, confidence 0-1). A point the estimator
// did not find has NaN x, y and confidence 0.
struct KeypointDetection {
  Eigen::MatrixX3d points;
  int trackId = -1;  // the estimator's own person id across frames, when it wrote one
};

// An image's size in pixels: what a MediaPipe CSV's normalised (0-1) coordinates refer to,
// and where a camera's principal point is expected (its centre).
struct KeypointImageSize {
  int width = 0;
  int height = 0;
};

struct KeypointFrames {
  std::string file;    // the file or folder as given
  std::string format;  // "OpenPose JSON", "AlphaPose JSON", "MMPose JSON", "MediaPipe CSV", "DeepLabCut CSV"
  int pointCount = 0;  // points per person (the same in every detection)
  std::optional<std::string> layoutHint;  // a layout name the file states (MMPose meta_info)
  std::optional<double> rateHz;           // a frame rate the file states (a CSV time column)
  std::vector<std::string> pointNames;    // the file's own point names (DeepLabCut); else empty
  std::optional<KeypointImageSize> imageSize;  // the image the points were found in, when stated
  std::vector<std::vector<KeypointDetection>> frames;
  std::vector<std::string> warnings;

  int frameCount() const { return static_cast<int>(frames.size()); }
};

// Bounds: files hold real clips, not hours (an hour at 60 fps is 216000 frames).
inline constexpr int kMaxKeypointFrames = 216000;
inline constexpr int kMaxKeypointsPerPerson = 200;
inline constexpr int kMaxPeoplePerFrame = 100;

// True when `path` is a folder of OpenPose JSON files, a .json file (any of the three), or a
// .csv file whose first lines are a MediaPipe or DeepLabCut header (keypointCsvKind).
bool looksLikeKeypointInput(const std::filesystem::path& path);

// Reads a keypoint file or folder, telling the format from the content: a folder of per-
// frame files or an object with "people" is OpenPose, a list of {"image_id", "keypoints"}
// AlphaPose, an object or list with "instance_info" / "instances" MMPose. Throws Error(Io)
// for an unreadable path, Error(Malformed) naming the file (and frame) for bad JSON, a
// point count that changes, a keypoint list not a multiple of 3 (2 for MMPose), non-numeric
// or non-finite values, more frames / points / people than the bounds above, and
// Error(BadData) when no frame has anybody in it. A .csv path goes to readKeypointCsv.
KeypointFrames readKeypointFrames(const std::filesystem::path& path,
                                  const std::optional<KeypointImageSize>& imageSize = std::nullopt);

// The parsers behind it, on text already read (`name` is what errors say).
KeypointFrames parseOpenPoseFrames(const std::vector<std::pair<std::string, std::string>>& filesAndTexts,
                                   const std::string& name);
KeypointFrames parseAlphaPoseJson(const std::string& text, const std::string& name);
KeypointFrames parseMmposeJson(const std::string& text, const std::string& name);

// [SECTION] CSV keypoint files (keypoint_csv.cpp) --------------------------------------------

inline constexpr int kMaxKeypointImageSidePx = 100000;

// "1920x1080" (the --image-size option); Error(BadArgument) naming `option` otherwise.
KeypointImageSize parseKeypointImageSize(const std::string& text, const std::string& option);

enum class KeypointCsvKind { NotKeypoints, MediaPipe, DeepLabCut };

// A CSV's kind from its first line that is neither blank nor a '#' comment: a first field
// "scorer" is DeepLabCut, a "nose_x" column MediaPipe. The project's own CSVs
// ("frame,time_s,head_x,…", "frame,time_s,head_u,…") are NotKeypoints.
KeypointCsvKind keypointCsvKind(std::string_view text);

// The same from the first 64 KiB of a file (not the whole file); NotKeypoints when unreadable.
KeypointCsvKind sniffKeypointCsv(const std::filesystem::path& path);

// Reads a MediaPipe Pose or DeepLabCut CSV, told apart by keypointCsvKind; Error(Malformed)
// naming the file when it is neither. `imageSize` is for MediaPipe (see parseMediaPipeCsv).
KeypointFrames readKeypointCsv(const std::filesystem::path& path,
                               std::optional<KeypointImageSize> imageSize = std::nullopt);

// MediaPipe Pose, one row per frame: a header with <landmark>_x, <landmark>_y for the 33
// BlazePose landmarks (layout "MediaPipe-33"), optional <landmark>_z (ignored),
// <landmark>_visibility (the confidence; 1 without the column), frame, and a time column
// (time_s or timestamp in seconds, timestamp_ms in milliseconds) whose median step gives
// rateHz. x, y are fractions of the image: `imageSize`, else a "# image_size=1920x1080" line
// before the header, gives the pixels; without either Error(BadArgument) naming the file.
// An empty or nan cell is an absent point; a row with no point is a frame with nobody.
KeypointFrames parseMediaPipeCsv(const std::string& text, const std::string& name,
                                 std::optional<KeypointImageSize> imageSize = std::nullopt);

// DeepLabCut: header rows "scorer,…", for multi-animal projects "individuals,…", then
// "bodyparts,…" (each name over its x, y, likelihood columns) and "coords,x,y,likelihood,…";
// then one row per frame "<frame index>,x,y,likelihood,…". Each individual is a detection
// (trackId its index); the first individual's body parts are pointNames. Multi-animal
// "single" columns (unique body parts) are left out with a warning. Empty or nan cells,
// and likelihood 0, are absent points.
KeypointFrames parseDeepLabCutCsv(const std::string& text, const std::string& name);

}  // namespace ew
