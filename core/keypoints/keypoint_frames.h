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
  bool operator==(const KeypointImageSize&) const = default;
};

// Said by every reader of points as fractions of the image when it has no size to multiply
// them by (the viewer keeps such a clip open for the user to give one).
inline constexpr std::string_view kNeedsImageSize = "fractions of the image";

// The video a pose estimator read: the picture's size and the frame rate, which most keypoint
// files do not store.
struct KeypointVideo {
  std::string file;
  KeypointImageSize size;
  double fps = 0.0;  // 0: unknown
  bool operator==(const KeypointVideo&) const = default;
};

struct KeypointFrames {
  std::string file;    // the file or folder as given
  std::string format;  // "OpenPose JSON", "AlphaPose JSON", "MMPose JSON", "MediaPipe CSV", "DeepLabCut CSV",
                       // "YOLO pose labels"
  int pointCount = 0;  // points per person (the same in every detection)
  std::optional<std::string> layoutHint;  // a layout name the file states (MMPose meta_info)
  std::optional<double> rateHz;           // a frame rate the file states (a CSV time column)
  std::vector<std::string> pointNames;    // the file's own point names (DeepLabCut); else empty
  std::optional<KeypointImageSize> imageSize;  // the image the points were found in, when the file states it
  std::vector<std::vector<KeypointDetection>> frames;
  std::vector<std::string> warnings;
  // The trackIds follow each person (the built-in detector's, which follows each one on its
  // own crop): people are grouped by them instead of by nearness, so that someone who
  // leaves is never continued by whoever stands nearest (trackPeople).
  bool trackIdsFollowPeople = false;

  int frameCount() const { return static_cast<int>(frames.size()); }
};

// Bounds: files hold real clips, not hours (an hour at 60 fps is 216000 frames).
inline constexpr int kMaxKeypointFrames = 216000;
inline constexpr int kMaxKeypointsPerPerson = 200;
inline constexpr int kMaxPeoplePerFrame = 100;

// True when `path` is a folder of OpenPose JSON files, a .json file (any of the three), a
// .csv file whose first lines are a MediaPipe or DeepLabCut header (keypointCsvKind), or YOLO
// pose labels (yoloLabelsFolder).
bool looksLikeKeypointInput(const std::filesystem::path& path);

// A folder's per-frame files ending in `extension` (".json"), as (file name, text) pairs in
// frame order (trailingNumber, then the name). Error(Io) when the folder cannot be listed,
// Error(BadData) when it holds none, Error(Malformed) for more than kMaxKeypointFrames.
std::vector<std::pair<std::string, std::string>> readPerFrameFiles(const std::filesystem::path& folder,
                                                                   const std::string& extension);

// The last run of digits in a file name's stem ("cam01.0012.json" -> 12, "walk_7.txt" -> 7),
// the frame number per-frame files carry; -1 when it has none.
long trailingNumber(const std::string& fileName);

// Reads a keypoint file or folder, telling the format from the content: YOLO pose labels
// (yoloLabelsFolder), a folder of per-frame files or an object with "people" is OpenPose, a list of {"image_id", "keypoints"}
// AlphaPose, an object or list with "instance_info" / "instances" MMPose. Throws Error(Io)
// for an unreadable path, Error(Malformed) naming the file (and frame) for bad JSON, a
// point count that changes, a keypoint list not a multiple of 3 (2 for MMPose), non-numeric
// or non-finite values, more frames / points / people than the bounds above, and
// Error(BadData) when no frame has anybody in it (also for `[]`, what AlphaPose writes for a
// video with nobody in it). A .csv path goes to readKeypointCsv.
// Per-frame files (OpenPose, YOLO) and AlphaPose's numbered images are placed by their frame
// numbers: a frame with no file or entry is a frame with nobody (with a warning), so that a
// clip's timing holds where the estimator wrote nothing. `imageSize` is for the readers of
// points as fractions of the image (MediaPipe, YOLO): the size given, else the file's own
// (a MediaPipe comment), else `videoSize` (the video's found beside the file).
KeypointFrames readKeypointFrames(const std::filesystem::path& path,
                                  const std::optional<KeypointImageSize>& imageSize = std::nullopt,
                                  const std::optional<KeypointImageSize>& videoSize = std::nullopt);

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
// "scorer" is DeepLabCut, a MediaPipe landmark's _visibility column or the _x columns of two
// of its landmarks MediaPipe. The project's own CSVs ("frame,time_s,head_x,…", "frame,time_s,head_u,…") are
// NotKeypoints.
KeypointCsvKind keypointCsvKind(std::string_view text);

