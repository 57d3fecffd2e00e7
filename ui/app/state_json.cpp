#include "ui/app/state_json.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/walk_camera.h"
#include "core/common/json_number.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/held_model.h"
#include "ui/app/theme.h"

namespace ew::ui {

namespace {

nlohmann::json dataJson(const Document& d) {
  nlohmann::json data = {{"loaded", d.population != nullptr},
                         {"generation", d.generation},
                         {"models", d.models != nullptr}};
  nlohmann::json sources = nlohmann::json::array();
  for (const auto& p : d.sourcePaths) sources.push_back(p.string());
  data["sources"] = sources;
  if (d.population) {
    data["label"] = d.population->label;
    data["walkers"] = d.population->walkerCount();
    nlohmann::json subjects = nlohmann::json::array();
    for (const auto& w : d.population->walkers) subjects.push_back(w.subject);
    data["subjects"] = subjects;
  }
  return data;
}

nlohmann::json selectionJson(const Document& d) {
  nlohmann::json j = {{"index", d.walker}};
  if (const Walker* w = d.selectedWalker()) {
    j["inspected"] = d.isInspected(d.walker);
    j["id"] = w->id;
    j["subject"] = w->subject;
    j["files"] = w->files;
  }
  return j;
}

// The model held, and the walkers inspected against it.
nlohmann::json modelJson(const Document& d) {
  nlohmann::json j = {{"source", modelSourceName(d.modelSource)}, {"name", heldModelName(d)}};
  if (const EigenwalkerModel* m = d.heldModel()) {
    j["walkers"] = m->walkerCount();
    j["components"] = m->componentCount();
  }
  nlohmann::json files = nlohmann::json::array();
  for (const auto& f : d.modelFiles) files.push_back(f->file.string());
  j["files"] = files;
  nlohmann::json inspected = nlohmann::json::array();
  if (d.inspected)
    for (const auto& w : d.inspected->walkers) inspected.push_back(w.id);
  j["inspected"] = inspected;
  return j;
}

// What the reconstruction of the selected walker used and measured (the metrics strip).
nlohmann::json reconstructionJson(const Derived& derived) {
  const ReconBase* r = derived.recon();
  const ReconDisplay* d = derived.display();
  if (!r || !d) return nullptr;
  nlohmann::json j = {{"model", r->modelName},
                      {"in_model", r->inModel},
                      {"held_out", r->heldOutSubject},
                      {"model_walkers", r->modelWalkers},
                      {"components", r->components},
                      {"alpha_used_deg", r->alphaUsedDeg},
                      {"abs_error_mm2", d->absScoredMm2},
                      {"rel_error", d->relScored},
                      {"mpjpe_mm", d->mpjpeMm},
                      {"joints_scored", d->jointsScored},
                      {"residual_rms_mm", d->residualRmsMm},
                      {"engine", engineName(r->engine)}};
  if (r->snippets) {
    j["snippets"] = r->snippets->starts.size();
    j["snippet_angles_deg"] = r->snippets->freeAlphaDeg;
    j["snippet_reprojection_rms_mm"] = r->snippets->reprojectionRms;
    j["prior_walkers"] = r->priorWalkers;
    j["speed_mps"] = r->speedMps;
    j["speed_source"] = r->speedSource;
  }
  if (r->skeleton) {
    j["skeleton_frames"] = r->skeleton->framesMm.rows();
    j["skeleton_clamped_bone_frames"] = r->skeleton->clampedBoneFrames;
  }
  std::vector<double> perJoint(d->depthRmsMm.data(), d->depthRmsMm.data() + d->depthRmsMm.size());
  j["depth_rms_mm"] = perJoint;
  // Joints the marker set lacked, estimated from a model: their errors apart.
  nlohmann::json estimated = nlohmann::json::array();
  for (int i = 0; i < kJointCount; ++i)
    if (r->modelEstimated[static_cast<std::size_t>(i)]) estimated.push_back(kJointNames[i]);
  j["model_estimated"] = estimated;
  j["mpjpe_measured_mm"] = d->mpjpeMeasuredMm;
  j["mpjpe_model_estimated_mm"] = d->mpjpeModelEstimatedMm
                                      ? nlohmann::json(*d->mpjpeModelEstimatedMm)
                                      : nlohmann::json(nullptr);
  return j;
}

nlohmann::json optionalJson(const std::optional<double>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}
std::optional<double> finiteOr(double v) {
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

// The tracks (0-based) the clip's frame `frame` shows, the fitted one among them.
std::vector<int> peopleInFrame(const KeypointTrial& trial, int frame) {
  std::vector<int> out;
  for (std::size_t i = 0; i < trial.people.size(); ++i)
    if (personRowAt(trial.people[i], frame) >= 0) out.push_back(static_cast<int>(i));
  return out;
}

// "1920x1080", or null.
nlohmann::json imageSizeJson(const std::optional<KeypointImageSize>& size) {
  if (!size) return nullptr;
  return std::to_string(size->width) + "x" + std::to_string(size->height);
}

// The walker's 15 joints on a frame of the clip as fitted (u, v each, null where missing).
nlohmann::json frameJointsJson(const KeypointTrial& t, int frame) {
  nlohmann::json j = nlohmann::json::array();
  if (frame < 0 || frame >= t.jointsPx.rows()) return j;
  for (Eigen::Index c = 0; c < t.jointsPx.cols(); ++c)
    j.push_back(std::isfinite(t.jointsPx(frame, c)) ? nlohmann::json(t.jointsPx(frame, c)) : nlohmann::json(nullptr));
  return j;
}

// The keypoint clip: what the user chose, and the last fit (camera, walk, residuals).
nlohmann::json clipJson(const AppState& s) {
  if (!s.clip.settings) return nullptr;
  const ClipSettings& c = *s.clip.settings;
  nlohmann::json j = {{"path", c.path.string()},
                      {"layout_chosen", c.layout},
                      {"fps_chosen", c.fps},
                      {"person_chosen", c.person},
                      {"focal_px_fixed", optionalJson(c.focalPx)},
                      {"calibration", c.calibrationFile.empty() ? nlohmann::json(nullptr)
                                                                : nlohmann::json(c.calibrationFile.string())},
                      {"calibration_camera", c.calibrationCamera},
                      {"azimuth_deg_fixed", optionalJson(c.alphaDeg)},
                      {"elevation_deg_fixed", optionalJson(c.elevationDeg)},
                      {"image_size_given", imageSizeJson(c.imageSize)},
                      {"scene_horizon_row_px", optionalJson(c.horizonRowPx)},
                      {"scene_horizon_held", c.horizonRowPx && c.holdToHorizon},
                      {"fit_error", s.clip.fits.error()},
                      {"source", c.tracked ? "track" : c.detected ? "detections" : "file"},
                      {"corrections", c.corrections ? c.corrections->keyframes.size() : 0}};
  if (!s.clip.fit()) return j;
  const ClipResult& r = *s.clip.fit();
  const CameraFit& f = r.rec.fit;
  const bool pinhole = f.camera.model == CameraModel::Pinhole;
  const std::optional<double> sceneRow = r.settings.horizonRowPx;
  std::vector<double> residuals(r.rec.residualRmsPx.begin(), r.rec.residualRmsPx.end());
  for (double& v : residuals)
    if (!std::isfinite(v)) v = -1.0;  // JSON has no NaN: never seen
  j["fit"] = {
      {"current", r.settings == c},
      {"model", r.model.name},
      {"format", r.rec.trial.format},
      {"layout", r.rec.trial.layout->name},
      {"frames", r.rec.trial.frameCount},
      {"rate_hz", r.rec.trial.rateHz},
      {"rate_from", r.rec.trial.rateSource},
      {"image_size", imageSizeJson(r.rec.trial.imageSize)},
      {"image_size_from", r.rec.trial.imageSizeSource},
      {"people", r.rec.trial.people.size()},
      {"person", r.rec.trial.chosen},
      {"frame", clipFrameAt(r, s.view.playback.cycles) + 1},  // counted from 1, as the caption
      {"people_in_frame", peopleInFrame(r.rec.trial, clipFrameAt(r, s.view.playback.cycles))},
      {"frame_joints_px", frameJointsJson(r.rec.trial, clipFrameAt(r, s.view.playback.cycles))},
      {"corrections", r.settings.corrections ? r.settings.corrections->keyframes.size() : 0},
      {"alpha_deg", f.camera.alphaDeg},
      {"elevation_deg", f.camera.elevationDeg},
      {"focal_px", pinhole ? nlohmann::json(f.camera.focalPx) : nlohmann::json(nullptr)},
      {"distance_m",
       pinhole ? nlohmann::json(f.camera.distanceMm / 1000.0) : nlohmann::json(nullptr)},
      // The fitted camera's horizon (c_y − f tan ε) and its angle from the scene's, when read.
      {"horizon_row_px", pinhole ? nlohmann::json(horizonRowPx(f.camera)) : nlohmann::json(nullptr)},
      {"horizon_off_deg", pinhole && sceneRow ? nlohmann::json(horizonOffDeg(f.camera, *sceneRow)) : nlohmann::json(nullptr)},
      {"reprojection_rms_px", f.reprojectionRmsPx},
      {"outlier_samples", f.outlierSamples},
      {"residual_rms_px", residuals},
      {"head_height_m", f.headHeightMm / 1000.0},
      {"stature_m", f.statureMm / 1000.0},
      {"walking_in_place", f.inPlace},
      {"cautions", r.rec.cautions},
      {"speed_mps", f.speedMps},
      {"stride_hz", f.strideHz},
      {"stride_length_m", f.strideLengthM},
      // One SD of each (CameraFit::sd; null where the fit gives none).
      {"walker_distance_m", finiteOrNull(f.walkerDistanceM)},
      {"sd", {{"stature_m", finiteOrNull(f.sd.statureMm / 1000.0)}, {"speed_mps", finiteOrNull(f.sd.speedMps)},
              {"stride_length_m", finiteOrNull(f.sd.strideLengthM)}, {"alpha_deg", finiteOrNull(f.sd.alphaDeg)},
              {"elevation_deg", finiteOrNull(f.sd.elevationDeg)}, {"focal_px", finiteOrNull(f.sd.focalPx)},
              {"walker_distance_m", finiteOrNull(f.sd.walkerDistanceM)}}},
      // The heels and toes lifted from the image, drawn with the 3D walker.
      {"feet", {{"samples_seen", r.rec.feet.pointsSeen}, {"samples_lifted", r.rec.feet.pointsLifted},
                {"note", r.rec.feet.note}}},
      {"seconds", r.seconds}};
  return j;
}

// The video open: its frames, the keyframes marked and the last track.
nlohmann::json videoJson(const AppState& s) {
  if (!s.video.session) return nullptr;
  const VideoSession& v = *s.video.session;
  const VideoInfo& i = v.frames->info();
  nlohmann::json keyframes = nlohmann::json::array();
  for (const auto& k : v.keyframes.keyframes)
    keyframes.push_back(
        {{"frame", k.frame}, {"joints", k.jointsPx.array().isFinite().count() / 2}});
  nlohmann::json j = {{"path", v.path.string()},
                      {"width_px", i.widthPx},
                      {"height_px", i.heightPx},
                      {"fps", i.fps},
                      {"frames", v.frameCount()},
                      {"frame", v.frame},
                      {"shown_frame", actions::shownVideoFrame(s)},
                      {"zoom", v.zoom},
                      {"zoom_centre_px", {v.zoomCentrePx.x(), v.zoomCentrePx.y()}},
                      {"marking", v.marking},
                      {"mark_step", v.markStep},
                      {"keyframes", keyframes},
                      {"undo_steps", v.undo.size()},
                      {"redo_steps", v.redo.size()},
                      {"cache_bytes", v.frames->bytesHeld()},
                      {"track_error", v.trackError},
                      {"tracker", trackerName(v.tracker)},
                      {"flatten_background", v.flattenBackground},
                      {"hold_trunk", v.holdTheTrunk},
                      {"model_loop", v.modelLoopRounds}};
  j["detection"] = {{"running", s.video.detect.running()},
                    {"model", std::string(poseModelSizeName(s.video.detectorModel))},
                    {"error", v.detectError},
                    {"shows_fit", actions::showsDetectionFit(s)},
                    {"when_opened", s.video.detectWhenOpens}};
  if (v.detecting) j["detection"]["latest_frame"] = v.detecting->latestFrame();
  if (v.detected) {
    const DetectedVideo& d = *v.detected;
    j["detection"]["done"] = {{"model", std::string(poseModelSizeName(d.model))},
                              {"people", d.people},
                              {"frames", d.framesRead},
                              {"frames_with_people", d.framesWithPeople},
                              {"from_cache", d.fromCache},
                              {"seconds", d.seconds},
                              {"horizon_row_px", optionalJson(d.horizon.rowPx())},
                              {"horizon_why_none", d.horizon.whyNone}};
  }
  if (v.tracked) {
    const auto& t = *v.tracked;
    j["track"] = {{"tracker", trackerName(t.tracker)},
                  {"background", t.track.background},
                  {"trunk_held", t.holdTheTrunk},
                  {"first_frame", t.track.firstFrame},
                  {"last_frame", t.lastFrame()},
                  {"seconds", t.seconds},
                  {"ran_frames", {t.ranFirst, t.ranLast}},
                  {"mean_confidence", t.track.confidence.mean()},
                  {"keyframes", t.keyframes.keyframes.size()},
                  {"model_loop", t.modelLoopRounds},
                  {"model_loop_fits", t.loopRounds.size()},
                  {"model_loop_hidden_joint_frames",
                   t.loopRounds.empty() ? 0 : t.loopRounds.back().hiddenJointFrames},
                  {"model_loop_stopped", t.loopStopped},
                  {"horizon_row_px", optionalJson(t.horizon.rowPx())},
                  {"horizon_why_none", t.horizon.whyNone}};
    j["track"]["frame_to_mark_next"] = actions::nextFrameToMark(s);
    j["track"]["least_sure_frame"] = actions::leastSureTrackedFrame(s);
  }
  return j;
}

const char* modeName(Mode m) {
  return m == Mode::Reconstruct ? "reconstruct" : m == Mode::Explore ? "explore" : "clip";
}

const char* levelName(LogLevel level) {
  return level == LogLevel::Error ? "error" : level == LogLevel::Warning ? "warning" : "info";
}

// Compare mode: each engine's errors, or why it gave none; null when compare mode is off.
// Explore mode: each semantic axis's reading of the explorer's walker; reconstruct mode: the
// attributes predicted from the 2D view.
nlohmann::json semanticJson(const AppState& s) {
  nlohmann::json j = nlohmann::json::object();
  const auto finite = [](double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  };
  if (const auto* e = s.derived.explore()) j["explore_stride_hz"] = e->strideHz;
  if (const auto* axes = s.derived.semantic(); axes && s.doc.mode == Mode::Explore) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& a : axes->axes)
      list.push_back({{"attribute", a.axis.attribute},
                      {"reading", finite(actions::semanticReading(s, a.axis.attribute))},
                      {"sd", finite(a.axis.sd)},
                      {"gain", finite(a.axis.gain)},
                      {"loo_r2", finite(a.quality.r2)},
                      {"loo_accuracy", finite(a.quality.accuracy)}});
    j["axes"] = list;
    j["axes_from"] = axes->from;
  }
  nlohmann::json fromView = nlohmann::json::array();
  for (const auto& f : s.derived.attributesFromView())
    fromView.push_back({{"attribute", f.attribute},
                        {"from_2d", finite(f.from2d)},
                        {"from_3d", finite(f.from3d)},
                        {"truth", finite(f.truth)}});
  j["from_view"] = fromView;
  if (!fromView.empty()) j["from_view_learnt_from"] = s.derived.attributesFromViewAxes().from;
  return j;
}

nlohmann::json compareJson(const AppState& s) {
  const CompareResult* c = s.derived.compare();
  if (!s.doc.compareEngines || !c) return nullptr;
  nlohmann::json engines = nlohmann::json::array();
  for (const auto& e : c->engines) {
    nlohmann::json j = {{"engine", engineName(e.engine)},
                        {"shown", s.doc.compareShown[static_cast<std::size_t>(e.engine)]},
                        {"seconds", e.seconds},
                        {"error", e.error}};
    if (e.display && e.base) {
      j["mpjpe_mm"] = e.display->mpjpeMm;
      j["abs_error_mm2"] = e.display->absScoredMm2;
      j["rel_error"] = e.display->relScored;
      j["alpha_used_deg"] = e.base->alphaUsedDeg;
      j["residual_rms_mm"] = e.display->residualRmsMm;
    }
    engines.push_back(j);
  }
  return engines;
}

// The gait report as the panel last computed it (show_panel gait, or an export, computes it).
nlohmann::json gaitJson(const AppState& s) {
  const GaitPanel& p = s.panels.gait;
  nlohmann::json rows = nlohmann::json::object();
  nlohmann::json columns =
      nlohmann::json::object();  // each column's measures (compare mode: per engine)
  for (const auto& c : p.columns) {
    nlohmann::json m = nlohmann::json::object();
    for (const auto& row : gaitRows())
      m[row.key] = optionalJson(finiteOr(gaitRowValue(c.summary, row.key)));
    columns[c.name] = m;
  }
  for (size_t r = 0; r < gaitRows().size(); ++r) {
    const std::string key = gaitRows()[r].key;
    rows[key] = {
        {"motion_capture", optionalJson(finiteOr(gaitRowValue(p.mocap, key)))},
        {"reconstruction", optionalJson(finiteOr(gaitRowValue(p.recon(), key)))},
        {"population_mean", optionalJson(p.band ? finiteOr(p.band->rowMean[r]) : std::nullopt)},
        {"population_sd", optionalJson(p.band ? finiteOr(p.band->rowSd[r]) : std::nullopt)}};
  }
  return {{"open", p.open},     {"band_walkers", p.band ? p.band->walkers : 0},
          {"band", p.band ? p.band->from : std::string()},
          {"measures", rows},   {"reconstruction_error", p.recon().error},
          {"columns", columns}, {"status", p.status}};
}

nlohmann::json rectJson(const PanelRect& r) { return {r.pos.x, r.pos.y, r.size.x, r.size.y}; }

nlohmann::json overlaysJson(const FrameRecord& f) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, rect] : f.overlays) j[name] = rectJson(rect);
  return j;
}

