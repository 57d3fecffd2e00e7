#pragma once
// A pose estimator's keypoint clip in the viewer (docs/VIEWER.md, "Keypoint clips"): what the
// user chose for it (the Document's part) and the reconstruction through the unknown camera
// (core/camera/clip_reconstruction.h), computed in the background whenever the choice changes.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "core/camera/clip_reconstruction.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/tracking/keyframes.h"
#include "core/eigenwalker/model.h"

namespace ew::ui {

struct ClipSettings {
  std::filesystem::path path;      // OpenPose folder or file, AlphaPose / MMPose JSON, MediaPipe / DLC CSV
  std::string layout;              // "" = guessed
  double fps = 0.0;                // 0 = the file's, else 30 (JSON stores none)
  int person = -1;                 // -1 = the one who walks
  std::optional<double> focalPx;   // known focal length (else estimated)
  // A calibration file (Pose2Sim's Calib_*.toml; docs/CAMERA.md) and which of its cameras
  // ("" = its only one): the focal length, the principal point and the lens's distortion.
  std::filesystem::path calibrationFile;
  std::string calibrationCamera;
  std::optional<double> alphaDeg;  // azimuth held at this value (else estimated)
  std::optional<double> elevationDeg;
  // The image's size, given by the user: else the file's, else the video's found beside the
  // keypoints (video/video_beside.h). What a MediaPipe CSV's or YOLO labels' fractions are of.
  std::optional<KeypointImageSize> imageSize;
  // The video found beside the keypoints when the clip was opened (not on every refit: opening
  // a 1080p H.264 file takes ~25 ms).
  std::optional<KeypointVideo> video;
  // A video's tracked joints (ui/app/video.h) instead of a file: `path` is the video; layout,
  // fps and person do not apply.
  std::shared_ptr<const KeypointTrial> tracked;
  // A video's people found by the built-in detector (ui/app/detection.h) instead of a file:
  // `path` is the video, `video` its size and rate; read as a MediaPipe-33 file is (person,
  // fps apply; the layout is the detector's).
  std::shared_ptr<const KeypointFrames> detected;
  // The joints the user corrected on frames of `detected` (the video's keyframes, ui/app/video.h):
  // the walker's track redone around each (correctTrial, core/tracking/corrected_track.h)
  // before the fit. Null when none.
  std::shared_ptr<const Keyframes> corrections;
  bool operator==(const ClipSettings&) const = default;
};

// The model a clip is fitted with and what the header calls it.
struct ClipModel {
  std::shared_ptr<const EigenwalkerModel> model;
  std::string name;
  bool operator==(const ClipModel& o) const { return model == o.model; }
};

// The pixels a clip's points cover (u, v; empty when none is finite).
struct PixelBounds {
  Eigen::Vector2d low{0.0, 0.0}, high{0.0, 0.0};
  bool empty = true;
};

struct ClipResult {
  ClipSettings settings;
  ClipModel model;
  ClipReconstruction rec;
  double seconds = 0.0;  // how long reading and fitting took
  // Computed once with the fit, for the views: the keypoints' extent (the camera glyph's
  // view rays) and the keypoints' and reprojection's together (the 2D view's frame).
  PixelBounds keypointBounds, shownBounds;
  double durationS() const { return rec.timesS.size() > 0 ? rec.trial.frameCount / rec.trial.rateHz : 0.0; }
};

// Reads and fits the clip (blocking; the viewer runs it as a background job). Throws what
// core throws: typed errors naming the file.
ClipResult fitClip(const ClipSettings& settings, const ClipModel& model);

// What the views say where a clip has no fit: that it needs the image's size (its points are
// fractions of an image of unknown size), else that it could not be fitted.
const char* unfittedClipMessage(const std::string& fitError);

// The clip's frame shown at playback position `cycles` (gait cycles since the start, wrapped
// to the clip's length): the 2D input and the 3D walker are drawn at this same frame.
int clipFrameAt(const ClipResult& clip, double cycles);
// Fixed values the fit held, for captions: "focal 1400 px, elevation 12°" ("" when none).
std::string heldCameraValues(const ClipSettings& settings);

}  // namespace ew::ui