// The same from the first 64 KiB of a file (not the whole file); NotKeypoints when unreadable.
KeypointCsvKind sniffKeypointCsv(const std::filesystem::path& path);

// Reads a MediaPipe Pose or DeepLabCut CSV, told apart by keypointCsvKind; Error(Malformed)
// naming the file when it is neither. `imageSize` is for MediaPipe (see parseMediaPipeCsv).
KeypointFrames readKeypointCsv(const std::filesystem::path& path,
                               std::optional<KeypointImageSize> imageSize = std::nullopt,
                               std::optional<KeypointImageSize> videoSize = std::nullopt);

// MediaPipe Pose, one row per frame: a header with <landmark>_x, <landmark>_y for the 33
// BlazePose landmarks (layout "MediaPipe-33"), optional <landmark>_z (ignored),
// <landmark>_visibility (the confidence; 1 without the column), frame, and a time column
// (time_s or timestamp in seconds, timestamp_ms in milliseconds) whose median step gives
// rateHz. x, y are fractions of the image: `imageSize`, else a "# image_size=1920x1080" line
// before the header, else `videoSize`, gives the pixels; without any Error(BadArgument)
// naming the file.
// An empty or nan cell is an absent point; a row with no point is a frame with nobody.
KeypointFrames parseMediaPipeCsv(const std::string& text, const std::string& name,
                                 std::optional<KeypointImageSize> imageSize = std::nullopt,
                                 std::optional<KeypointImageSize> videoSize = std::nullopt);

// DeepLabCut: header rows "scorer,…", for multi-animal projects "individuals,…", then
// "bodyparts,…" (each name over its x, y, likelihood columns) and "coords,x,y,likelihood,…";
// then one row per frame "<frame index>,x,y,likelihood,…". Each individual is a detection
// (trackId its index); the first individual's body parts are pointNames. Multi-animal
// "single" columns (unique body parts) are left out with a warning. Empty or nan cells,
// and likelihood 0, are absent points.
KeypointFrames parseDeepLabCutCsv(const std::string& text, const std::string& name);

// [SECTION] Ultralytics YOLO pose labels (yolo_pose_labels.cpp) ------------------------------

// What `yolo pose predict save_txt=True` writes: per frame a "<video>_<frame>.txt" (frames from
// 1; none where nobody was detected), a line a person: "class cx cy w h", then "x y v" (or
// "x y") per keypoint, then the box confidence (save_conf) and the track id (`yolo track`),
// every coordinate a fraction of the image. Returns the folder of label files `path` stands
// for (itself, or its "labels" folder: Ultralytics' run folder, which holds the labels and the
// annotated video), or `path` itself for one .txt file, when its first file's first line reads
// as such a label; nullopt otherwise.
std::optional<std::filesystem::path> yoloLabelsFolder(const std::filesystem::path& path);

// Reads them from `labels`, the folder of label files or the one file yoloLabelsFolder found
// (not looked for again): each file's frame number places it (Ultralytics counts from 1; a folder whose
// numbers start at 0 from 0), an absent file is a frame with nobody. The point count and
// what follows the keypoints are decided from the field count (17, 18, 25, 26 or 33 points;
// an extra whole number in every line is a track id, else the box confidence); 17 points are
// COCO-17. x, y are multiplied by `imageSize`, required: Error(BadArgument) naming the
// folder without it. A keypoint at (0, 0) or of visibility 0 is absent. Error(Malformed)
// naming the file and line for a non-number, a field count that changes or fits no layout,
// coordinates that are not fractions (below -1 or above 2: pixels), a file name without a
// frame number, two files of one frame; the bounds of KeypointFrames.
KeypointFrames readYoloPoseLabels(const std::filesystem::path& labels, std::optional<KeypointImageSize> imageSize);
// The same on texts already read: (file name, text) pairs; `name` is what errors say.
KeypointFrames parseYoloPoseLabels(const std::vector<std::pair<std::string, std::string>>& filesAndTexts,
                                   const std::string& name, std::optional<KeypointImageSize> imageSize);

}  // namespace ew
