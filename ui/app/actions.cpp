#include "ui/app/actions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string_view>

#include "core/camera/focal_length.h"
#include "core/common/errors.h"
#include "core/engine/model.h"
#include "core/engine/model_file.h"
#include "core/engine/projection.h"
#include "core/gait/joint_angles.h"
#include "core/io/atomic_write.h"
#include "core/io/bvh_writer.h"
#include "core/io/joint_csv.h"
#include "core/io/load_trial.h"
#include "core/io/trc_writer.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_layout.h"
#include "ui/app/held_model.h"
#include "ui/app/script.h"
#include "ui/app/state_json.h"
#include "ui/app/theme.h"
#include "ui/app/tour.h"
#include "ui/app/video_poll.h"
#include "video/video_beside.h"

namespace ew::ui::actions {

// [SECTION] Loading

namespace {

void ensureDefaultModel(AppState& s);

// The model that completes trials lacking joints (joint_completion.h): the one they will be
// inspected against (the default model when the synthetic population, or nothing, is shown).
std::shared_ptr<const EigenwalkerModel> completionModel(AppState& s) {
  const Document& d = s.doc;
  if (d.modelSource == ModelSource::Population && d.models && !d.sourcePaths.empty())
    return {d.models, &d.models->all};
  if (d.modelSource == ModelSource::File && d.heldModel())
    return {d.modelFiles[static_cast<std::size_t>(d.modelFile)], d.heldModel()};
  try {
    ensureDefaultModel(s);
  } catch (const std::exception& e) {
    s.log.warning(std::string("no model to complete trials that lack joints: ") + e.what());
    return nullptr;
  }
  return {s.doc.defaultModel, &s.doc.defaultModel->model};
}

void startLoad(AppState& s, OpenRequest request) {
  const auto paths = request.paths;
  auto completion = paths.empty() ? nullptr : completionModel(s);
  s.jobs.loading = std::move(request);
  const std::string title =
      paths.empty() ? "Synthesising the default population" : "Loading " + describePaths(paths);
  s.log.info(title);
  s.jobs.load.start(title,
                    [paths, overrides = s.doc.fileOverrides,
                     completion](JobProgress& progress) -> std::shared_ptr<const Population> {
                      auto report = [&progress](int done, int total, const std::string& what) {
                        progress.set(done, total, what);
                      };
                      if (paths.empty())
                        return std::make_shared<const Population>(defaultPopulation(report));
                      // One walker is enough: fewer than a leave-one-out population needs are
                      // inspected against the held model (pollJobs decides).
                      return std::make_shared<const Population>(
                          loadPopulation(paths, report, overrides, 1, completion));
                    });
}

// Starts the open now, or once the running load / model build is done.
void requestOpen(AppState& s, OpenRequest request) {
  if (s.jobs.load.running() || s.jobs.models.running()) {
    s.jobs.pendingOpen = std::move(request);
    return;
  }
  startLoad(s, std::move(request));
}

void startModels(AppState& s) {
  auto population = s.doc.population;
  s.jobs.models.start("Building leave-one-out models",
                      [population](JobProgress& progress) -> std::shared_ptr<const ModelSet> {
                        return std::make_shared<const ModelSet>(buildModelSet(
                            *population, [&progress](int done, int total, const std::string& what) {
                              progress.set(done, total, what);
                            }));
                      });
}

LoadedData loadedData(const Document& d) {
  return {d.population, d.models, d.sourcePaths, d.walker, d.editedSd, d.exploreSd, d.modelSource};
}

// Puts back the data shown before a load, under a new generation (caches computed for what
// failed must not be taken for it). The user's settings (α, estimator, mode, N, overrides)
// stay as they are.
void restoreData(AppState& s, LoadedData before) {
  s.doc.population = std::move(before.population);
  s.doc.models = std::move(before.models);
  s.doc.sourcePaths = std::move(before.sourcePaths);
  s.doc.walker = before.walker;
  s.doc.editedSd = std::move(before.editedSd);
  s.doc.exploreSd = std::move(before.exploreSd);
  s.doc.modelSource = before.modelSource;
  ++s.doc.generation;
}

// What the user still has after a failure.
std::string keptDescription(const AppState& s) {
  if (s.doc.walkerCount() == 0)
    return "Nothing is loaded: open other data, or the synthetic default population.";
  std::string kept = "Still showing ";
  if (s.doc.population) {
    kept += s.doc.population->label + " (" + std::to_string(s.doc.population->walkerCount()) +
            " walkers";
    if (s.doc.inspected)
      kept += " + " + std::to_string(s.doc.inspected->walkerCount()) + " inspected";
  } else {
    kept +=
        std::to_string(s.doc.walkerCount()) + " inspected walker(s) (model " + heldModelName(s.doc);
  }
  if (const Walker* w = s.doc.selectedWalker()) kept += ", " + w->subject + " selected";
  return kept + "): nothing you had open has changed.";
}

// The message with each opened path shortened to its file or folder name where it names it
// (the banner's title says where it was opened from; the log keeps the full paths).
std::string shortenPaths(std::string message, const std::vector<std::filesystem::path>& paths) {
  std::vector<std::filesystem::path> sorted = paths;
  std::sort(sorted.begin(), sorted.end(),
            [](const auto& a, const auto& b) { return a.string().size() > b.string().size(); });
  for (const auto& p : sorted) {
    const std::string full = p.string();
    const std::string name = describePaths({p});
    if (full.empty() || full == name) continue;
    for (std::size_t at = message.find(full); at != std::string::npos;
         at = message.find(full, at)) {
      const std::size_t end = at + full.size();
      const bool whole = end == message.size() ||
                         std::string_view(":/ ,\n").find(message[end]) != std::string_view::npos;
      if (!whole) {
        at = end;
        continue;
      }
      message.replace(at, full.size(), name);
      at += name.size();
    }
  }
  return message;
}

void showNotice(AppState& s, OpenNotice notice) {
  notice.serial = ++s.jobs.noticeSerial;
  s.jobs.notice = std::move(notice);
}

// After a load that left some of the items the user named out: an amber banner.
void noticeSkipped(AppState& s, const OpenRequest& request, const Population& pop) {
  std::vector<std::string> skipped = request.refused;
  skipped.insert(skipped.end(), pop.skippedItems.begin(), pop.skippedItems.end());
  if (skipped.empty()) return;
  OpenNotice n;
  n.error = false;
  const auto& named = request.named.empty() ? request.paths : request.named;
  n.title = "Opened " + std::to_string(named.size() - skipped.size()) + " of " +
            std::to_string(named.size()) + " items; skipped " + std::to_string(skipped.size());
  for (const auto& why : skipped) n.fullText += (n.fullText.empty() ? "" : "\n") + why;
  n.detail = shortenPaths(n.fullText, named);
  n.kept = "Showing " + pop.label + " (" + std::to_string(pop.walkerCount()) + " walkers).";
  showNotice(s, std::move(n));
}

// [SECTION] Models held and walkers inspected

// Makes `saved` the held model: every walker is inspected against it from now on.
void holdModel(AppState& s, std::shared_ptr<const SavedModel> saved) {
  auto& files = s.doc.modelFiles;
  const auto same = std::find_if(files.begin(), files.end(), [&saved](const auto& m) {
    return !m->file.empty() && fileKey(m->file) == fileKey(saved->file);
  });
  const int index = static_cast<int>(same - files.begin());
  if (same != files.end()) {
    *same = saved;  // opened again: the file's current contents
  } else {
    files.push_back(saved);
  }
  s.doc.modelFile = index;
  s.doc.modelSource = ModelSource::File;
  s.doc.editedSd.clear();
  ++s.doc.generation;
  s.log.info("Model " + saved->name + " (" + std::to_string(saved->model.walkerCount()) +
             " walkers, " + std::to_string(saved->model.componentCount()) +
             " components): the walkers are inspected against it");
}

// The default model of real walkers, read once. Throws ew::Error when its asset is bad.
void ensureDefaultModel(AppState& s) {
  if (!s.doc.defaultModel) s.doc.defaultModel = readDefaultModel();
}

// Reads the .ewm files among `paths` and holds the last that reads; a file that does not
// read is reported as a failed open. Returns the other paths.
std::vector<std::filesystem::path> openModelFiles(AppState& s,
                                                  std::vector<std::filesystem::path> paths) {
  std::vector<std::filesystem::path> rest;
  for (auto& p : paths) {
    if (!isModelFile(p)) {
      rest.push_back(std::move(p));
      continue;
    }
    try {
      holdModel(s, readModelFile(p));
      dismissNotice(s);
    } catch (const std::exception& e) {
      ++s.jobs.failures;
      reportOpenError(s, {p}, e.what());
    }
  }
  return rest;
}

// Whether walkers just loaded are inspected against the held model rather than becoming the
// population: always while a saved or default model is held; with the population's model,
// when they are too few for a leave-one-out population of their own.
bool inspectLoaded(const AppState& s, const Population& loaded) {
  if (s.jobs.loading.paths.empty()) return false;  // the synthetic default population
  // A model is not built from its own estimates: completed trials are always inspected.
  return s.doc.modelSource != ModelSource::Population || loaded.walkerCount() < kMinPopulation ||
         hasModelEstimated(loaded);
}

// Appends `loaded` to the inspected walkers and selects the first of them. A synthetic
// population's model is no model of real walkers: with it (or nothing) held, they meet the
// default model of real walkers. Throws when that model cannot be read.
void addInspected(AppState& s, const Population& loaded) {
  if (s.doc.modelSource == ModelSource::Population &&
      (!s.doc.population || s.doc.sourcePaths.empty())) {
    ensureDefaultModel(s);
    s.doc.modelSource = ModelSource::Default;
    s.log.info(
        "Inspecting against " + s.doc.defaultModel->name +
        (s.doc.population ? ": the synthetic population is not a model of real walkers" : ""));
  }
  auto all = std::make_shared<Population>();
  if (s.doc.inspected) *all = *s.doc.inspected;
  all->label = all->label.empty() ? loaded.label : all->label + ", " + loaded.label;
  const int first = s.doc.populationCount() + all->walkerCount();
  all->walkers.insert(all->walkers.end(), loaded.walkers.begin(), loaded.walkers.end());
  all->facts.insert(all->facts.end(), loaded.facts.begin(), loaded.facts.end());
  all->warnings.insert(all->warnings.end(), loaded.warnings.begin(), loaded.warnings.end());
  s.doc.inspected = std::move(all);
  s.doc.walker = first;
  s.panels.subjects.scrollToSelection = true;
  s.doc.editedSd.clear();
  ++s.doc.generation;
  s.log.info("Inspecting " + loaded.label + " (" + std::to_string(loaded.walkerCount()) +
             " walker(s)) against " + heldModelName(s.doc));
}

// A load finished: the new population (its models built next), or walkers to inspect.
void takeLoaded(AppState& s, const std::shared_ptr<const Population>& pop) {
  dismissNotice(s);
  for (const auto& w : s.jobs.loading.refused) s.log.warning("skipped: " + w);
  for (const auto& w : pop->warnings) s.log.warning(w);
  if (inspectLoaded(s, *pop)) {
    addInspected(s, *pop);
    noticeSkipped(s, s.jobs.loading, *pop);
    return;
  }
  // What was shown stays until the new models are built (a failed build puts it back).
  if (s.doc.population) s.jobs.beforeLoad = loadedData(s.doc);
  s.doc.population = pop;
  s.doc.models.reset();
  if (!s.jobs.loading.keepModel) s.doc.modelSource = ModelSource::Population;
  s.doc.sourcePaths = s.jobs.loading.paths;
  ++s.doc.generation;
  s.doc.walker = 0;
  s.doc.editedSd.clear();
  s.doc.exploreSd.clear();
  s.doc.exploreOmegaOffsetRadS = 0.0;
  s.log.info("Loaded " + pop->label + ": " + std::to_string(pop->walkerCount()) + " walkers");
  noticeSkipped(s, s.jobs.loading, *pop);
  startModels(s);
}

// [SECTION] Keypoint clips

// The model a clip is fitted with: the one walkers are inspected against (completionModel).
ClipModel clipModel(AppState& s) {
  ClipModel m;
  m.model = completionModel(s);
  if (!m.model) throw std::runtime_error("no model to fit the clip with");
  m.name = s.doc.defaultModel && m.model.get() == &s.doc.defaultModel->model ? s.doc.defaultModel->name
                                                                             : heldModelName(s.doc);
  return m;
}

// Starts the fit the document asks for, unless it is shown, running, or failed already.
void startClipFit(AppState& s) {
  if (!s.doc.clip || s.jobs.clip.running()) return;
  const ClipModel model = clipModel(s);
  if (s.clip() && s.clip()->settings == *s.doc.clip && s.clip()->model == model) return;
  if (s.jobs.clip.failed(*s.doc.clip)) return;
  const std::string title = "Fitting the camera of " + describePaths({s.doc.clip->path});
  s.log.info(title);
  s.jobs.clip.start(*s.doc.clip, title, [settings = *s.doc.clip, model](JobProgress& progress) {
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
    if (s.jobs.notice && s.jobs.notice->title.starts_with(kFitCautionTitle)) s.jobs.notice.reset();
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

// `before`: the fit shown until `c` (jobs.clip keeps `c` as its latest, and clears its failure).
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
  if (s.jobs.lastError.starts_with("Clip fit failed")) s.jobs.lastError.clear();
  // A video's track: the fit shows the frame the user is at.
  if ((c->settings.tracked || c->settings.detected) && s.video) {
    // A detection's first fit shows the walker halfway through the frames it is seen on.
    if (c->settings.detected && std::exchange(s.video->showWalkerWhenFitted, false)) {
      const auto& t = c->rec.trial;
      if (t.chosen >= 0 && t.chosen < static_cast<int>(t.people.size())) {
        const auto& seen = t.people[static_cast<std::size_t>(t.chosen)].frames;
        if (!seen.empty()) s.video->frame = seen[seen.size() / 2];
      }
    }
    setVideoFrame(s, s.video->frame);
  }
  if (newClip) {
    dismissNotice(s);
    frameClipScene(s, *c);
    s.view.clipZoom = 1.0;
    std::erase(s.recentPaths, c->settings.path);
    s.recentPaths.insert(s.recentPaths.begin(), c->settings.path);
    if (s.recentPaths.size() > 10) s.recentPaths.resize(10);
  }
  noticeFitCautions(s, *c);
}

// A fit that failed: at open, a failed open (the clip shown before, if any, stays); after a
// change of settings, the controls say why and the last fit stays on screen. `running`: the
// settings that failed (jobs.clip has them as its failed key, and the error).
void clipFailed(AppState& s, const ClipSettings& running, const std::string& error) {
  ++s.jobs.failures;
  const bool atOpen = !s.clip() || s.clip()->settings.path != running.path;
  if (!atOpen) {
    s.jobs.lastError = "Clip fit failed (" + heldCameraValues(running) + "): " + error;
    s.log.error(s.jobs.lastError);
    return;
  }
  if (error.find(kNeedsImageSize) != std::string::npos && s.doc.clip == running) {
    // Points as fractions of an image of unknown size: the clip stays open, its controls ask
    // for the size (no video beside it gave one).
    s.jobs.clip.reset();
    s.jobs.lastError = "Give the image size of " + running.path.filename().string();
    s.log.error(error);
    OpenNotice n;
    n.title = s.jobs.lastError + " (the Keypoint clip panel)";
    n.shortTitle = "Image size needed";
    n.detail = n.fullText = error;
    showNotice(s, std::move(n));
    return;
  }
  if (s.doc.clip == running) {
    s.doc.clip = s.clip() ? std::optional<ClipSettings>(s.clip()->settings) : std::nullopt;
    // A video stays shown with its track when the walk cannot be fitted to it (a clip that
    // is not walking): the track is still worth seeing over the footage.
    if (!s.doc.clip && !s.video && s.doc.mode == Mode::Clip) s.doc.mode = Mode::Reconstruct;
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

// Opens the first keypoint clip among `paths` and returns the others; further clips are
// refused (one clip at a time), and every clip when a video was opened with them.
std::vector<std::filesystem::path> openClips(AppState& s, std::vector<std::filesystem::path> paths,
                                             std::vector<std::string>& refused, bool withVideo = false) {
  std::vector<std::filesystem::path> rest;
  bool opened = false;
  for (auto& p : paths) {
    if (!isKeypointClip(p)) {
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
  return rest;
}

// Opens the first video among `paths` and reads the keyframe files given with it into it
// (a keyframe file alone goes to the video open, or to the video it names beside it);
// returns the other paths. A video or keyframe file that cannot be read is a failed open.
std::vector<std::filesystem::path> openVideos(AppState& s, std::vector<std::filesystem::path> paths,
                                              std::vector<std::string>& refused, bool& opened) {
  std::vector<std::filesystem::path> rest, keyframeFiles;
  opened = false;
  for (auto& p : paths) {
    if (isKeyframeFile(p)) {
      keyframeFiles.push_back(std::move(p));
    } else if (!isVideoFile(p)) {
      rest.push_back(std::move(p));
    } else if (opened) {
      refused.push_back(p.string() + ": one video at a time");
    } else {
      opened = true;
      try {
        openVideo(s, p);
      } catch (const std::exception& e) {
        ++s.jobs.failures;
        reportOpenError(s, {p}, e.what());
        opened = false;
        return rest;
      }
    }
  }
  // A video alone goes to the detector; with its keyframes, it is for marking and tracking.
  if (opened && keyframeFiles.empty() && s.view.detectWhenVideoOpens) {
    try {
      startDetection(s);
    } catch (const std::exception& e) {
      // The video is open all the same: its joints can be marked and tracked.
      const bool noModels = s.video && !s.video->detectError.empty();
      reportNote(s, noModels ? "Detecting people needs the pose models" : "Detection did not start", e.what(),
                 noModels ? "Pose models missing" : "");
    }
  }
  for (const auto& k : keyframeFiles) {
    try {
      // The video the file names, beside it, unless that one is open (the video opened with
      // the file, or the one the user marks).
      const Keyframes named = readKeyframes(k);
      const auto beside = k.parent_path() / named.video;
      const bool besideExists = !named.video.empty() && std::filesystem::exists(beside);
      if (!s.video && !besideExists)
        throw std::invalid_argument(k.string() + ": open the video the keyframes were marked on first");
      if (!s.video || (!opened && besideExists && s.video->path.filename() != named.video))
        openVideo(s, beside);
      loadKeyframes(s, k);
    } catch (const std::exception& e) {
      ++s.jobs.failures;
      reportOpenError(s, {k}, e.what());
    }
  }
  return rest;
}

}  // namespace

std::shared_ptr<const EigenwalkerModel> modelForTracking(AppState& s) { return clipModel(s).model; }

std::string describePaths(const std::vector<std::filesystem::path>& paths) {
  if (paths.empty()) return "the synthetic default population";
  std::vector<std::string> names;
  for (const auto& p : paths) {
    const auto name = p.filename().empty() ? p.parent_path().filename() : p.filename();
    names.push_back(name.empty() ? p.string() : name.string());
  }
  return listForMessage(names, 3);
}

void reportError(AppState& s, const std::string& title, const std::string& detail) {
  s.jobs.lastError = detail.empty() ? title : title + ": " + detail;
  s.log.error(s.jobs.lastError);
  OpenNotice n;
  n.title = title;
  n.detail = detail;
  n.fullText = s.jobs.lastError;
  n.kept = keptDescription(s);
  showNotice(s, std::move(n));
}

void reportNote(AppState& s, const std::string& title, const std::string& detail, const std::string& shortTitle) {
  s.log.warning(detail.empty() ? title : title + ": " + detail);
  OpenNotice n;
  n.error = false;
  n.title = title;
  n.shortTitle = shortTitle;
  n.detail = n.fullText = detail;
  showNotice(s, std::move(n));
}

void reportOpenError(AppState& s, const std::vector<std::filesystem::path>& paths,
                     const std::string& message) {
  reportError(s, "Could not open " + describePaths(paths), message);
  s.jobs.notice->detail = shortenPaths(message, paths);
  s.jobs.notice->retryPaths = paths;
  s.jobs.notice->canRetry = true;
}

void dismissNotice(AppState& s) {
  s.jobs.notice.reset();
  s.jobs.lastError.clear();
}

void open(AppState& s, std::vector<std::filesystem::path> paths) {
  OpenRequest request;
  const bool onlyModels =
      !paths.empty() &&
      std::all_of(paths.begin(), paths.end(), [](const auto& p) { return isModelFile(p); });
  request.paths = openModelFiles(s, std::move(paths));
  const bool hadPaths = !request.paths.empty();
  bool videoOpened = false;
  request.paths = openVideos(s, std::move(request.paths), request.refused, videoOpened);
  request.paths = openClips(s, std::move(request.paths), request.refused, videoOpened);
  for (const auto& r : request.refused) s.log.warning("skipped: " + r);
  if (hadPaths && request.paths.empty()) {
    // Only a clip or a video: the synthetic walkers load too when nothing is, for the other modes.
    if (!s.doc.population && !s.jobs.busy()) requestOpen(s, OpenRequest{});
    return;
  }
  if (onlyModels) {
    // A model alone, with nothing to inspect yet: the synthetic walkers, against it.
    if (s.doc.walkerCount() > 0 || s.jobs.busy() || s.doc.modelSource != ModelSource::File) return;
    request.keepModel = true;
  }
  requestOpen(s, std::move(request));
}

void pollJobs(AppState& s) {
  if (auto outcome = s.jobs.load.poll()) {
    bool taken = false;
    if (outcome->value) {
      try {
        takeLoaded(s, *outcome->value);
        taken = true;
      } catch (const std::exception& e) {
        outcome->error = std::string("no model to inspect it against: ") + e.what();
      }
    }
    if (!taken) {
      ++s.jobs.failures;
      std::string why = outcome->error;
      for (const auto& r : s.jobs.loading.refused) why += "\nalso skipped: " + r;
      reportOpenError(s, s.jobs.loading.paths, why);
      const auto& named =
          s.jobs.loading.named.empty() ? s.jobs.loading.paths : s.jobs.loading.named;
      s.jobs.notice->detail = shortenPaths(why, named);
    }
  }
  if (auto outcome = s.jobs.models.poll()) {
    if (outcome->value) {
      s.doc.models = *outcome->value;
      s.jobs.beforeLoad.reset();
      for (auto it = s.doc.sourcePaths.rbegin(); it != s.doc.sourcePaths.rend(); ++it) {
        std::erase(s.recentPaths, *it);
        s.recentPaths.insert(s.recentPaths.begin(), *it);
      }
      if (s.recentPaths.size() > 10) s.recentPaths.resize(10);
      s.log.info("Built " + std::to_string(s.doc.models->withoutSubject.size()) +
                 " leave-one-out models and the full model (" +
                 std::to_string(s.doc.models->all.walkerCount()) + " walkers)");
    } else {
      ++s.jobs.failures;
      // The new data cannot be shown without its models: back to what was shown before.
      const std::string what = s.doc.population ? s.doc.population->label : std::string("the data");
      restoreData(s, s.jobs.beforeLoad ? std::move(*s.jobs.beforeLoad) : LoadedData{});
      s.jobs.beforeLoad.reset();
      reportError(s, "Could not build the models for " + what, outcome->error);
      s.jobs.notice->retryPaths = s.jobs.loading.paths;
      s.jobs.notice->canRetry = true;
    }
  }
  const auto shownFit = s.clip();
  if (auto done = s.jobs.clip.poll()) {
    if (done->ok()) {
      takeClip(s, shownFit, done->value);
    } else {
      clipFailed(s, done->key, done->error);
    }
  }
  pollVideo(s);
  try {
    startClipFit(s);
  } catch (const std::exception& e) {
    s.jobs.clip.fail(*s.doc.clip, e.what());
    clipFailed(s, *s.doc.clip, e.what());
  }
  if (auto done = s.jobs.summary.poll(); done && !done->ok())
    s.log.error("Data summary failed: " + done->error);
  if (auto done = s.jobs.analysis.poll()) {
    if (done->ok()) {
      const auto& result = done->value;
      s.log.info("Analysis: " + std::to_string(result->subjects.size()) + " held-out subjects × " +
                 std::to_string(result->anglesDeg.size()) + " view angles in " +
                 std::to_string(static_cast<int>(result->seconds * 1000.0)) + " ms");
    } else {
      s.log.error("Analysis failed: " + done->error);
    }
  }
  if (s.jobs.pendingOpen && !s.jobs.load.running() && !s.jobs.models.running()) {
    auto request = std::move(*s.jobs.pendingOpen);
    s.jobs.pendingOpen.reset();
    startLoad(s, std::move(request));
  }
}

// [SECTION] Document edits

namespace {

void requireLoaded(const AppState& s) {
  if (s.doc.walkerCount() == 0) throw std::invalid_argument("no data loaded");
}

}  // namespace

void selectWalker(AppState& s, int index) {
  requireLoaded(s);
  if (index < 0 || index >= s.doc.walkerCount())
    throw std::invalid_argument("walker index " + std::to_string(index) + " out of range");
  if (s.doc.walker != index) s.doc.editedSd.clear();
  s.doc.walker = index;
  // A walker picked while a keypoint clip is shown: show that walker (the clip stays open).
  if (s.doc.mode == Mode::Clip) s.doc.mode = Mode::Reconstruct;
}

void selectSubject(AppState& s, const std::string& subjectOrId) {
  requireLoaded(s);
  int i = s.doc.population ? s.doc.population->findWalker(subjectOrId) : -1;
  if (i < 0 && s.doc.inspected) {
    const int j = s.doc.inspected->findWalker(subjectOrId);
    if (j >= 0) i = s.doc.populationCount() + j;
  }
  if (i < 0) throw std::invalid_argument("no subject or walker \"" + subjectOrId + "\"");
  selectWalker(s, i);
  s.panels.subjects.scrollToSelection = true;  // bring it into the list's view
}

void setMode(AppState& s, Mode mode) { s.doc.mode = mode; }

void setAngle(AppState& s, double alphaDeg) {
  if (!std::isfinite(alphaDeg) || alphaDeg < -180.0 || alphaDeg > 180.0)
    throw std::invalid_argument("view angle must lie in [-180, 180] degrees");
  if (s.doc.recon.alphaDeg != alphaDeg) s.doc.editedSd.clear();
  s.doc.recon.alphaDeg = alphaDeg;
}

void setEstimator(AppState& s, Estimator estimator) {
  if (s.doc.recon.estimator != estimator) s.doc.editedSd.clear();
  s.doc.recon.estimator = estimator;
}

void setEngine(AppState& s, EngineKind engine) {
  if (s.doc.recon.engine != engine) s.doc.editedSd.clear();
  s.doc.recon.engine = engine;
}

void setCompareEngines(AppState& s, bool on) {
  s.doc.compareEngines = on;
  if (on) s.doc.mode = Mode::Reconstruct;
}

void setCompareShown(AppState& s, EngineKind engine, bool shown) {
  s.doc.compareShown[static_cast<std::size_t>(engine)] = shown;
}

void setSigma2(AppState& s, double sigma2Mm2) {
  if (!std::isfinite(sigma2Mm2) || sigma2Mm2 <= 0.0)
    throw std::invalid_argument("sigma2 must be a positive number of mm^2");
  s.doc.sigma2Chosen = true;
  if (s.doc.recon.sigma2Mm2 != sigma2Mm2) s.doc.editedSd.clear();
  s.doc.recon.sigma2Mm2 = sigma2Mm2;
}

void followModelSigma2(AppState& s) {
  const EigenwalkerModel* held = s.doc.heldModel();
  if (s.doc.sigma2Chosen || held == nullptr) return;
  const double optimum = defaultSigma2Mm2(*held);
  if (s.doc.recon.sigma2Mm2 != optimum) s.doc.editedSd.clear();
  s.doc.recon.sigma2Mm2 = optimum;
}

void setComponents(AppState& s, int components) {
  if (components < 0) throw std::invalid_argument("components must be >= 0 (0 = auto)");
  if (const EigenwalkerModel* held = s.doc.heldModel()) {
    const int maxN = held->componentCount();
    if (components > maxN)
      throw std::invalid_argument("components must be at most " + std::to_string(maxN));
  }
  if (s.doc.recon.components != components) s.doc.editedSd.clear();
  s.doc.recon.components = components;
}

void setUnknownAngle(AppState& s, bool unknown) {
  if (s.doc.recon.unknownAngle != unknown) s.doc.editedSd.clear();
  s.doc.recon.unknownAngle = unknown;
}

int coefficientCount(const AppState& s) {
  if (s.doc.mode == Mode::Explore) {
    const auto* e = s.derived.explore();
    return e ? e->components : 0;
  }
  const auto* r = s.derived.recon();
  return r ? r->components : 0;
}

void setCoefficient(AppState& s, int index, double sd) {
  requireLoaded(s);
  const int n = coefficientCount(s);
  if (index < 0 || index >= n)
    throw std::invalid_argument("coefficient " + std::to_string(index + 1) + " out of range 1…" +
                                std::to_string(n));
  if (!std::isfinite(sd)) throw std::invalid_argument("coefficient value must be a number");
  sd = std::clamp(sd, -3.0, 3.0);
  if (s.doc.mode == Mode::Explore) {
    s.doc.exploreSd.resize(static_cast<std::size_t>(n), 0.0);
    s.doc.exploreSd[static_cast<std::size_t>(index)] = sd;
  } else {
    const auto* d = s.derived.display();
    if (!d) throw std::invalid_argument("no reconstruction yet");
    if (static_cast<int>(s.doc.editedSd.size()) != n)
      s.doc.editedSd.assign(d->kSd.data(), d->kSd.data() + d->kSd.size());
    s.doc.editedSd[static_cast<std::size_t>(index)] = sd;
  }
}

void resetCoefficients(AppState& s) {
  if (s.doc.mode == Mode::Explore) {
    s.doc.exploreSd.assign(s.doc.exploreSd.size(), 0.0);
    s.doc.exploreOmegaOffsetRadS = 0.0;
  } else {
    s.doc.editedSd.clear();
  }
}

void randomiseCoefficients(AppState& s, unsigned seed) {
  const int n = coefficientCount(s);
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  s.doc.exploreSd.resize(static_cast<std::size_t>(n));
  for (auto& v : s.doc.exploreSd) v = std::clamp(normal(rng), -3.0, 3.0);
  s.doc.exploreOmegaOffsetRadS = 0.0;
}

void coefficientsFromWalker(AppState& s) {
  requireLoaded(s);
  const EigenwalkerModel* held = s.doc.heldModel();
  const Walker* walker = s.doc.selectedWalker();
  if (!held || !walker) throw std::invalid_argument("models not built yet");
  const auto* e = s.derived.explore();
  const int n = e ? e->components : 0;
  const EigenwalkerModel m = truncateModel(*held, n);
  const Eigen::VectorXd k = projectOntoModel(m, walker->fit.w);
  s.doc.exploreSd.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    s.doc.exploreSd[static_cast<std::size_t>(i)] =
        std::clamp(k(i) / std::max(std::sqrt(m.eigenvalues(i)), 1e-12), -3.0, 3.0);
  s.doc.exploreOmegaOffsetRadS = held->omegasRadS.size() > 0 ? walker->fit.omegaRadS - held->omegasRadS.mean() : 0.0;
}

ExploreState exploreState(const AppState& s) { return {s.doc.exploreSd, s.doc.exploreOmegaOffsetRadS}; }

void moveAlongAxis(AppState& s, const std::string& attribute, const ExploreState& from, double delta) {
  const auto* e = s.derived.explore();
  const auto* axes = s.derived.semantic();
  const SemanticAxisView* a = axes ? axes->find(attribute) : nullptr;
  if (!e || !a) throw std::invalid_argument("no semantic axis '" + attribute + "' (explore mode, population loaded)");
  if (!std::isfinite(delta)) throw std::invalid_argument("the attribute's value must be a number");
  const int n = e->components;
  s.doc.exploreSd = from.sd;
  s.doc.exploreSd.resize(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n && i < a->axis.directionK.size(); ++i)
    s.doc.exploreSd[static_cast<std::size_t>(i)] =
        std::clamp(s.doc.exploreSd[static_cast<std::size_t>(i)] + a->axis.directionK(i) * delta / std::max(e->sd(i), 1e-12), -3.0, 3.0);
  s.doc.exploreOmegaOffsetRadS = from.omegaOffsetRadS + a->axis.directionOmega * delta;
}

double semanticReading(const AppState& s, const std::string& attribute) {
  const auto* e = s.derived.explore();
  const auto* axes = s.derived.semantic();
  const SemanticAxisView* a = axes ? axes->find(attribute) : nullptr;
  if (!e || !a) throw std::invalid_argument("no semantic axis '" + attribute + "' (explore mode, population loaded)");
  return predictAttribute(a->axis, e->k, 2.0 * std::numbers::pi * e->strideHz);
}

void setSemanticValue(AppState& s, const std::string& attribute, double value) {
  moveAlongAxis(s, attribute, exploreState(s), value - semanticReading(s, attribute));
}

// [SECTION] View state

void setPhase(AppState& s, double phase01) {
  if (!std::isfinite(phase01) || phase01 < 0.0 || phase01 > 1.0)
    throw std::invalid_argument("phase must lie in [0, 1]");
  s.view.playback.setPhase(phase01);
}

void setPlaying(AppState& s, bool playing) { s.view.playback.playing = playing; }

std::vector<std::string> overlayNames() {
  return {"depth_error", "error_lines",  "error_bars",   "metrics", "ghost",       "camera",
          "grid",        "reprojection", "stick_figure", "trails",  "point_lights"};
}

namespace {

// The flag of overlay `name`, or nullptr.
template <class O>
auto overlayFlag(O& o, const std::string& name) -> decltype(&o.trails) {
  return name == "depth_error"    ? &o.depthErrorColour
         : name == "error_lines"  ? &o.errorLines
         : name == "error_bars"   ? &o.errorBars
         : name == "metrics"      ? &o.metrics
         : name == "ghost"        ? &o.ghost
         : name == "camera"       ? &o.cameraGlyph
         : name == "grid"         ? &o.grid
         : name == "reprojection" ? &o.reprojection
         : name == "stick_figure" ? &o.stickFigure
         : name == "trails"       ? &o.trails
         : name == "point_lights" ? &o.pointLights
                                  : nullptr;
}

[[noreturn]] void unknownOverlay(const std::string& name) {
  std::string known;
  for (const auto& n : overlayNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown overlay \"" + name + "\" (known: " + known + ")");
}

}  // namespace

bool overlay(const AppState& s, const std::string& name) {
  const bool* flag = overlayFlag(s.view.overlays, name);
  if (!flag) unknownOverlay(name);
  return *flag;
}

void setOverlay(AppState& s, const std::string& name, bool on) {
  auto& o = s.view.overlays;
  bool* target = overlayFlag(o, name);
  if (!target) unknownOverlay(name);
  *target = on;
}

void setCamera(AppState& s, const std::string& preset) {
  if (preset == "three_quarter") {
    s.view.camera = OrbitCamera::preset(CameraPreset::ThreeQuarter);
  } else if (preset == "front") {
    s.view.camera = OrbitCamera::preset(CameraPreset::Front);
  } else if (preset == "side") {
    s.view.camera = OrbitCamera::preset(CameraPreset::Side);
  } else if (preset == "top") {
    s.view.camera = OrbitCamera::preset(CameraPreset::Top);
  } else {
    throw std::invalid_argument("unknown camera \"" + preset +
                                "\" (known: three_quarter, front, side, top)");
  }
}

// [SECTION] Export

void requestPng(AppState& s, std::filesystem::path path, CaptureView view) {
  if (path.empty()) throw std::invalid_argument("no file name for the PNG");
  s.exports.png = PngRequest{std::move(path), view, 2};
}

CaptureView captureViewFromName(const std::string& name) {
  if (name == "window") return CaptureView::Window;
  if (name == "input") return CaptureView::Input;
  if (name == "reconstruction") return CaptureView::Reconstruction;
  throw std::invalid_argument("unknown view \"" + name +
                              "\" (known: window, input, reconstruction)");
}

void startVideoExport(AppState& s, const VideoSettings& settings) {
  requireLoaded(s);
  if (s.exports.video) throw std::invalid_argument("a video export is already running");
  if (s.doc.mode == Mode::Reconstruct ? !s.derived.display() : !s.derived.explore())
    throw std::invalid_argument("nothing to export yet");
  s.exports.video = std::make_unique<VideoExport>(settings, playbackStrideHz(s));
  s.log.info("Exporting " + std::to_string(s.exports.video->frameCount()) + " frames to " +
             settings.path.string());
}

void cancelVideoExport(AppState& s) {
  if (!s.exports.video) return;
  s.log.warning("Video export cancelled: " + s.exports.video->settings().path.string());
  s.exports.video.reset();
}

void reportExportError(AppState& s, const std::string& message) {
  ++s.exports.failures;
  s.exports.lastError = message;
  s.log.error(message);
}

void exportCsv(AppState& s, const std::filesystem::path& path, std::optional<double> cycles) {
  requireLoaded(s);
  const WalkerMotion m = displayedWalkerMotion(s, cycles);
  writeJointCsv(path, m.framesX45, m.rateHz,
                {"eigenwalker viewer: " + m.description, "cycles=" + std::to_string(m.cycles)});
  s.log.info("Wrote " + path.string() + " (" + std::to_string(m.framesX45.rows()) + " frames, " +
             m.description + ")");
}

void exportBvh(AppState& s, const std::filesystem::path& path, std::optional<double> cycles) {
  requireLoaded(s);
  const WalkerMotion m = displayedWalkerMotion(s, cycles);
  writeBvh(path, m.framesX45, m.rateHz);
  s.log.info("Wrote " + path.string() + " (" + std::to_string(m.framesX45.rows()) + " frames, " +
             m.description + ")");
}

void exportModel(AppState& s, const std::filesystem::path& path) {
  requireLoaded(s);
  const EigenwalkerModel* held = s.doc.heldModel();
  if (!held) throw std::invalid_argument("models not built yet");
  EigenwalkerModel model = *held;
  std::string what = "the model of every walker";
  if (s.doc.mode == Mode::Reconstruct) {
    WalkerModel used;
    try {
      used = modelForWalker(s.doc, s.doc.walker);
    } catch (const std::runtime_error& e) {
      throw std::invalid_argument(e.what());
    }
    model = std::move(used.model);
    what = used.member ? "the model without " + used.heldOutSubject : "the model held";
  }
  saveModel(model, path);
  s.log.info("Wrote " + path.string() + " (" + what + ", " + std::to_string(model.walkerCount()) +
             " walkers)");
}

void exportState(AppState& s, const std::filesystem::path& path) {
  if (path.empty()) throw std::invalid_argument("no file name for the state");
  const std::string text = stateJson(s).dump(2) + "\n";
  writeFileAtomically(path, [&text](std::ostream& out) { out << text; });
  s.log.info("Wrote " + path.string() + " (viewer state)");
}

// [SECTION] Analysis

namespace {

AnalysisWalkers analysisWalkers(const AppState& s) {
  if (const EigenwalkerModel* model = heldModelOtherThanThePopulations(s.doc))
    return modelAnalysisWalkers(*model, heldModelPhrase(s.doc));
  if (!s.doc.population) throw std::invalid_argument("the analysis needs a loaded population or a model");
  return populationAnalysisWalkers(*s.doc.population);
}

}  // namespace

AnalysisKey analysisKey(const AppState& s) {
  return {s.doc.generation, s.doc.recon.components, s.doc.recon.sigma2Mm2,
          s.panels.analysis.showEngines || s.doc.compareEngines, heldModelOtherThanThePopulations(s.doc)};
}

std::string analysisSubject(const AppState& s) {
  const Walker* w = s.doc.selectedWalker();
  if (!w) return "";
  if (const EigenwalkerModel* model = heldModelOtherThanThePopulations(s.doc)) return subjectInModel(*model, *w);
  return s.doc.isInspected(s.doc.walker) ? std::string() : w->subject;
}

void requestAnalysis(AppState& s) {
  if ((!s.doc.population && !heldModelOtherThanThePopulations(s.doc)) || s.jobs.load.running() || s.jobs.analysis.running()) return;
  const AnalysisKey key = analysisKey(s);
  s.jobs.analysis.request(
      key, "Analysis (leave-one-subject-out, −90…90°)",
      [walkers = analysisWalkers(s), key](JobProgress& progress) -> std::shared_ptr<const AnalysisResult> {
        return std::make_shared<const AnalysisResult>(computeAnalysis(
            walkers, key, [&progress](int done, int total, const std::string& what) {
              progress.set(done, total, what);
            }));
      });
}

std::shared_ptr<const AnalysisResult> analysisNow(AppState& s) {
  const AnalysisKey key = analysisKey(s);
  if (auto cached = s.jobs.analysis.find(key)) return cached;
  auto result = std::make_shared<const AnalysisResult>(computeAnalysis(analysisWalkers(s), key, {}));
  s.jobs.analysis.put(key, result);
  return result;
}

void exportAnalysisCsv(AppState& s, const std::filesystem::path& path) {
  const auto result = analysisNow(s);
  // A walker that is none of the analysed subjects has no curve of its own: the mean is written.
  const std::string subject = analysisSubject(s);
  writeAnalysisCsv(*result, subject, path);
  s.log.info("Wrote " + path.string() + " (analysis curves, " +
             (subject.empty() ? std::string("the mean") : subject + " and the mean") + ")");
}

void setAnalysisMetric(AppState& s, const std::string& name) {
  if (name == "E_a") {
    s.panels.analysis.metric = ErrorMetric::AbsMm2;
  } else if (name == "E_r") {
    s.panels.analysis.metric = ErrorMetric::Relative;
  } else if (name == "MPJPE") {
    s.panels.analysis.metric = ErrorMetric::MpjpeMm;
  } else {
    throw std::invalid_argument("metric must be \"E_a\", \"E_r\" or \"MPJPE\"");
  }
}

// [SECTION] Gait report

namespace {

// The reconstruction's frames carried forward at its own measured speed: what OpenSim shows
// walking over the floor.
Eigen::MatrixXd walkedOverTheFloor(const GaitSummary& g) {
  Eigen::MatrixXd frames = g.framesMm;
  const double speed = g.measures && std::isfinite(g.measures->speedMps) ? g.measures->speedMps : 0.0;
  for (Eigen::Index f = 0; f < frames.rows(); ++f)
    for (int j = 0; j < kJointCount; ++j) frames(f, 3 * j + 1) += speed * 1000.0 * static_cast<double>(f) / kReportRateHz;
  return frames;
}

}  // namespace

namespace {

// What the gait report's JSON says it measured: the walker (or clip) and how it was made.
GaitReportText gaitReportSubject(const AppState& s) {
  if (s.doc.mode == Mode::Explore) return {"explore", "synthesised"};
  if (s.doc.mode == Mode::Clip)
    return {s.clip() ? s.clip()->settings.path.filename().string() : std::string(),
            "eigenwalker through the estimated camera"};
  const Walker* w = s.doc.selectedWalker();
  return {w ? w->id : std::string(), engineName(s.doc.recon.engine)};
}

}  // namespace

void exportGaitReport(AppState& s, const std::filesystem::path& path) {
  GaitPanel& p = s.panels.gait;
  s.derived.update(s.doc);  // a script may have changed the document since the last frame
  p.update(s);
  const GaitSummary& recon = p.recon();
  if (!recon.measures) throw std::invalid_argument("no measured walker to export (" + recon.error + ")");
  const std::string ext = path.extension().string();
  const GaitBand empty;
  const GaitBand& band = p.band ? *p.band : empty;
  if (ext == ".csv") {
    writeGaitReportCsv(path.string(), p.mocap, p.exportColumns(), band);
  } else if (ext == ".json") {
    writeGaitReportJson(path.string(), gaitReportSubject(s), p.mocap, p.exportColumns(), band);
  } else if (ext == ".trc") {
    const Eigen::MatrixXd frames = walkedOverTheFloor(recon);
    writeTrc(path, frames, kReportRateHz);
    std::filesystem::path mot = path;
    mot.replace_extension(".mot");
    writeJointAngles(mot.string(), jointAngles(frames, Eigen::Vector3d::UnitZ(), path.string()), kReportRateHz,
                     {"gait report: the reconstruction's joint angles (eigenwalker)"});
  } else {
    throw std::invalid_argument("gait report: export to .csv, .json or .trc (with its .mot), not '" + ext + "'");
  }
  p.status = "wrote " + path.filename().string() + (ext == ".trc" ? " and its .mot" : "");
  s.log.info("Wrote " + path.string() + " (gait report)");
}

// [SECTION] Opening data

void drop(AppState& s, const std::vector<std::filesystem::path>& paths) {
  if (paths.empty()) throw std::invalid_argument("nothing dropped");
  OpenRequest request;
  request.named = paths;
  for (const auto& p : paths) {
    std::error_code ec;
    if (!std::filesystem::exists(p, ec)) {
      request.refused.push_back(p.string() + ": no such file or folder");
    } else if (!std::filesystem::is_directory(p, ec) && !isSupportedDataFile(p) &&
               !isModelFile(p) && !isKeypointClip(p) && !isVideoFile(p) && !isKeyframeFile(p)) {
      request.refused.push_back(p.string() +
                                ": not a motion-capture file (.c3d .bvh .asf .amc .trc .csv .tsv), a "
                                "pose estimator's keypoints (.json, MediaPipe / DeepLabCut .csv), a "
                                "video (.mp4 .avi .mov .mkv .webm .m4v .mpg), a keyframe file, a "
                                "model (.ewm) or a folder");
    } else {
      request.paths.push_back(p);
    }
  }
  // Nothing to open: the drop is refused as a whole, and nothing changes.
  if (request.paths.empty()) throw std::invalid_argument(listForMessage(request.refused, 3, "; "));
  s.log.info("Dropped " + std::to_string(paths.size()) + (paths.size() == 1 ? " item" : " items"));
  // A dropped model is held at once; the trials dropped with it are inspected against it.
  const bool onlyModels = std::all_of(request.paths.begin(), request.paths.end(),
                                      [](const auto& p) { return isModelFile(p); });
  request.paths = openModelFiles(s, std::move(request.paths));
  bool videoOpened = false;
  request.paths = openVideos(s, std::move(request.paths), request.refused, videoOpened);
  request.paths = openClips(s, std::move(request.paths), request.refused, videoOpened);
  if (onlyModels || request.paths.empty()) {
    for (const auto& r : request.refused) s.log.warning("skipped: " + r);
    return;
  }
  requestOpen(s, std::move(request));
}

void setFileOverride(AppState& s, const std::filesystem::path& file, const std::string& units,
                     double rateHz) {
  if (!std::isfinite(rateHz) || rateHz < 0.0 || rateHz > 10000.0)
    throw std::invalid_argument("rate must lie in [0, 10000] Hz (0 = the file's)");
  LoadOptions o;
  if (!units.empty()) {
    if (units != "cmu") (void)unitToMm(units, file.string());  // throws for an unknown unit
    o.unitsOverride = units;
  }
  if (rateHz > 0.0) o.rateHzOverride = rateHz;
  const std::string key = fileKey(file);
  // A joint mapping written for the file (writeJointMapping) stays.
  if (const auto it = s.doc.fileOverrides.find(key); it != s.doc.fileOverrides.end())
    o.mappingFile = it->second.mappingFile;
  if (!o.unitsOverride && !o.rateHzOverride && !o.mappingFile) {
    s.doc.fileOverrides.erase(key);
  } else {
    s.doc.fileOverrides[key] = o;
  }
}

void reloadWithOverrides(AppState& s) {
  if (s.doc.sourcePaths.empty())
    throw std::invalid_argument("the synthetic default has no files to override");
  open(s, s.doc.sourcePaths);
}

void writeJointMapping(AppState& s, const std::filesystem::path& file,
                       const std::filesystem::path& out, const JointMapping& mapping,
                       bool openNow) {
  if (file.empty()) throw std::invalid_argument("no file to map");
  if (out.empty()) throw std::invalid_argument("no file name for the mapping");
  writeJointMappingFile(out, mapping);
  s.doc.fileOverrides[fileKey(file)].mappingFile = out;
  s.log.info("Wrote " + out.string() + " (joint mapping of " + file.filename().string() + ")");
  if (openNow) open(s, {file});
}

void requestDataSummary(AppState& s) {
  if (!s.doc.population || s.jobs.load.running() || s.jobs.summary.running()) return;
  auto paths = s.doc.sourcePaths;
  auto overrides = s.doc.fileOverrides;
  const auto generation = s.doc.generation;
  s.jobs.summary.request(
      generation, "Summarising the data",
      [paths, overrides, generation](JobProgress& progress) -> std::shared_ptr<const DataSummary> {
        auto d =
            summarizeData(paths, overrides, [&progress](int done, int total, const std::string& w) {
              progress.set(done, total, w);
            });
        d.generation = generation;
        return std::make_shared<const DataSummary>(std::move(d));
      });
}

std::shared_ptr<const DataSummary> dataSummaryNow(AppState& s) {
  requireLoaded(s);
  if (auto kept = s.jobs.summary.find(s.doc.generation)) return kept;
  auto d = summarizeData(s.doc.sourcePaths, s.doc.fileOverrides);
  d.generation = s.doc.generation;
  auto summary = std::make_shared<const DataSummary>(std::move(d));
  s.jobs.summary.put(s.doc.generation, summary);
  return summary;
}

void exportDataSummary(AppState& s, const std::filesystem::path& path) {
  const auto d = dataSummaryNow(s);
  writeDataSummaryJson(*d, path);
  s.log.info("Wrote " + path.string() + " (" + std::to_string(d->rows.size()) + " trials)");
}

// [SECTION] Teaching

void setTheme(AppState& s, const std::string& name) { s.view.theme = themeFromName(name); }

void setPresentation(AppState& s, bool on) {
  if (s.view.presentation != on) s.log.info(on ? "Presentation mode (F5 or Esc to leave)" : "Presentation mode ended");
  s.view.presentation = on;
}

namespace {

void applyTourStep(AppState& s) {
  const auto& steps = tourSteps();
  const auto& step = steps[static_cast<std::size_t>(s.panels.tour.step)];
  const auto script =
      parseScript(nlohmann::json::parse(step.actionsJson), std::string("tour step ") + step.title);
  // A step's action the data cannot do (no semantic speed axis in a population that has no
  // steerable one) is a warning: the tour goes on with the rest of the step.
  for (const auto& a : script) {
    try {
      applyAction(s, a);
    } catch (const std::exception& e) {
      s.log.warning(std::string("tour step ") + step.title + ": " + a.name + ": " + e.what());
    }
  }
  s.log.info(std::string("Tour ") + std::to_string(s.panels.tour.step + 1) + "/" +
             std::to_string(steps.size()) + ": " + step.title);
}

}  // namespace

void tourStart(AppState& s) {
  requireLoaded(s);
  s.panels.tour.active = true;
  s.panels.tour.step = 0;
  applyTourStep(s);
}

void tourNext(AppState& s) {
  if (!s.panels.tour.active) throw std::invalid_argument("the tour has not started");
  if (s.panels.tour.step + 1 >= static_cast<int>(tourSteps().size())) {
    tourEnd(s);
    return;
  }
  ++s.panels.tour.step;
  applyTourStep(s);
}

void tourBack(AppState& s) {
  if (!s.panels.tour.active) throw std::invalid_argument("the tour has not started");
  if (s.panels.tour.step == 0) return;
  --s.panels.tour.step;
  applyTourStep(s);
}

void tourEnd(AppState& s) {
  if (s.panels.tour.active) s.log.info("Tour ended");
  s.panels.tour.active = false;
  s.panels.tour.step = 0;
  s.view.overlays.pointLights = false;
  s.panels.analysis.open = false;
}

void showPanel(AppState& s, const std::string& name, bool shown) {
  if (name == "export") {
    s.panels.exports.open = shown;
  } else if (name == "analysis") {
    s.panels.analysis.open = shown;
  } else if (name == "gait") {
    s.panels.gait.open = shown;
  } else if (name == "help") {
    s.panels.help.open = shown;
  } else if (name == "data") {
    s.panels.data.open = shown;
  } else if (name == "notice_details") {
    if (shown && !s.panels.notice.visible(s))
      throw std::invalid_argument("no notice to show the details of");
    s.panels.notice.detailsOpen = shown;
  } else if (name == "model") {
    s.panels.header.modelMenuOpen = shown;
  } else {
    throw std::invalid_argument("unknown panel \"" + name +
                                "\" (known: export, analysis, gait, help, data, notice_details, model)");
  }
}

double playbackStrideHz(const AppState& s) {
  if (s.doc.mode == Mode::Clip) return s.clip() ? s.clip()->rec.fit.strideHz : 0.9;
  if (s.doc.mode == Mode::Explore) {
    const auto* e = s.derived.explore();
    return e ? e->strideHz : 0.9;
  }
  const WalkerFacts* f = s.doc.selectedFacts();
  return f ? f->strideHz : 0.9;
}

// [SECTION] The model held

void setModelSource(AppState& s, const std::string& which) {
  if (which == "population") {
    if (!s.doc.population) throw std::invalid_argument("no population is loaded");
    s.doc.modelSource = ModelSource::Population;
  } else if (which == "default") {
    try {
      ensureDefaultModel(s);
    } catch (const std::exception& e) {
      throw std::invalid_argument(std::string("the default model cannot be read: ") + e.what());
    }
    s.doc.modelSource = ModelSource::Default;
  } else {
    // An opened model by file name or path; a path not opened yet is opened.
    const auto& files = s.doc.modelFiles;
    const auto it = std::find_if(files.begin(), files.end(), [&which](const auto& m) {
      return m->name == which || (!m->file.empty() && fileKey(m->file) == fileKey(which));
    });
    if (it == files.end()) {
      if (!isModelFile(which))
        throw std::invalid_argument("model must be \"population\", \"default\" or an .ewm file");
      try {
        holdModel(s, readModelFile(which));
      } catch (const std::exception& e) {
        throw std::invalid_argument(e.what());
      }
      return;
    }
    s.doc.modelSource = ModelSource::File;
    s.doc.modelFile = static_cast<int>(it - files.begin());
  }
  s.doc.editedSd.clear();
  ++s.doc.generation;
  s.log.info("Model: " + heldModelName(s.doc));
}

}  // namespace ew::ui::actions

namespace ew::ui::actions {

// [SECTION] Keypoint clips

namespace {

ClipSettings& clipSettings(AppState& s) {
  if (!s.doc.clip) throw std::invalid_argument("no keypoint clip is open");
  return *s.doc.clip;
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
  if (s.doc.clip && s.doc.clip->path == path) settings = *s.doc.clip;
  settings.video = videoBesideKeypoints(path);
  s.doc.clip = settings;
  s.doc.mode = Mode::Clip;
  s.jobs.clip.retry();
  s.log.info("Opening the keypoint clip " + path.string());
}

void setClipFocal(AppState& s, std::optional<double> focalPx) {
  if (focalPx && !isPlausibleFocalPx(*focalPx)) throw std::invalid_argument(focalLengthProblem(*focalPx));
  clipSettings(s).focalPx = focalPx;
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
  if (s.clip() && person >= static_cast<int>(s.clip()->rec.trial.people.size()))
    throw std::invalid_argument("person " + std::to_string(person) + " out of range (" +
                                std::to_string(s.clip()->rec.trial.people.size()) + " tracks)");
  clipSettings(s).person = person;
}

void setClipFrame(AppState& s, int frame) {
  if (s.doc.mode != Mode::Clip || !s.clip()) throw std::invalid_argument("no keypoint clip is shown");
  const ClipResult& c = *s.clip();
  if (frame < 1 || frame > c.rec.trial.frameCount)
    throw std::invalid_argument("frame must lie in [1, " + std::to_string(c.rec.trial.frameCount) + "]");
  // Half a frame in, so that the frame shown is this one however the time rounds.
  s.view.playback.cycles = (frame - 0.5) / c.rec.trial.rateHz * c.rec.fit.strideHz;
  s.view.playback.playing = false;
}

void closeClip(AppState& s) {
  s.doc.clip.reset();
  s.jobs.clip.reset();
  s.jobs.clip.clearFailure();
  if (s.doc.mode == Mode::Clip) s.doc.mode = Mode::Reconstruct;
}

}  // namespace ew::ui::actions
