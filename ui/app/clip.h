#pragma once
// A pose estimator's keypoint clip in the viewer (docs/VIEWER.md, "Keypoint clips"): what the
// user chose for it and the reconstruction through the unknown camera
// (core/camera/clip_reconstruction.h), computed in the background whenever the choice changes.
// The feature's whole state is one struct, ClipFeature (AppState::clip, at the end); its
// actions are ui/app/clip_actions.h, its panel ui/panels/clip_controls.h.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "core/camera/clip_reconstruction.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/tracking/keyframes.h"
#include "core/eigenwalker/model.h"
#include "ui/app/async_cache.h"

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
  // The horizon's row read off the video's level lines (ui/app/detection.h, VideoHorizon): a
  // detection's fit holds its camera's height to it, as `reconstruct` does; a track's is only
  // checked against it, as `track --reconstruct`'s is (docs/CAMERA.md, "The scene's horizon").
  // Either way a fit more than 2° off it is cautioned.
  std::optional<double> horizonRowPx;
  bool holdToHorizon = true;
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

// [SECTION] The feature's state
// Everything the viewer keeps of the keypoint clip, in one place (AppState::clip): what the
// user chose, the fits computed from it, how its 2D view is magnified.
//
// Undo: the settings live here, not in the Document, and that changes nothing undo does. Undo
// restores named parameters (ui/app/undo.h: the walker, α, the overlays, …), not the Document
// whole, and a clip's settings were never among them: changing one refits, and a new clip
// starts a new history (undo's context is the clip's path, read from here). Were the settings
// to become undoable, undo would capture `settings` from this struct, as it captures the
// overlays from the view state.
struct ClipFeature {
  // The clip open (Mode::Clip shows it) and the user's choices for its fit; none: no clip.
  std::optional<ClipSettings> settings;
  // Its camera fits, by their settings: latest() is the last that succeeded (fit()), error()
  // why the last one failed (the clip's controls show it).
  AsyncCache<ClipSettings, ClipResult> fits{1};
  // The 2D view magnified `zoom` times (1: the region the walker crosses) about the image
  // pixel (x right, y down) at its middle; a new clip starts at 1.
  double zoom = 1.0;
  double zoomCentreX = 0.0, zoomCentreY = 0.0;

  // The last fit that succeeded (null: none yet).
  const std::shared_ptr<const ClipResult>& fit() const { return fits.latest(); }
};

}  // namespace ew::ui
