#include "ui/app/script_actions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/script_args.h"
#include "ui/app/shortcuts.h"
#include "ui/app/undo.h"

namespace ew::ui {

void ScriptWaits::load(const AppState& s) {
  failuresBefore = s.notices.failures;
  checkLoad = true;
}

namespace {

using namespace script_args;
using W = ScriptWaits;
using A = ScriptAction;

// [SECTION] Actions with more to read than one value

void setMode(AppState& s, const A& a, W&) {
  const std::string m = text(a);
  if (m == "reconstruct") {
    actions::setMode(s, Mode::Reconstruct);
  } else if (m == "explore") {
    actions::setMode(s, Mode::Explore);
  } else if (m == "clip") {
    if (!s.clip.settings) throw std::invalid_argument("no keypoint clip is open");
    actions::setMode(s, Mode::Clip);
  } else {
    throw std::invalid_argument("mode must be \"reconstruct\", \"explore\" or \"clip\"");
  }
}

// {"zoom": Z, "centre": [x, y]} (image pixels, y down; Z 1 shows the whole picture, or the
// region a clip's walker crosses)
void zoom(AppState& s, const A& a, W&) {
  const auto& arg = a.argument;
  if (!arg.is_object() || !arg.contains("zoom") || !arg["zoom"].is_number() || !arg.contains("centre") ||
      !arg["centre"].is_array() || arg["centre"].size() != 2 || !arg["centre"][0].is_number() ||
      !arg["centre"][1].is_number())
    throw std::invalid_argument(R"(expects {"zoom": Z, "centre": [x, y]})");
  const Eigen::Vector2d centre(arg["centre"][0].get<double>(), arg["centre"][1].get<double>());
  if (a.name == "video_zoom")
    actions::setVideoZoom(s, arg["zoom"].get<double>(), centre);
  else
    actions::setClipZoom(s, arg["zoom"].get<double>(), centre);
}

// undo_keyframes, redo_keyframes, remove_keyframe: a detected video's corrections changed, and
// the script waits for the fit again.
void keyframesEdited(AppState& s, W& w) {
  w.failuresBefore = s.notices.failures;
  w.checkLoad = actions::correctsDetections(s) && !s.video.session->marking;
}

// The app's undo or redo (ui/app/undo.h); when it stepped a video's keyframes, the script waits
// for the fit they start as after `undo_keyframes`.
void undoOrRedo(AppState& s, W& w, void (*step)(AppState&)) {
  // An undo of the keyframes takes a step off their undo stack, a redo puts one back.
  const auto keyframeSteps = [&s] { return s.video.session ? s.video.session->undo.size() : 0; };
  const std::size_t before = keyframeSteps();
  step(s);
  if (keyframeSteps() != before) keyframesEdited(s, w);
}

// {"first": F, "last": L[, "tracker": "flow" | "appearance"][, "flatten_background": B]
//  [, "hold_trunk": B][, "model_loop": N]} (L -1: the end): tracked and fitted in the
// background; a track or fit that fails fails the script like a failed open.
void trackVideo(AppState& s, const A& a, W& w) {
  const auto& arg = a.argument;
  if (!arg.is_object() || !arg.contains("first") || !arg["first"].is_number_integer() ||
      !arg.contains("last") || !arg["last"].is_number_integer())
    throw std::invalid_argument(R"(expects {"first": F, "last": L})");
  actions::setTrackRange(s, arg["first"].get<int>(), arg["last"].get<int>());
  if (arg.contains("tracker")) {
    if (!arg["tracker"].is_string())
      throw std::invalid_argument(R"("tracker" is "flow" or "appearance")");
    actions::setTracker(s, trackerFromName(arg["tracker"].get<std::string>()));
  }
  if (arg.contains("flatten_background")) {
    if (!arg["flatten_background"].is_boolean())
      throw std::invalid_argument(R"("flatten_background" is true or false)");
    actions::setFlattenBackground(s, arg["flatten_background"].get<bool>());
  }
  if (arg.contains("hold_trunk")) {
    if (!arg["hold_trunk"].is_boolean())
      throw std::invalid_argument(R"("hold_trunk" is true or false)");
    actions::setHoldTheTrunk(s, arg["hold_trunk"].get<bool>());
  }
  if (arg.contains("model_loop")) {
    if (!arg["model_loop"].is_number_integer())
      throw std::invalid_argument(R"("model_loop" is a number of rounds, 0-10)");
    actions::setModelLoopRounds(s, arg["model_loop"].get<int>());
  }
  w.load(s);
  actions::startTracking(s);
}

// A path, or {"path": P[, "model": "lite" | "full" | "heavy"]}: the video opened as a drop
// opens it and its people detected, then the walker fitted, in the background; a detection
// that finds nobody, or a fit that fails, fails the script like a failed open.
void detectVideo(AppState& s, const A& a, W& w) {
  const auto& arg = a.argument;
  const bool object = arg.is_object() && arg.contains("path") && arg["path"].is_string();
  if (!arg.is_string() && !object)
    throw std::invalid_argument(R"(expects a path or {"path": P, "model": "full"})");
  if (object && arg.contains("model")) {
    if (!arg["model"].is_string()) throw std::invalid_argument(R"("model" is "lite", "full" or "heavy")");
    try {
      actions::setDetectorModel(s, parsePoseModelSize(arg["model"].get<std::string>(), "model"));
    } catch (const std::exception& e) {
      throw std::invalid_argument(e.what());
    }
  }
  const std::filesystem::path video = object ? arg["path"].get<std::string>() : arg.get<std::string>();
  if (!isVideoFile(video)) throw std::invalid_argument(video.string() + ": not a video (.mp4 .avi .mov …)");
  w.load(s);
  const bool onOpen = std::exchange(s.video.detectWhenOpens, true);
  actions::open(s, {video});
  s.video.detectWhenOpens = onOpen;
  if (s.notices.failures != w.failuresBefore) return;  // the video did not open: said as a failed open
  if (!s.video.detect.running()) {
    w.checkLoad = false;
    throw std::invalid_argument(s.video.session && !s.video.session->detectError.empty()
                                    ? s.video.session->detectError
                                    : "the detection did not start");
  }
}

// The Data window's Joint mapping tab: the suggestion for every joint, written to "out".
void writeJointMapping(AppState& s, const A& a, W& w) {
  const auto& arg = a.argument;
  if (!arg.is_object() || !arg.contains("file") || !arg["file"].is_string() ||
      !arg.contains("out") || !arg["out"].is_string())
    throw std::invalid_argument(R"(expects {"file": F, "out": P, "open": true|false})");
  const bool openNow =
      arg.contains("open") && arg["open"].is_boolean() && arg["open"].get<bool>();
  auto& tab = s.panels.data.mapping;
  tab.read(s, arg["file"].get<std::string>());
  if (tab.statusIsError) throw std::invalid_argument(tab.status);
  const std::string out = arg["out"].get<std::string>();
  tab.outPath.fill('\0');
  out.copy(tab.outPath.data(), tab.outPath.size() - 1);
  w.failuresBefore = s.notices.failures;
  tab.write(s, openNow);
  w.checkLoad = openNow;
}

void setFileOverride(AppState& s, const A& a, W&) {
  if (!a.argument.is_object() || !a.argument.contains("file") || !a.argument["file"].is_string())
    throw std::invalid_argument(R"(expects {"file": P, "units": "cm", "rate": 100})");
  std::string units;
  if (a.argument.contains("units")) {
    if (!a.argument["units"].is_string()) throw std::invalid_argument("units must be a string");
    units = a.argument["units"].get<std::string>();
  }
  actions::setFileOverride(s, a.argument["file"].get<std::string>(), units,
                           numberField(a.argument, "rate", 0.0));
}

void exportPng(AppState& s, const A& a, W& w) {
  if (a.argument.is_string()) {
    actions::requestPng(s, a.argument.get<std::string>(), CaptureView::Window);
  } else if (a.argument.is_object() && a.argument.contains("path") &&
             a.argument["path"].is_string()) {
    const std::string view = a.argument.contains("view") && a.argument["view"].is_string()
                                 ? a.argument["view"].get<std::string>()
                                 : std::string("window");
    actions::requestPng(s, a.argument["path"].get<std::string>(),
                        actions::captureViewFromName(view));
  } else {
    throw std::invalid_argument(
        R"(expects a path or {"path": P, "view": "window"|"input"|"reconstruction"})");
  }
  w.exportFailuresBefore = s.exports.failures;
  w.checkExport = true;
}

void exportVideo(AppState& s, const A& a, W& w) {
  if (!a.argument.is_object() || !a.argument.contains("path") || !a.argument["path"].is_string())
    throw std::invalid_argument(
        R"(expects {"path": P, "cycles": N, "fps": F, "width": W, "height": H, "captions": B})");
  VideoSettings v;
  v.path = a.argument["path"].get<std::string>();
  v.cycles = numberField(a.argument, "cycles", v.cycles);
  v.fps = numberField(a.argument, "fps", v.fps);
  v.width = static_cast<int>(numberField(a.argument, "width", v.width));
  v.height = static_cast<int>(numberField(a.argument, "height", v.height));
  if (a.argument.contains("captions")) {
    if (!a.argument["captions"].is_boolean())
      throw std::invalid_argument(R"("captions" is true or false)");
    v.captions = a.argument["captions"].get<bool>();
  }
  s.derived.update(s.doc);
  actions::startVideoExport(s, v);
  w.exportFailuresBefore = s.exports.failures;
  w.checkExport = true;
}

void tour(AppState& s, const A& a, W&) {
  const std::string t = text(a);
  if (t == "start") {
    actions::tourStart(s);
  } else if (t == "next") {
    actions::tourNext(s);
  } else if (t == "back") {
    actions::tourBack(s);
  } else if (t == "end") {
    actions::tourEnd(s);
  } else {
    throw std::invalid_argument("tour expects \"start\", \"next\", \"back\" or \"end\"");
  }
}

// [NAME, true|false] for overlay and show_panel.
std::pair<std::string, bool> nameAndFlag(const A& a) {
  if (!a.argument.is_array() || a.argument.size() != 2 || !a.argument[0].is_string() ||
      !a.argument[1].is_boolean())
    throw std::invalid_argument("expects [NAME, true|false]");
  return {a.argument[0].get<std::string>(), a.argument[1].get<bool>()};
}

// {"expect_failure": {NAME: ARG}}: the action (or the load it starts) must fail; the failure
// is shown as in an interactive session and the script goes on.
void expectFailure(AppState& s, const A& a, W& w) {
  const ScriptAction inner = innerAction(a);
  try {
    applyScriptAction(s, inner, w);
  } catch (const std::exception& e) {
    // Refused at once: reported as the window reports it (a refused drop gets the banner).
    w.checkLoad = false;
    if (inner.name == "open" || inner.name == "drop") {
      actions::reportOpenError(s, pathList(inner), e.what());
    } else {
      s.log.error(inner.name + ": " + e.what());
    }
    s.log.info("script: " + inner.name + " failed as expected");
    return;
  }
  if (!w.checkLoad)
    throw std::invalid_argument(inner.name + " was expected to fail, but it succeeded");
  w.expectFailure = true;  // the load's outcome is checked once it is done (ScriptRunner::step)
}

// {"start_dots": S, "step_dots": D, "max_dots": M, "reversals": R, "averaged": A, "seed": N},
// each optional (the quiz panel's defaults): the quiz started.
void quizStart(AppState& s, const A& a, W&) {
  const auto& arg = a.argument;
  if (!arg.is_object() && !arg.is_null() && !(arg.is_boolean() && arg.get<bool>()))
    throw std::invalid_argument(R"(expects {"start_dots": S, "step_dots": D, "reversals": R, …} or {})");
  StaircaseOptions o = s.quiz.options;
  const auto whole = [&](const char* key, int& into) {
    if (!arg.is_object() || !arg.contains(key)) return;
    if (!arg[key].is_number_integer()) throw std::invalid_argument(std::string("\"") + key + "\" is a whole number");
    into = arg[key].get<int>();
  };
  whole("start_dots", o.startDots);
  whole("step_dots", o.stepDots);
  whole("max_dots", o.maxDots);
  whole("reversals", o.reversals);
  whole("averaged", o.averagedReversals);
  int seed = static_cast<int>(o.seed);
  whole("seed", seed);
  if (seed < 0) throw std::invalid_argument(R"("seed" is 0 or more)");
  o.seed = static_cast<std::uint64_t>(seed);
  actions::quizStart(s, o);
}

// true / false, or {"open": B, "size": [W, H], "theme": "dark" | "projector",
// "views": "both" | "input" | "reconstruction"}, each optional.
void audience(AppState& s, const A& a, W&) {
  const auto& arg = a.argument;
  if (arg.is_boolean()) return actions::setAudienceOpen(s, arg.get<bool>());
  if (!arg.is_object()) throw std::invalid_argument(R"(expects true, false or {"open": true, "size": [W, H], "theme": T, "views": V})");
  if (arg.contains("size")) {
    const auto& size = arg["size"];
    if (!size.is_array() || size.size() != 2 || !size[0].is_number_integer() || !size[1].is_number_integer())
      throw std::invalid_argument(R"("size" is [width, height])");
    actions::setAudienceSize(s, size[0].get<int>(), size[1].get<int>());
  }
  const auto name = [&](const char* key) {
    if (!arg[key].is_string()) throw std::invalid_argument(std::string("\"") + key + "\" is a name");
    return arg[key].get<std::string>();
  };
  if (arg.contains("theme")) actions::setAudienceTheme(s, name("theme"));
  if (arg.contains("views")) actions::setAudienceViews(s, name("views"));
  if (arg.contains("open")) {
    if (!arg["open"].is_boolean()) throw std::invalid_argument(R"("open" is true or false)");
    actions::setAudienceOpen(s, arg["open"].get<bool>());
  } else {
    actions::setAudienceOpen(s, true);
  }
}

WalkDirection directionFromName(const std::string& name) {
  if (name == "left") return WalkDirection::Left;
  if (name == "right") return WalkDirection::Right;
  throw std::invalid_argument("the answer is \"left\" or \"right\", not \"" + name + "\"");
}

// [SECTION] The table
// Rows: name, apply, runner only, yields (ScriptActionKind). Arguments: docs/VIEWER.md.

// clang-format off
const ScriptActionKind kActions[] = {
  // Opening data: each waits for its load, whose failure fails the script.
  {"open", [](AppState& s, const A& a, W& w) { const auto paths = pathList(a); w.load(s); actions::open(s, paths); }, true, true},
  {"drop", [](AppState& s, const A& a, W& w) { const auto paths = pathList(a); w.load(s); actions::drop(s, paths); }, true, true},
  {"reload", [](AppState& s, const A&, W& w) { w.load(s); actions::reloadWithOverrides(s); }, true, true},
  {"set_file_override", setFileOverride},
  {"write_joint_mapping", writeJointMapping, true, true},
  {"export_data_summary", [](AppState& s, const A& a, W&) { actions::exportDataSummary(s, text(a)); }},
  {"set_model", [](AppState& s, const A& a, W&) { actions::setModelSource(s, text(a)); }},
  {"expect_failure", expectFailure, true, true},
  // The document
  {"select_subject", [](AppState& s, const A& a, W&) { actions::selectSubject(s, text(a)); }},
  {"set_mode", setMode},
  {"set_angle", [](AppState& s, const A& a, W&) { actions::setAngle(s, number(a)); }},
  {"set_method", [](AppState& s, const A& a, W&) {
     const std::string m = text(a);
     if (m == "lsq") {
       actions::setEstimator(s, Estimator::Lsq);
     } else if (m == "map") {
       actions::setEstimator(s, Estimator::Map);
     } else {
       throw std::invalid_argument("method must be \"lsq\" or \"map\"");
     }
   }},
  {"set_engine", [](AppState& s, const A& a, W&) { actions::setEngine(s, parseEngineKind(text(a), "set_engine")); }},
  {"compare_engines", [](AppState& s, const A& a, W&) {
     if (!a.argument.is_boolean()) throw std::invalid_argument("expects true or false");
     actions::setCompareEngines(s, a.argument.get<bool>());
   }},
  {"show_engine", [](AppState& s, const A& a, W&) {
     if (!a.argument.is_array() || a.argument.size() != 2 || !a.argument[0].is_string() ||
         !a.argument[1].is_boolean())
       throw std::invalid_argument("expects [ENGINE, true|false]");
     actions::setCompareShown(s, parseEngineKind(a.argument[0].get<std::string>(), "show_engine"),
                              a.argument[1].get<bool>());
   }},
  {"set_sigma2", [](AppState& s, const A& a, W&) { actions::setSigma2(s, number(a)); }},
  {"set_components", [](AppState& s, const A& a, W&) {
     const double v = number(a);
     if (v != std::floor(v)) throw std::invalid_argument("expects a whole number");
     actions::setComponents(s, static_cast<int>(v));
   }},
  {"unknown_angle", [](AppState& s, const A& a, W&) { actions::setUnknownAngle(s, boolean(a)); }},
  {"set_coefficient", [](AppState& s, const A& a, W&) {
     if (!a.argument.is_array() || a.argument.size() != 2 || !a.argument[0].is_number_integer() ||
         !a.argument[1].is_number())
       throw std::invalid_argument("expects [INDEX (from 1), SD]");
     s.derived.update(s.doc);  // the count of components follows the latest settings
     actions::setCoefficient(s, a.argument[0].get<int>() - 1, a.argument[1].get<double>());
   }},
  {"reset_coefficients", [](AppState& s, const A&, W&) { actions::resetCoefficients(s); }},
  {"randomise_coefficients", [](AppState& s, const A& a, W&) {
     s.derived.update(s.doc);
     actions::randomiseCoefficients(s, static_cast<unsigned>(number(a)));
   }},
  {"coefficients_from_subject", [](AppState& s, const A&, W&) {
     s.derived.update(s.doc);
     actions::coefficientsFromWalker(s);
   }},
  // {"attribute": NAME, "value": V}: the explorer's walker moved along the attribute's axis.
  {"set_semantic", [](AppState& s, const A& a, W&) {
     if (!a.argument.is_object() || !a.argument.contains("attribute") ||
         !a.argument["attribute"].is_string() || !a.argument.contains("value") ||
         !a.argument["value"].is_number())
       throw std::invalid_argument(R"(expects {"attribute": NAME, "value": V})");
     s.derived.update(s.doc);
     actions::setSemanticValue(s, a.argument["attribute"].get<std::string>(),
                               a.argument["value"].get<double>());
   }},
  {"undo", [](AppState& s, const A&, W& w) { undoOrRedo(s, w, undo); }},
  {"redo", [](AppState& s, const A&, W& w) { undoOrRedo(s, w, redo); }},
  // The classroom stage (ui/app/stage_actions.h)
  {"inverted", [](AppState& s, const A& a, W&) { actions::setInverted(s, boolean(a)); }},
  {"scramble", [](AppState& s, const A& a, W&) { actions::setScramble(s, scrambleFromName(text(a))); }},
  {"mask_dots", [](AppState& s, const A& a, W&) { actions::setMaskDots(s, wholeNumber(a)); }},
  {"dot_lifetime", [](AppState& s, const A& a, W&) { actions::setDotLifetime(s, number(a)); }},
  {"backwards", [](AppState& s, const A& a, W&) { actions::setBackwards(s, boolean(a)); }},
  {"overground", [](AppState& s, const A& a, W&) { actions::setTranslating(s, boolean(a)); }},
  {"depth_reversed", [](AppState& s, const A& a, W&) { actions::setDepthReversed(s, boolean(a)); }},
  {"reset_displays", [](AppState& s, const A&, W&) { actions::resetStage(s); }},
  {"turning", [](AppState& s, const A& a, W&) { actions::setTurning(s, boolean(a)); }},
  {"turn_rate", [](AppState& s, const A& a, W&) { actions::setTurnRate(s, number(a)); }},
  {"stage_turned", [](AppState& s, const A& a, W&) {
     const double deg = number(a);
     if (!std::isfinite(deg) || std::abs(deg) > 180.0) throw std::invalid_argument("the stage turns −180 to 180°");
     s.stage.turnedDeg = deg;
   }},
  {"stage_elevation", [](AppState& s, const A& a, W&) { actions::setStageElevation(s, number(a)); }},
  {"quiz_start", quizStart},
  {"quiz_answer", [](AppState& s, const A& a, W&) { actions::quizAnswer(s, directionFromName(text(a))); }},
  {"quiz_stop", [](AppState& s, const A&, W&) { actions::quizStop(s); }},
  {"save_quiz", [](AppState& s, const A& a, W&) { actions::saveQuizCsv(s, text(a)); }},
  {"export_html", [](AppState& s, const A& a, W&) { actions::exportWalkerHtml(s, text(a)); }},
  {"audience", audience},
  // The PNG is taken at the end of the next frame; the script waits for it.
  {"audience_screenshot", [](AppState& s, const A& a, W& w) { actions::requestAudiencePng(s, text(a)); w.frames = 2; }, false, true},
  // The view
  {"set_phase", [](AppState& s, const A& a, W&) { actions::setPhase(s, number(a)); }},
  {"play", [](AppState& s, const A& a, W&) { actions::setPlaying(s, boolean(a)); }},
  {"overlay", [](AppState& s, const A& a, W&) {
     const auto [name, on] = nameAndFlag(a);
     actions::setOverlay(s, name, on);
   }},
  {"set_camera", [](AppState& s, const A& a, W&) { actions::setCamera(s, text(a)); }},
  {"show_panel", [](AppState& s, const A& a, W&) {
     const auto [name, shown] = nameAndFlag(a);
     actions::showPanel(s, name, shown);
   }},
  {"drawer_tab", [](AppState& s, const A& a, W&) { s.panels.drawer.active = drawerTabFromName(text(a)); }},
  {"set_theme", [](AppState& s, const A& a, W&) { actions::setTheme(s, text(a)); }},
  {"presentation", [](AppState& s, const A& a, W&) { actions::setPresentation(s, boolean(a)); }},
  {"tour", tour},
  {"header_more", [](AppState& s, const A& a, W&) {
     if (!boolean(a)) throw std::invalid_argument("expects true (the menu closes when anything else is clicked)");
     if (!s.panels.header.moreShown)
       throw std::invalid_argument("the header shows every button at this window size and UI scale: no More… menu");
     s.panels.header.openMore = true;
   }},
  {"key", [](AppState& s, const A& a, W&) {
     const auto chord = parseKeyChord(text(a));
     if (!chord || !applyShortcut(s, *chord))
       throw std::invalid_argument("no key \"" + text(a) +
                                   "\" (the keys: docs/VIEWER.md, \"Keyboard\")");
   }},
  // The next action comes a frame after this one is seen.
  {"mouse", [](AppState& s, const A& a, W& w) { applyMouse(s, a.argument); w.frames = 1; }, true, true},
  // Keypoint clips: a refit runs in the background, and its failure fails the script.
  {"set_clip", [](AppState& s, const A& a, W& w) { applyClipSettings(s, a); w.failuresBefore = s.notices.failures; w.checkLoad = true; }, false, true},
  {"close_clip", [](AppState& s, const A&, W&) { actions::closeClip(s); }},
  {"set_frame", [](AppState& s, const A& a, W&) {
     const double v = number(a);
     if (v != std::floor(v)) throw std::invalid_argument("expects a whole frame number (from 1)");
     actions::setClipFrame(s, static_cast<int>(v));
   }},
  {"clip_zoom", zoom},
  // Video: marking, tracking, detecting
  {"video_frame", [](AppState& s, const A& a, W&) { actions::setVideoFrame(s, wholeNumber(a)); }},
  {"video_zoom", zoom},
  {"mark_joints", [](AppState& s, const A& a, W&) { markJoints(s, a); }},
  {"start_marking", [](AppState& s, const A&, W&) { actions::startMarking(s); }},
  {"stop_marking", [](AppState& s, const A&, W&) { actions::stopMarking(s); }},
  {"skip_joint", [](AppState& s, const A&, W&) { actions::skipMarkedJoint(s); }},
  {"undo_keyframes", [](AppState& s, const A&, W& w) { actions::undoKeyframes(s); keyframesEdited(s, w); }},
  {"redo_keyframes", [](AppState& s, const A&, W& w) { actions::redoKeyframes(s); keyframesEdited(s, w); }},
  {"remove_keyframe", [](AppState& s, const A& a, W& w) { actions::removeKeyframe(s, wholeNumber(a)); keyframesEdited(s, w); }},
  {"save_keyframes", [](AppState& s, const A& a, W&) { actions::saveKeyframes(s, text(a)); }},
  {"save_track", [](AppState& s, const A& a, W&) { actions::saveTrack(s, text(a)); }},
  {"mark_from_keypoints", [](AppState& s, const A& a, W&) { actions::markFromKeypoints(s, text(a)); }},
  // {"r_knee": [x, y]}: one joint dragged there on the frame shown and let go; a tracked
  // video is tracked again, a detected one fitted again with it as a correction (issue 52),
  // and the script waits for it as for track_video.
  {"drag_joint", [](AppState& s, const A& a, W& w) {
     if (!a.argument.is_object() || a.argument.size() != 1)
       throw std::invalid_argument(R"(expects {"joint name": [x, y]})");
     markJoints(s, a);
     w.failuresBefore = s.notices.failures;
     w.checkLoad = actions::letGoOfJoint(s);
   }, true},
  {"track_video", trackVideo, true},
  {"detect_video", detectVideo, true},
  {"detect_on_open", [](AppState& s, const A& a, W&) {
     if (!a.argument.is_boolean()) throw std::invalid_argument("expects true or false");
     actions::setDetectWhenVideoOpens(s, a.argument.get<bool>());
   }},
  {"close_video", [](AppState& s, const A&, W&) { actions::closeVideo(s); }},
  // Analysis and exports
  {"analysis_engines", [](AppState& s, const A& a, W&) {
     if (!a.argument.is_boolean()) throw std::invalid_argument("expects true or false");
     s.panels.analysis.showEngines = a.argument.get<bool>();
   }},
  {"set_analysis_metric", [](AppState& s, const A& a, W&) { actions::setAnalysisMetric(s, text(a)); }},
  {"export_analysis_csv", [](AppState& s, const A& a, W&) { actions::exportAnalysisCsv(s, text(a)); }},
  {"export_gait_report", [](AppState& s, const A& a, W&) { actions::exportGaitReport(s, text(a)); }},
  {"export_state", [](AppState& s, const A& a, W&) {
     s.derived.update(s.doc);  // the reconstruction of what the actions before chose
     actions::exportState(s, text(a));
   }},
  {"export_csv", [](AppState& s, const A& a, W&) {
     s.derived.update(s.doc);
     const auto [path, cycles] = pathAndCycles(a);
     actions::exportCsv(s, path, cycles);
   }},
  {"export_bvh", [](AppState& s, const A& a, W&) {
     s.derived.update(s.doc);
     const auto [path, cycles] = pathAndCycles(a);
     actions::exportBvh(s, path, cycles);
   }},
  {"export_model", [](AppState& s, const A& a, W&) {
     s.derived.update(s.doc);
     actions::exportModel(s, text(a));
   }},
  {"export_png", exportPng, true, true},
  {"export_video", exportVideo, true, true},
  // The runner's own
  {"wait_frames", [](AppState&, const A& a, W& w) {
     const double v = number(a);
     if (v < 0 || v != std::floor(v)) throw std::invalid_argument("expects a whole number >= 0");
     w.frames = static_cast<int>(v);
   }, true, true},
  {"screenshot", [](AppState&, const A& a, W& w) { w.capture = text(a); }, true, true},
};
// clang-format on

}  // namespace

// The action inside {"expect_failure": {NAME: ARG}}.
ScriptAction innerAction(const ScriptAction& a) {
  const auto& inner = a.argument;
  if (!inner.is_object() || inner.size() != 1)
    throw std::invalid_argument(R"(expects one action, e.g. {"drop": ["walk.csv"]})");
  const std::string key = inner.begin().key();
  if (!scriptAction(key) || key == "expect_failure")
    throw std::invalid_argument("unknown action \"" + key + "\"");
  return {key, inner.begin().value(), a.position};
}

std::span<const ScriptActionKind> scriptActions() { return kActions; }

const ScriptActionKind* scriptAction(std::string_view name) {
  const auto it = std::find_if(std::begin(kActions), std::end(kActions),
                               [name](const ScriptActionKind& k) { return k.name == name; });
  return it == std::end(kActions) ? nullptr : &*it;
}

void applyScriptAction(AppState& s, const ScriptAction& a, ScriptWaits& waits) {
  const ScriptActionKind* kind = scriptAction(a.name);
  if (!kind) throw std::invalid_argument("cannot be used here");
  kind->apply(s, a, waits);
}

void applyAction(AppState& s, const ScriptAction& a) {
  const ScriptActionKind* kind = scriptAction(a.name);
  if (!kind || kind->runnerOnly) throw std::invalid_argument("cannot be used here");
  ScriptWaits ignored;  // the tour's steps wait for nothing
  kind->apply(s, a, ignored);
}

}  // namespace ew::ui
