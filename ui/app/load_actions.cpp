// Data loading: opening files and folders, the models built for them, the model held.
#include "ui/app/load_actions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/common/errors.h"
#include "core/eigenwalker/model.h"
#include "core/io/load_trial.h"
#include "ui/app/actions.h"
#include "ui/app/actions_internal.h"
#include "ui/app/held_model.h"
#include "ui/app/video_poll.h"

namespace ew::ui::actions {

// [SECTION] Loading

namespace {
void ensureDefaultModel(AppState& s);
}  // namespace

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

namespace {

void startLoad(AppState& s, OpenRequest request) {
  const auto paths = request.paths;
  auto completion = paths.empty() ? nullptr : completionModel(s);
  s.loading.request = std::move(request);
  const std::string title =
      paths.empty() ? "Synthesising the default population" : "Loading " + describePaths(paths);
  s.log.info(title);
  s.loading.population.start(title,
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
  if (s.loading.population.running() || s.loading.models.running()) {
    s.loading.pending = std::move(request);
    return;
  }
  startLoad(s, std::move(request));
}

void startModels(AppState& s) {
  auto population = s.doc.population;
  s.loading.models.start("Building leave-one-out models",
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
      ++s.notices.failures;
      reportOpenError(s, {p}, e.what());
    }
  }
  return rest;
}

// Whether walkers just loaded are inspected against the held model rather than becoming the
// population: always while a saved or default model is held; with the population's model,
// when they are too few for a leave-one-out population of their own.
bool inspectLoaded(const AppState& s, const Population& loaded) {
  if (s.loading.request.paths.empty()) return false;  // the synthetic default population
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
  for (const auto& w : s.loading.request.refused) s.log.warning("skipped: " + w);
  for (const auto& w : pop->warnings) s.log.warning(w);
  if (inspectLoaded(s, *pop)) {
    addInspected(s, *pop);
    noticeSkipped(s, s.loading.request, *pop);
    return;
  }
  // What was shown stays until the new models are built (a failed build puts it back).
  if (s.doc.population) s.loading.before = loadedData(s.doc);
  s.doc.population = pop;
  s.doc.models.reset();
  if (!s.loading.request.keepModel) s.doc.modelSource = ModelSource::Population;
  s.doc.sourcePaths = s.loading.request.paths;
  ++s.doc.generation;
  s.doc.walker = 0;
  s.doc.editedSd.clear();
  s.doc.exploreSd.clear();
  s.doc.exploreOmegaOffsetRadS = 0.0;
  s.log.info("Loaded " + pop->label + ": " + std::to_string(pop->walkerCount()) + " walkers");
  noticeSkipped(s, s.loading.request, *pop);
  startModels(s);
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
        ++s.notices.failures;
        reportOpenError(s, {p}, e.what());
        opened = false;
        return rest;
      }
    }
  }
  // A video alone goes to the detector; with its keyframes, it is for marking and tracking.
  if (opened && keyframeFiles.empty() && s.video.detectWhenOpens) {
    try {
      startDetection(s);
    } catch (const std::exception& e) {
      // The video is open all the same: its joints can be marked and tracked.
      const bool noModels = s.video.session && !s.video.session->detectError.empty();
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
      if (!s.video.session && !besideExists)
        throw std::invalid_argument(k.string() + ": open the video the keyframes were marked on first");
      if (!s.video.session ||
          (!opened && besideExists && s.video.session->path.filename() != named.video))
        openVideo(s, beside);
      loadKeyframes(s, k);
    } catch (const std::exception& e) {
      ++s.notices.failures;
      reportOpenError(s, {k}, e.what());
    }
  }
  return rest;
}

}  // namespace

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
    if (!s.doc.population && !s.jobsBusy()) requestOpen(s, OpenRequest{});
    return;
  }
  if (onlyModels) {
    // A model alone, with nothing to inspect yet: the synthetic walkers, against it.
    if (s.doc.walkerCount() > 0 || s.jobsBusy() || s.doc.modelSource != ModelSource::File) return;
    request.keepModel = true;
  }
  requestOpen(s, std::move(request));
}

void pollJobs(AppState& s) {
  if (auto outcome = s.loading.population.poll()) {
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
      ++s.notices.failures;
      std::string why = outcome->error;
      for (const auto& r : s.loading.request.refused) why += "\nalso skipped: " + r;
      reportOpenError(s, s.loading.request.paths, why);
      const auto& named =
          s.loading.request.named.empty() ? s.loading.request.paths : s.loading.request.named;
      s.notices.banner->detail = shortenPaths(why, named);
    }
  }
  if (auto outcome = s.loading.models.poll()) {
    if (outcome->value) {
      s.doc.models = *outcome->value;
      s.loading.before.reset();
      for (auto it = s.doc.sourcePaths.rbegin(); it != s.doc.sourcePaths.rend(); ++it) {
        std::erase(s.recentPaths, *it);
        s.recentPaths.insert(s.recentPaths.begin(), *it);
      }
      if (s.recentPaths.size() > 10) s.recentPaths.resize(10);
      s.log.info("Built " + std::to_string(s.doc.models->withoutSubject.size()) +
                 " leave-one-out models and the full model (" +
                 std::to_string(s.doc.models->all.walkerCount()) + " walkers)");
    } else {
      ++s.notices.failures;
      // The new data cannot be shown without its models: back to what was shown before.
      const std::string what = s.doc.population ? s.doc.population->label : std::string("the data");
      restoreData(s, s.loading.before ? std::move(*s.loading.before) : LoadedData{});
      s.loading.before.reset();
      reportError(s, "Could not build the models for " + what, outcome->error);
      s.notices.banner->retryPaths = s.loading.request.paths;
      s.notices.banner->canRetry = true;
    }
  }
  pollClipFit(s);
  pollVideo(s);  // may give the clip a new track to fit
  refitClip(s);
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
  if (s.loading.pending && !s.loading.population.running() && !s.loading.models.running()) {
    auto request = std::move(*s.loading.pending);
    s.loading.pending.reset();
    startLoad(s, std::move(request));
  }
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
               !isModelFile(p) && !isKeypointClip(p) && !isVideoFile(p) && !isKeyframeFile(p) &&
               !isCalibrationFile(p)) {
      request.refused.push_back(p.string() +
                                ": not a motion-capture file (.c3d .bvh .asf .amc .trc .csv .tsv), a "
                                "pose estimator's keypoints (.json, MediaPipe / DeepLabCut .csv), a "
                                "video (.mp4 .avi .mov .mkv .webm .m4v .mpg), a keyframe file, a "
                                "camera calibration (.toml), a model (.ewm) or a folder");
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
  if (!s.doc.population || s.loading.population.running() || s.jobs.summary.running()) return;
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