nlohmann::json overflowJson(const FrameRecord& f) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [window, px] : f.overflow) j[window] = px;
  return j;
}

// What the last frame laid out ([x, y, width, height] in pixels) and drew.
nlohmann::json layoutJson(const FrameRecord& f) {
  const Layout& l = f.layout;
  return {{"presentation", l.presentation},
          {"drawer", l.drawer},
          {"drawn", f.drawn},
          {"input", rectJson(l.input)},
          {"reconstruction", rectJson(l.reconstruction)},
          {"playback", rectJson(l.playback)},
          {"presentation_bar", rectJson(l.presentationBar)},
          {"header", rectJson(l.header)},
          {"overlays", overlaysJson(f)},
          {"overflow", overflowJson(f)}};
}

// The classroom stage (ui/app/stage.h) and what its views draw this moment.
nlohmann::json stageJson(const AppState& s) {
  const StageFeature& st = s.stage;
  const BiologicalMotionOptions& d = st.display;
  nlohmann::json j{{"inverted", d.inverted},
                   {"scramble", scrambleName(d.scramble)},
                   {"mask_dots", d.maskDots},
                   {"dot_lifetime_s", d.dotLifetimeS},
                   {"backwards", d.backwards},
                   {"overground", d.translating},
                   {"depth_reversed", st.depthReversed},
                   {"turning", st.turning},
                   {"turn_deg_per_s", st.turnDegPerS},
                   {"turned_deg", st.turnedDeg},
                   {"elevation_deg", st.elevationDeg},
                   {"drawn", stageDrawsViews(s)},
                   {"description", stageDescription(st)}};
  if (const auto walker = stageWalker2d(s)) j["azimuth_deg"] = stageAzimuthDeg(s, walker->alphaDeg);
  return j;
}

