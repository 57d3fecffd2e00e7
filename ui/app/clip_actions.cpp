// Keypoint clips: opening one, its settings, its camera fit (AppState::clip, ui/app/clip.h).
#include "ui/app/clip_actions.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "core/camera/calibration_file.h"
#include "core/camera/camera_knowledge.h"
#include "core/camera/focal_length.h"
#include "core/common/errors.h"
#include "core/io/file_bytes.h"
#include "core/eigenwalker/model.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_layout.h"
#include "ui/app/actions.h"
#include "ui/app/actions_internal.h"
#include "ui/app/held_model.h"
#include "video/video_beside.h"

namespace ew::ui::actions {

// [SECTION] Keypoint clips

namespace {

// The model a clip is fitted with: the one walkers are inspected against (completionModel).
ClipModel clipModel(AppState& s) {
  ClipModel m;
  m.model = completionModel(s);
  if (!m.model) throw std::runtime_error("no model to fit the clip with");
  m.name = s.doc.defaultModel && m.model.get() == &s.doc.defaultModel->model ? s.doc.defaultModel->name
                                                                             : heldModelName(s.doc);
  return m;
}

// Starts the fit the clip's settings ask for, unless it is shown, running, or failed already.
void startClipFit(AppState& s) {
  if (!s.clip.settings || s.clip.fits.running()) return;
  const ClipModel model = clipModel(s);
  if (s.clip.fit() && s.clip.fit()->settings == *s.clip.settings && s.clip.fit()->model == model) return;
  if (s.clip.fits.failed(*s.clip.settings)) return;
  const std::string title = "Fitting the camera of " + describePaths({s.clip.settings->path});
  s.log.info(title);
  s.clip.fits.start(*s.clip.settings, title, [settings = *s.clip.settings, model](JobProgress& progress) {
    progress.set(0, 1, "reading and fitting");
    return std::make_shared<const ClipResult>(fitClip(settings, model));
  });
}

// A 3D view that takes in the walker's path and the camera: from the side of the walker's
// path away from the camera, raised, far enough to hold both.
void frameClipScene(AppState& s, const ClipResult& c) {
  const Eigen::Vector3d eye = cameraFromLookAt(c.rec.fit.camera) - walkerOriginFromLookAt(c.rec.fit.camera, 0.5 * c.durationS());
  OrbitCamera& cam = s.view.camera;
  cam = OrbitCamera::preset(CameraPreset::ThreeQuarter);
  // The target follows the walker (clipViewCamera): the view is a tracking shot from behind
  // the walker's shoulder, 40° off the line to the camera: the walker near and large in every
  // frame, the camera across the floor.
  cam.target = {0.0f, 0.0f, 1100.0f};
  const double line = std::hypot(eye.x(), eye.y());
  cam.distanceMm = static_cast<float>(std::clamp(0.8 * line + 3500.0, 4000.0, 20000.0));
  cam.pitchDeg = 12.0f;
  const double across = std::atan2(eye.x(), eye.y()) * 180.0 / std::numbers::pi + 140.0;
  cam.yawDeg = static_cast<float>(std::remainder(across, 360.0));
}

// A fit with cautions (a camera no one films a walk with, a weak azimuth) says so in the amber
// banner, where the log alone would go unread; a later fit without them takes the banner away.
constexpr const char* kFitCautionTitle = "The fitted camera may be wrong";
void noticeFitCautions(AppState& s, const ClipResult& c) {
  if (c.rec.cautions.empty()) {
    if (s.notices.banner && s.notices.banner->title.starts_with(kFitCautionTitle)) s.notices.banner.reset();
    return;
  }
  OpenNotice n;
  n.error = false;
  n.title = std::string(kFitCautionTitle) + " (" + c.settings.path.filename().string() + ")";
  n.shortTitle = "Doubtful camera fit";
  for (const auto& caution : c.rec.cautions) n.fullText += (n.fullText.empty() ? "" : "\n") + caution;
  n.detail = n.fullText;
  showNotice(s, std::move(n));
}

// `before`: the fit shown until `c` (clip.fits keeps `c` as its latest, and clears its failure).
void takeClip(AppState& s, const std::shared_ptr<const ClipResult>& before,
              const std::shared_ptr<const ClipResult>& c) {
  const bool newClip = !before || before->settings.path != c->settings.path;
  const auto& cam = c->rec.fit.camera;
  char buf[200];
  std::snprintf(buf, sizeof buf, "azimuth %.1f°, elevation %.1f°, reprojection RMS %.2f px, in %.0f ms",
                cam.alphaDeg, cam.elevationDeg, c->rec.fit.reprojectionRmsPx, 1000.0 * c->seconds);
  s.log.info("Fitted " + describePaths({c->settings.path}) + " (" + c->rec.trial.format + ", " +
             c->rec.trial.layout->name + "): " + buf);
  for (const auto& w : c->rec.trial.warnings) s.log.warning(w);
  for (const auto& caution : c->rec.cautions) s.log.warning(caution);
  if (s.notices.lastError.starts_with("Clip fit failed")) s.notices.lastError.clear();
  // A video's track: the fit shows the frame the user is at.
  if ((c->settings.tracked || c->settings.detected) && s.video.session) {
    // A detection's first fit shows the walker halfway through the frames it is seen on.
    if (c->settings.detected && std::exchange(s.video.session->showWalkerWhenFitted, false)) {
      const auto& t = c->rec.trial;
      if (t.chosen >= 0 && t.chosen < static_cast<int>(t.people.size())) {
        const auto& seen = t.people[static_cast<std::size_t>(t.chosen)].frames;
        if (!seen.empty()) s.video.session->frame = seen[seen.size() / 2];
      }
    }
    setVideoFrame(s, s.video.session->frame);
  }
  if (newClip) {
    dismissNotice(s);
    frameClipScene(s, *c);
    s.clip.zoom = 1.0;
    std::erase(s.recentPaths, c->settings.path);
    s.recentPaths.insert(s.recentPaths.begin(), c->settings.path);
    if (s.recentPaths.size() > 10) s.recentPaths.resize(10);
  }
  noticeFitCautions(s, *c);
}

// A fit that failed: at open, a failed open (the clip shown before, if any, stays); after a
// change of settings, the controls say why and the last fit stays on screen. `running`: the
// settings that failed (clip.fits has them as its failed key, and the error).
void clipFailed(AppState& s, const ClipSettings& running, const std::string& error) {
  ++s.notices.failures;
  const bool atOpen = !s.clip.fit() || s.clip.fit()->settings.path != running.path;
  if (!atOpen) {
    s.notices.lastError = "Clip fit failed (" + heldCameraValues(running) + "): " + error;
    s.log.error(s.notices.lastError);
    return;
  }
  if (error.find(kNeedsImageSize) != std::string::npos && s.clip.settings == running) {
    // Points as fractions of an image of unknown size: the clip stays open, its controls ask
    // for the size (no video beside it gave one).
    s.clip.fits.reset();
    s.notices.lastError = "Give the image size of " + running.path.filename().string();
    s.log.error(error);
    OpenNotice n;
    n.title = s.notices.lastError + " (the Keypoint clip panel)";
    n.shortTitle = "Image size needed";
    n.detail = n.fullText = error;
    showNotice(s, std::move(n));
    return;
  }
  if (s.clip.settings == running) {
    s.clip.settings = s.clip.fit() ? std::optional<ClipSettings>(s.clip.fit()->settings) : std::nullopt;
    // A video stays shown with its track when the walk cannot be fitted to it (a clip that
    // is not walking): the track is still worth seeing over the footage.
    if (!s.clip.settings && !s.video.session && s.doc.mode == Mode::Clip)
      s.doc.mode = Mode::Reconstruct;
  }
  if (running.tracked) {
    // The video opened and tracked; opening it again would not fit the walk either.
    reportError(s, "No walk fits the track of " + running.path.filename().string(),
                error);
    return;
  }
  if (running.detected) {
    reportError(s, "No walk fits the people detected in " + running.path.filename().string(),
                error);
    return;
  }
  reportOpenError(s, {running.path}, error);
}

}  // namespace

void pollClipFit(AppState& s) {
  const auto shownFit = s.clip.fit();
  if (auto done = s.clip.fits.poll()) {
    if (done->ok()) {
      takeClip(s, shownFit, done->value);
    } else {
      clipFailed(s, done->key, done->error);
    }
  }
}

void refitClip(AppState& s) {
  try {
    startClipFit(s);
  } catch (const std::exception& e) {
    const ClipSettings settings = *s.clip.settings;  // a copy: clipFailed may change them
    s.clip.fits.fail(settings, e.what());
    clipFailed(s, settings, e.what());
  }
}

// Opens the first keypoint clip among `paths` and returns the others; further clips are
// refused (one clip at a time), and every clip when a video was opened with them.
std::vector<std::filesystem::path> openClips(AppState& s, std::vector<std::filesystem::path> paths,
                                             std::vector<std::string>& refused, bool withVideo) {
  std::vector<std::filesystem::path> rest, calibrations;
  bool opened = false;
  for (auto& p : paths) {
    if (isCalibrationFile(p)) {
      calibrations.push_back(std::move(p));
    } else if (!isKeypointClip(p)) {
      rest.push_back(std::move(p));
    } else if (withVideo) {
      refused.push_back(p.string() +
                        ": a video and a keypoint clip at a time (the video is open; its Mark the "
                        "joints section reads a keypoint file of it)");
    } else if (opened) {
      refused.push_back(p.string() + ": one keypoint clip at a time");
    } else {
      openClip(s, p);
      opened = true;
    }
  }
  // A calibration goes to the clip opened with it, or to the one open.
  for (const auto& file : calibrations) {
    if (!s.clip.settings) {
      refused.push_back(file.string() + ": a calibration is for a keypoint clip: open one with it");
      continue;
    }
    try {
      setClipCalibration(s, file, "");
    } catch (const std::exception& e) {
      refused.push_back(e.what());
    }
  }
  return rest;
}

std::shared_ptr<const EigenwalkerModel> modelForTracking(AppState& s) { return clipModel(s).model; }

namespace {

std::string lettersAndDigits(const std::string& text) {
  std::string out;
  for (unsigned char ch : text)
    if (std::isalnum(ch)) out.push_back(static_cast<char>(std::tolower(ch)));
  return out;
}

// The camera of a calibration with several whose name the clip's folder or file carries
// (Pose2Sim: cam_01 for pose/cam01_json), else "" (the file's only camera, or an error listing
// them when the fit reads it).
std::string calibrationCameraFor(const std::filesystem::path& file, const std::filesystem::path& clip) {
  std::vector<CalibratedCamera> cameras;
  try {
    cameras = parseCalibrationToml(readFileText(file), file.string());
  } catch (const std::exception&) {
    return "";  // resolveCameraKnowledge says what is wrong with it
  }
  if (cameras.size() < 2) return "";
  const std::string clipName = lettersAndDigits(clip.filename().string());
  std::string match;
  for (const CalibratedCamera& c : cameras) {
    const std::string name = lettersAndDigits(c.name);
    if (name.empty() || clipName.rfind(name, 0) != 0) continue;
    if (!match.empty()) return "";  // two fit: the user chooses
    match = c.name;
  }
  return match;
}

ClipSettings& clipSettings(AppState& s) {
  if (!s.clip.settings) throw std::invalid_argument("no keypoint clip is open");
  return *s.clip.settings;
}

}  // namespace

bool isKeypointClip(const std::filesystem::path& path) {
  try {
    return looksLikeKeypointInput(path) && !isModelFile(path);
  } catch (const std::exception&) {
    return false;  // unreadable: the motion-capture loader says why
  }
}

void openClip(AppState& s, const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw std::invalid_argument(path.string() + ": no such file or folder");
  ClipSettings settings;
  settings.path = path;
  // The clip takes the views' place, as a video opened takes a clip's.
  closeVideo(s);
  // A clip opened again keeps what the user chose for it; its video is looked for again.
  if (s.clip.settings && s.clip.settings->path == path) settings = *s.clip.settings;
  settings.video = videoBesideKeypoints(path);
  s.clip.settings = settings;
  s.doc.mode = Mode::Clip;
  s.clip.fits.retry();
  s.log.info("Opening the keypoint clip " + path.string());
}

void setClipFocal(AppState& s, std::optional<double> focalPx) {
  if (focalPx && !isPlausibleFocalPx(*focalPx)) throw std::invalid_argument(focalLengthProblem(*focalPx));
  ClipSettings& c = clipSettings(s);
  c.focalPx = focalPx;
  // The last given wins: a focal length typed replaces a calibration's.
  if (focalPx) c.calibrationFile.clear(), c.calibrationCamera.clear();
}

bool isCalibrationFile(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return extension == ".toml";
}

void setClipCalibration(AppState& s, const std::filesystem::path& file, const std::string& camera) {
  ClipSettings& c = clipSettings(s);
  if (file.empty()) {
    c.calibrationFile.clear();
    c.calibrationCamera.clear();
    return;
  }
  const std::string chosen = camera.empty() ? calibrationCameraFor(file, c.path) : camera;
  CameraGivens given;
  given.calibrationFile = file;
  if (!chosen.empty()) given.calibrationCamera = chosen;
  try {
    resolveCameraKnowledge(given);  // reads and checks it now, not in the fit
  } catch (const std::exception& e) {
    throw std::invalid_argument(e.what());
  }
  c.calibrationFile = file;
  c.calibrationCamera = chosen;
  c.focalPx.reset();
  s.log.info("Calibration " + file.filename().string() + (chosen.empty() ? "" : " (" + chosen + ")") +
             " for the keypoint clip");
}

void setClipAzimuth(AppState& s, std::optional<double> alphaDeg) {
  if (alphaDeg && !(std::isfinite(*alphaDeg) && *alphaDeg >= -180.0 && *alphaDeg <= 180.0))
    throw std::invalid_argument("azimuth must lie in [-180, 180] degrees");
  clipSettings(s).alphaDeg = alphaDeg;
}

void setClipElevation(AppState& s, std::optional<double> elevationDeg) {
  if (elevationDeg && !(std::isfinite(*elevationDeg) && *elevationDeg >= -30.0 && *elevationDeg <= 80.0))
    throw std::invalid_argument("elevation must lie in [-30, 80] degrees");
  clipSettings(s).elevationDeg = elevationDeg;
}

void setClipHoldToHorizon(AppState& s, bool hold) {
  ClipSettings& c = clipSettings(s);
  if (!c.horizonRowPx)
    throw std::invalid_argument("no scene horizon was read for this clip (a detected or tracked video's level lines give one)");
  c.holdToHorizon = hold;
}

void setClipLayout(AppState& s, const std::string& layout) {
  std::string name;
  if (!layout.empty()) {
    try {
      name = keypointLayoutNamed(layout).name;
    } catch (const std::exception& e) {
      throw std::invalid_argument(e.what());
    }
  }
  clipSettings(s).layout = name;
}

void setClipFps(AppState& s, double fps) {
  if (!(std::isfinite(fps) && fps >= 0.0 && fps <= 10000.0))
    throw std::invalid_argument("frame rate must lie in [0, 10000] fps (0 = the file's, else 30)");
  clipSettings(s).fps = fps;
}

void setClipImageSize(AppState& s, std::optional<KeypointImageSize> size) {
  const auto side = [](int px) { return px >= 1 && px <= kMaxKeypointImageSidePx; };
  if (size && !(side(size->width) && side(size->height)))
    throw std::invalid_argument("image size must be 1 to " + std::to_string(kMaxKeypointImageSidePx) +
                                " px a side");
  clipSettings(s).imageSize = size;
}

void setClipPerson(AppState& s, int person) {
  if (person < -1) throw std::invalid_argument("person must be -1 (the walker) or a track index");
  if (s.clip.fit() && person >= static_cast<int>(s.clip.fit()->rec.trial.people.size()))
    throw std::invalid_argument("person " + std::to_string(person) + " out of range (" +
                                std::to_string(s.clip.fit()->rec.trial.people.size()) + " tracks)");
  clipSettings(s).person = person;
}

void setClipFrame(AppState& s, int frame) {
  if (s.doc.mode != Mode::Clip || !s.clip.fit()) throw std::invalid_argument("no keypoint clip is shown");
  const ClipResult& c = *s.clip.fit();
  if (frame < 1 || frame > c.rec.trial.frameCount)
    throw std::invalid_argument("frame must lie in [1, " + std::to_string(c.rec.trial.frameCount) + "]");
  // Half a frame in, so that the frame shown is this one however the time rounds.
  s.view.playback.cycles = (frame - 0.5) / c.rec.trial.rateHz * c.rec.fit.strideHz;
  s.view.playback.playing = false;
}

void setClipZoom(AppState& s, double zoom, const Eigen::Vector2d& centrePx) {
  if (!s.clip.fit()) throw std::invalid_argument("no keypoint clip is shown");
  if (!std::isfinite(zoom) || !centrePx.allFinite()) throw std::invalid_argument("clip zoom: not a number");
  s.clip.zoom = std::clamp(zoom, 1.0, kMaxVideoZoom);
  s.clip.zoomCentreX = centrePx.x();
  s.clip.zoomCentreY = centrePx.y();
}

void closeClip(AppState& s) {
  s.clip.settings.reset();
  s.clip.fits.reset();
  s.clip.fits.clearFailure();
  if (s.doc.mode == Mode::Clip) s.doc.mode = Mode::Reconstruct;
}

}  // namespace ew::ui::actions