nlohmann::json quizJson(const QuizFeature& q) {
  if (!q.staircase) return nlohmann::json();
  const Staircase& c = *q.staircase;
  const double threshold = c.thresholdDots();
  return {{"running", q.running()},
          {"done", c.done()},
          {"trials", c.trials().size()},
          {"reversals", c.reversalCount()},
          {"noise_dots", c.noiseDots()},
          {"threshold_dots", std::isfinite(threshold) ? nlohmann::json(threshold) : nlohmann::json()}};
}

}  // namespace

nlohmann::json stateJson(const AppState& s) {
  const Document& d = s.doc;
  const ViewState& v = s.view;
  nlohmann::json j;
  j["data"] = dataJson(d);
  j["walker"] = selectionJson(d);
  j["model"] = modelJson(d);
  j["reconstruction"] = reconstructionJson(s.derived);
  j["reconstruction_error"] = s.derived.error();
  j["mode"] = modeName(d.mode);
  j["clip"] = clipJson(s);
  j["video"] = videoJson(s);
  j["gait"] = gaitJson(s);
  j["compare"] = compareJson(s);
  j["semantic"] = semanticJson(s);
  j["angle_deg"] = d.recon.alphaDeg;
  j["method"] = d.recon.estimator == Estimator::Lsq ? "lsq" : "map";
  j["engine"] = engineName(d.recon.engine);
  j["sigma2_mm2"] = d.recon.sigma2Mm2;
  j["components"] = d.recon.components;
  j["unknown_angle"] = d.recon.unknownAngle;
  j["edited_sd"] = d.editedSd;
  j["explore_sd"] = d.exploreSd;
  j["view"] = {
      {"phase", v.playback.phase()},
      {"playing", v.playback.playing},
      {"speed", v.playback.speed},
      {"theme", themeName(v.theme)},
      {"ui_scale", v.uiScale},
      {"ui_scale_limit", v.uiScaleLimit > 0.0f ? nlohmann::json(v.uiScaleLimit) : nlohmann::json()},
      {"camera",
       {{"yaw_deg", v.camera.yawDeg},
        {"pitch_deg", v.camera.pitchDeg},
        {"distance_mm", v.camera.distanceMm}}},
      {"point_lights", v.overlays.pointLights},
      {"presentation", v.presentation},
      {"clip_zoom", s.clip.zoom}};
  j["layout"] = layoutJson(s.lastFrame);
  // Beside the last frame's layout: a record of the frames drawn, not of the session (tests that
  // compare two sessions' states leave "layout" out).
  j["layout"]["repainted_shares"] =
      std::vector<double>(s.repaintedShares.begin(), s.repaintedShares.end());
  j["undo"] = {{"steps", s.history.undoSteps()}, {"redo_steps", s.history.redoSteps()}};
  // The drawer layout (small window or large scale): the tab shown; null in the full layout.
  j["view"]["drawer"] = s.panels.drawer.inUse
                            ? nlohmann::json(drawerTabName(s.panels.drawer.active))
                            : nlohmann::json();
  // The guided tour: its step (0-based) and whether its text was folded last frame.
  j["tour"] = s.panels.tour.active ? nlohmann::json{{"step", s.panels.tour.step}, {"text_folded", s.panels.tour.folded}}
                                   : nlohmann::json();
  j["stage"] = stageJson(s);
  j["quiz"] = quizJson(s.quiz);
  j["audience"] = {{"open", s.audience.open},
                   {"shown", s.audience.shown},
                   {"size", {s.audience.widthPx, s.audience.heightPx}},
                   {"theme", audienceThemeName(s.audience.theme)},
                   {"views", audienceViewsName(s.audience.views)}};
  j["busy"] = s.busy();
  j["failures"] = s.notices.failures;
  j["error"] = s.notices.lastError;
  if (s.notices.banner) {
    const auto& n = *s.notices.banner;
    j["notice"] = {{"level", n.error ? "error" : "warning"},
                   {"title", n.title},
                   {"detail", n.detail},
                   {"kept", n.kept},
                   {"can_retry", n.canRetry}};
  } else {
    j["notice"] = nullptr;
  }
  nlohmann::json log = nlohmann::json::array();
  for (const auto& e : s.log.entries())
    log.push_back({{"level", levelName(e.level)}, {"text", e.text}});
  j["log"] = log;
  return j;
}

}  // namespace ew::ui
