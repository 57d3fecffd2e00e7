#include "ui/app/script.h"

#include <cmath>
#include <fstream>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include "core/keypoints/keypoint_frames.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/shortcuts.h"
#include "ui/app/undo.h"

namespace ew::ui {

namespace {

const std::set<std::string>& knownActions() {
  // clang-format off
  static const std::set<std::string> names{
      "open",         "select_subject", "set_mode",      "set_angle",   "set_method",
      "set_sigma2",   "set_components", "unknown_angle", "set_coefficient", "set_phase",
      "play",         "overlay",        "wait_frames",   "screenshot",  "set_camera",
      "reset_coefficients", "randomise_coefficients", "coefficients_from_subject",
      "export_png",   "export_video",   "export_csv",    "export_bvh",  "export_model",
      "show_panel",   "export_analysis_csv", "set_analysis_metric", "set_theme", "tour",
      "drop",         "set_file_override", "reload", "export_data_summary", "export_state",
      "expect_failure", "set_model", "write_joint_mapping", "set_clip", "close_clip", "set_frame",
      "set_engine", "video_frame", "video_zoom", "clip_zoom", "mark_joints", "start_marking", "stop_marking", "skip_joint",
      "undo_keyframes", "redo_keyframes", "remove_keyframe", "save_keyframes", "save_track", "mark_from_keypoints", "drag_joint", "track_video",
      "close_video", "export_gait_report", "compare_engines", "show_engine", "analysis_engines", "drawer_tab",
      "set_semantic", "presentation", "key", "undo", "redo", "header_more", "mouse", "detect_video",
      "detect_on_open"};
  // clang-format on
  return names;
}

// Frames rendered after the work is done before a screenshot, so the UI has settled.
constexpr int kSettleFrames = 2;

// The `mouse` action's button: "left", "right" or "middle".
std::size_t mouseButton(const nlohmann::json& v) {
  const std::string b = v.is_string() ? v.get<std::string>() : std::string();
  if (b == "left") return 0;
  if (b == "right") return 1;
  if (b == "middle") return 2;
  throw std::invalid_argument("a mouse button is \"left\", \"right\" or \"middle\"");
}

// {"at": [x, y]} (window pixels, as a screenshot's), {"press": B}, {"release": B},
// {"wheel": notches} (up is positive), {"away": true}; several keys apply in that order.
void applyMouse(AppState& s, const nlohmann::json& arg) {
  if (!arg.is_object() || arg.empty())
    throw std::invalid_argument(R"(expects {"at": [x, y]}, {"press": "left"}, {"release": "left"}, {"wheel": 1} or {"away": true})");
  for (const auto& [key, value] : arg.items())
    if (key != "at" && key != "press" && key != "release" && key != "wheel" && key != "away")
      throw std::invalid_argument("no mouse key \"" + key + "\" (at, press, release, wheel, away)");
  auto& p = s.pointer;
  if (arg.contains("at")) {
    const auto& at = arg["at"];
    if (!at.is_array() || at.size() != 2 || !at[0].is_number() || !at[1].is_number())
      throw std::invalid_argument("\"at\" expects [x, y] in window pixels");
    p.present = true;
    p.x = at[0].get<float>();
    p.y = at[1].get<float>();
  }
  if (arg.contains("press")) p.down[mouseButton(arg["press"])] = true;
  if (arg.contains("release")) p.down[mouseButton(arg["release"])] = false;
  if (arg.contains("wheel")) {
    if (!arg["wheel"].is_number()) throw std::invalid_argument("\"wheel\" expects a number of notches");
    p.wheel += arg["wheel"].get<float>();
  }
  if (arg.contains("away")) p = AppState::ScriptedPointer{};
}

double number(const ScriptAction& a) {
  if (!a.argument.is_number()) throw std::invalid_argument("expects a number");
  return a.argument.get<double>();
}

bool boolean(const ScriptAction& a) {
  if (!a.argument.is_boolean()) throw std::invalid_argument("expects true or false");
  return a.argument.get<bool>();
}

std::string text(const ScriptAction& a) {
  if (!a.argument.is_string()) throw std::invalid_argument("expects a string");
  return a.argument.get<std::string>();
}

// A path string, or {"path": P, "cycles": N}.
std::pair<std::filesystem::path, std::optional<double>> pathAndCycles(const ScriptAction& a) {
  if (a.argument.is_string()) return {a.argument.get<std::string>(), std::nullopt};
  if (a.argument.is_object() && a.argument.contains("path") && a.argument["path"].is_string()) {
    std::optional<double> cycles;
    if (a.argument.contains("cycles")) {
      if (!a.argument["cycles"].is_number()) throw std::invalid_argument("cycles must be a number");
      cycles = a.argument["cycles"].get<double>();
    }
    return {a.argument["path"].get<std::string>(), cycles};
  }
  throw std::invalid_argument("expects a path or {\"path\": P, \"cycles\": N}");
}

double numberField(const nlohmann::json& o, const char* key, double fallback) {
  if (!o.contains(key)) return fallback;
  if (!o[key].is_number()) throw std::invalid_argument(std::string(key) + " must be a number");
  return o[key].get<double>();
}

// The action inside {"expect_failure": {NAME: ARG}}.
ScriptAction innerAction(const ScriptAction& a) {
  const auto& inner = a.argument;
  if (!inner.is_object() || inner.size() != 1)
    throw std::invalid_argument(R"(expects one action, e.g. {"drop": ["walk.csv"]})");
  const std::string key = inner.begin().key();
  if (!knownActions().contains(key) || key == "expect_failure")
    throw std::invalid_argument("unknown action \"" + key + "\"");
  return {key, inner.begin().value(), a.position};
}

// The paths of "open" (a path, a list, or null: none) and "drop" (a list).
std::vector<std::filesystem::path> pathList(const ScriptAction& a) {
  std::vector<std::filesystem::path> paths;
  if (a.name == "open" && a.argument.is_string()) {
    paths.emplace_back(a.argument.get<std::string>());
  } else if (a.argument.is_array()) {
    for (const auto& p : a.argument) {
      if (!p.is_string()) throw std::invalid_argument("expects a list of paths");
      paths.emplace_back(p.get<std::string>());
    }
  } else if (a.name != "open") {
    throw std::invalid_argument("expects a list of paths");
  } else if (!a.argument.is_null()) {
    throw std::invalid_argument(
        "expects a path, a list of paths, or null (the default population)");
  }
  return paths;
}

int wholeNumber(const ScriptAction& a) {
  const double v = number(a);
  if (v != std::floor(v) || std::abs(v) > 1e9)
    throw std::invalid_argument("expects a whole number");
  return static_cast<int>(v);
}

// {"mark_joints": {"head": [x, y], …}}: each joint placed on the frame shown, as clicks would
// (video pixels, x right, y down), each an edit of its own.
void markJoints(AppState& s, const ScriptAction& a) {
  if (!a.argument.is_object() || a.argument.empty())
    throw std::invalid_argument(R"(expects {"joint name": [x, y], …})");
  for (const auto& [name, xy] : a.argument.items()) {
    const auto joint = jointFromName(name);
    if (!joint) throw std::invalid_argument("unknown joint \"" + name + "\"");
    if (!xy.is_array() || xy.size() != 2 || !xy[0].is_number() || !xy[1].is_number())
      throw std::invalid_argument(name + ": expects [x, y] in pixels");
    actions::markJoint(s, *joint, xy[0].get<double>(), xy[1].get<double>());
  }
}

// {"set_clip": {"focal_px": F | null, "azimuth_deg": A | null, "elevation_deg": E | null,
//  "layout": "BODY_25B" | "", "fps": 30 | 0, "person": 1 | -1, "image_size": "1920x1080" | null}}:
// null / "" / 0 / -1 estimate, guess or take the default again.
void applyClipSettings(AppState& s, const ScriptAction& a) {
  if (!a.argument.is_object() || a.argument.empty())
    throw std::invalid_argument("expects an object of clip settings");
  auto optionalNumber = [](const nlohmann::json& v,
                           const std::string& key) -> std::optional<double> {
    if (v.is_null()) return std::nullopt;
    if (!v.is_number()) throw std::invalid_argument(key + " must be a number or null");
    return v.get<double>();
  };
  for (const auto& [key, v] : a.argument.items()) {
    if (key == "focal_px") {
      actions::setClipFocal(s, optionalNumber(v, key));
    } else if (key == "azimuth_deg") {
      actions::setClipAzimuth(s, optionalNumber(v, key));
    } else if (key == "elevation_deg") {
      actions::setClipElevation(s, optionalNumber(v, key));
    } else if (key == "layout") {
      if (!v.is_string()) throw std::invalid_argument("layout must be a string");
      actions::setClipLayout(s, v.get<std::string>());
    } else if (key == "fps") {
      actions::setClipFps(s, optionalNumber(v, key).value_or(0.0));
    } else if (key == "person") {
      if (!v.is_number_integer()) throw std::invalid_argument("person must be a whole number");
      actions::setClipPerson(s, v.get<int>());
    } else if (key == "image_size") {
      if (!v.is_null() && !v.is_string()) throw std::invalid_argument("image_size must be \"WxH\" or null");
      actions::setClipImageSize(s, v.is_null() ? std::nullopt
                                               : std::optional(parseKeypointImageSize(v.get<std::string>(), "image_size")));
    } else {
      throw std::invalid_argument(
          "unknown clip setting \"" + key +
          "\" (known: focal_px, azimuth_deg, elevation_deg, layout, fps, person, image_size)");
    }
  }
}

}  // namespace

std::vector<ScriptAction> parseScript(const nlohmann::json& script, const std::string& name) {
  if (!script.is_array()) throw std::runtime_error(name + ": a script is a JSON array of actions");
  std::vector<ScriptAction> actions;
  int position = 0;
  for (const auto& item : script) {
    ++position;
    if (!item.is_object() || item.size() != 1)
      throw std::runtime_error(name + ": action " + std::to_string(position) +
                               ": each action is an object with exactly one key, got " +
                               item.dump());
    const auto entry = item.begin();
    const std::string key = entry.key();
    if (!knownActions().contains(key))
      throw std::runtime_error(name + ": action " + std::to_string(position) +
                               ": unknown action \"" + key + "\"");
    actions.push_back({key, entry.value(), position});
    if (key == "expect_failure") {
      try {
        (void)innerAction(actions.back());
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error(name + ": action " + std::to_string(position) +
                                 ": expect_failure " + e.what());
      }
    }
  }
  return actions;
}

std::vector<ScriptAction> readScript(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read the script");
  nlohmann::json script;
  try {
    in >> script;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not valid JSON: " + e.what());
  }
  return parseScript(script, file.string());
}

ScriptRunner::ScriptRunner(std::vector<ScriptAction> actions, std::string name)
    : actions_(std::move(actions)), name_(std::move(name)) {}

void ScriptRunner::requestCapture(std::filesystem::path file) {
  capture_ = std::move(file);
  captureSettle_ = kSettleFrames;
  captureDue_ = false;
}

std::optional<std::filesystem::path> ScriptRunner::takeCapture() {
  if (!captureDue_) return std::nullopt;
  captureDue_ = false;
  auto file = std::move(capture_);
  capture_.reset();
  return file;
}

void applyAction(AppState& s, const ScriptAction& a) {
  const auto& n = a.name;
  if (n == "select_subject") {
    actions::selectSubject(s, text(a));
  } else if (n == "set_mode") {
    const std::string m = text(a);
    if (m == "reconstruct") {
      actions::setMode(s, Mode::Reconstruct);
    } else if (m == "explore") {
      actions::setMode(s, Mode::Explore);
    } else if (m == "clip") {
      if (!s.doc.clip) throw std::invalid_argument("no keypoint clip is open");
      actions::setMode(s, Mode::Clip);
    } else {
      throw std::invalid_argument("mode must be \"reconstruct\", \"explore\" or \"clip\"");
    }
  } else if (n == "set_clip") {
    applyClipSettings(s, a);
  } else if (n == "close_clip") {
    actions::closeClip(s);
  } else if (n == "set_frame") {
    const double v = number(a);
    if (v != std::floor(v)) throw std::invalid_argument("expects a whole frame number (from 1)");
    actions::setClipFrame(s, static_cast<int>(v));
  } else if (n == "video_frame") {
    actions::setVideoFrame(s, wholeNumber(a));
  } else if (n == "video_zoom" || n == "clip_zoom") {
    // {"zoom": Z, "centre": [x, y]} (image pixels, y down; Z 1 shows the whole picture, or the
    // region a clip's walker crosses)
    const auto& arg = a.argument;
    if (!arg.is_object() || !arg.contains("zoom") || !arg["zoom"].is_number() || !arg.contains("centre") ||
        !arg["centre"].is_array() || arg["centre"].size() != 2 || !arg["centre"][0].is_number() ||
        !arg["centre"][1].is_number())
      throw std::invalid_argument(R"(expects {"zoom": Z, "centre": [x, y]})");
    const Eigen::Vector2d centre(arg["centre"][0].get<double>(), arg["centre"][1].get<double>());
    if (n == "video_zoom")
      actions::setVideoZoom(s, arg["zoom"].get<double>(), centre);
    else
      actions::setClipZoom(s, arg["zoom"].get<double>(), centre);
  } else if (n == "mark_joints") {
    markJoints(s, a);
  } else if (n == "start_marking") {
    actions::startMarking(s);
  } else if (n == "stop_marking") {
    actions::stopMarking(s);
  } else if (n == "skip_joint") {
    actions::skipMarkedJoint(s);
  } else if (n == "undo_keyframes") {
    actions::undoKeyframes(s);
  } else if (n == "redo_keyframes") {
    actions::redoKeyframes(s);
  } else if (n == "remove_keyframe") {
    actions::removeKeyframe(s, wholeNumber(a));
  } else if (n == "save_keyframes") {
    actions::saveKeyframes(s, text(a));
  } else if (n == "save_track") {
    actions::saveTrack(s, text(a));
  } else if (n == "mark_from_keypoints") {
    actions::markFromKeypoints(s, text(a));
  } else if (n == "close_video") {
    actions::closeVideo(s);
  } else if (n == "detect_on_open") {
    if (!a.argument.is_boolean()) throw std::invalid_argument("expects true or false");
    actions::setDetectWhenVideoOpens(s, a.argument.get<bool>());
  } else if (n == "set_angle") {
    actions::setAngle(s, number(a));
  } else if (n == "set_method") {
    const std::string m = text(a);
    if (m == "lsq") {
      actions::setEstimator(s, Estimator::Lsq);
    } else if (m == "map") {
      actions::setEstimator(s, Estimator::Map);
    } else {
      throw std::invalid_argument("method must be \"lsq\" or \"map\"");
    }
  } else if (n == "compare_engines") {
    if (!a.argument.is_boolean()) throw std::invalid_argument("expects true or false");
    actions::setCompareEngines(s, a.argument.get<bool>());
  } else if (n == "show_engine") {
    if (!a.argument.is_array() || a.argument.size() != 2 || !a.argument[0].is_string() ||
        !a.argument[1].is_boolean())
      throw std::invalid_argument("expects [ENGINE, true|false]");
    actions::setCompareShown(s, parseEngineKind(a.argument[0].get<std::string>(), "show_engine"),
                             a.argument[1].get<bool>());
  } else if (n == "set_engine") {
    actions::setEngine(s, parseEngineKind(text(a), "set_engine"));
  } else if (n == "set_sigma2") {
    actions::setSigma2(s, number(a));
  } else if (n == "set_components") {
    const double v = number(a);
    if (v != std::floor(v)) throw std::invalid_argument("expects a whole number");
    actions::setComponents(s, static_cast<int>(v));
  } else if (n == "unknown_angle") {
    actions::setUnknownAngle(s, boolean(a));
  } else if (n == "set_coefficient") {
    if (!a.argument.is_array() || a.argument.size() != 2 || !a.argument[0].is_number_integer() ||
        !a.argument[1].is_number())
      throw std::invalid_argument("expects [INDEX (from 1), SD]");
    s.derived.update(s.doc);  // the count of components follows the latest settings
    actions::setCoefficient(s, a.argument[0].get<int>() - 1, a.argument[1].get<double>());
  } else if (n == "set_semantic") {
    // {"attribute": NAME, "value": V}: the explorer's walker moved along the attribute's axis.
    if (!a.argument.is_object() || !a.argument.contains("attribute") ||
        !a.argument["attribute"].is_string() || !a.argument.contains("value") ||
        !a.argument["value"].is_number())
      throw std::invalid_argument(R"(expects {"attribute": NAME, "value": V})");
    s.derived.update(s.doc);
    actions::setSemanticValue(s, a.argument["attribute"].get<std::string>(),
                              a.argument["value"].get<double>());
  } else if (n == "set_phase") {
    actions::setPhase(s, number(a));
  } else if (n == "play") {
    actions::setPlaying(s, boolean(a));
  } else if (n == "overlay") {
    if (!a.argument.is_array() || a.argument.size() != 2 || !a.argument[0].is_string() ||
        !a.argument[1].is_boolean())
      throw std::invalid_argument("expects [NAME, true|false]");
    actions::setOverlay(s, a.argument[0].get<std::string>(), a.argument[1].get<bool>());
  } else if (n == "set_camera") {
    actions::setCamera(s, text(a));
  } else if (n == "reset_coefficients") {
    actions::resetCoefficients(s);
  } else if (n == "randomise_coefficients") {
    s.derived.update(s.doc);
    actions::randomiseCoefficients(s, static_cast<unsigned>(number(a)));
  } else if (n == "show_panel") {
    if (!a.argument.is_array() || a.argument.size() != 2 || !a.argument[0].is_string() ||
        !a.argument[1].is_boolean())
      throw std::invalid_argument("expects [NAME, true|false]");
    actions::showPanel(s, a.argument[0].get<std::string>(), a.argument[1].get<bool>());
  } else if (n == "export_gait_report") {
    actions::exportGaitReport(s, text(a));
  } else if (n == "export_analysis_csv") {
    actions::exportAnalysisCsv(s, text(a));
  } else if (n == "set_analysis_metric") {
    actions::setAnalysisMetric(s, text(a));
  } else if (n == "drawer_tab") {
    s.panels.drawer.active = drawerTabFromName(text(a));
  } else if (n == "analysis_engines") {
    if (!a.argument.is_boolean()) throw std::invalid_argument("expects true or false");
    s.panels.analysis.showEngines = a.argument.get<bool>();
  } else if (n == "set_file_override") {
    if (!a.argument.is_object() || !a.argument.contains("file") || !a.argument["file"].is_string())
      throw std::invalid_argument(R"(expects {"file": P, "units": "cm", "rate": 100})");
    std::string units;
    if (a.argument.contains("units")) {
      if (!a.argument["units"].is_string()) throw std::invalid_argument("units must be a string");
      units = a.argument["units"].get<std::string>();
    }
    actions::setFileOverride(s, a.argument["file"].get<std::string>(), units,
                             numberField(a.argument, "rate", 0.0));
  } else if (n == "export_data_summary") {
    actions::exportDataSummary(s, text(a));
  } else if (n == "export_state") {
    s.derived.update(s.doc);  // the reconstruction of what the actions before chose
    actions::exportState(s, text(a));
  } else if (n == "set_theme") {
    actions::setTheme(s, text(a));
  } else if (n == "presentation") {
    actions::setPresentation(s, boolean(a));
  } else if (n == "header_more") {
    if (!boolean(a)) throw std::invalid_argument("expects true (the menu closes when anything else is clicked)");
    if (!s.panels.header.moreShown)
      throw std::invalid_argument("the header shows every button at this window size and UI scale: no More… menu");
    s.panels.header.openMore = true;
  } else if (n == "undo") {
    undo(s);
  } else if (n == "redo") {
    redo(s);
  } else if (n == "key") {
    const auto chord = parseKeyChord(text(a));
    if (!chord || !applyShortcut(s, *chord))
      throw std::invalid_argument("no key \"" + text(a) +
                                  "\" (the keys: docs/VIEWER.md, \"Keyboard\")");
  } else if (n == "tour") {
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
  } else if (n == "export_csv") {
    s.derived.update(s.doc);
    const auto [path, cycles] = pathAndCycles(a);
    actions::exportCsv(s, path, cycles);
  } else if (n == "export_bvh") {
    s.derived.update(s.doc);
    const auto [path, cycles] = pathAndCycles(a);
    actions::exportBvh(s, path, cycles);
  } else if (n == "export_model") {
    s.derived.update(s.doc);
    actions::exportModel(s, text(a));
  } else if (n == "set_model") {
    actions::setModelSource(s, text(a));
  } else if (n == "coefficients_from_subject") {
    s.derived.update(s.doc);
    actions::coefficientsFromWalker(s);
  } else {
    throw std::invalid_argument("cannot be used here");
  }
}

void ScriptRunner::apply(AppState& s, const ScriptAction& a) {
  const auto& n = a.name;
  if (n == "expect_failure") {
    applyExpectingFailure(s, a);
  } else if (n == "mouse") {
    applyMouse(s, a.argument);
    waitFrames_ = 1;  // the next action comes a frame after this one is seen
  } else if (n == "track_video") {
    // {"first": F, "last": L[, "tracker": "flow" | "appearance"][, "flatten_background": B]
    //  [, "hold_trunk": B][, "model_loop": N]}
    // (L -1: the end): tracked
    // and fitted in the background; a track or fit that fails fails the script like a failed
    // open.
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
    failuresBefore_ = s.jobs.failures;
    checkLoad_ = true;
    actions::startTracking(s);
  } else if (n == "detect_video") {
    // A path, or {"path": P[, "model": "lite" | "full" | "heavy"]}: the video opened as a drop
    // opens it and its people detected, then the walker fitted, in the background; a detection
    // that finds nobody, or a fit that fails, fails the script like a failed open.
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
    failuresBefore_ = s.jobs.failures;
    checkLoad_ = true;
    const bool onOpen = std::exchange(s.view.detectWhenVideoOpens, true);
    actions::open(s, {video});
    s.view.detectWhenVideoOpens = onOpen;
    if (s.jobs.failures != failuresBefore_) return;  // the video did not open: said as a failed open
    if (!s.jobs.detect.running()) {
      checkLoad_ = false;
      throw std::invalid_argument(s.video && !s.video->detectError.empty() ? s.video->detectError
                                                                           : "the detection did not start");
    }
  } else if (n == "undo_keyframes" || n == "redo_keyframes" || n == "remove_keyframe") {
    // A detected video's corrections changed: the script waits for the fit again.
    applyAction(s, a);
    failuresBefore_ = s.jobs.failures;
    checkLoad_ = actions::correctsDetections(s) && !s.video->marking;
  } else if (n == "drag_joint") {
    // {"r_knee": [x, y]}: one joint dragged there on the frame shown and let go; a tracked
    // video is tracked again, a detected one fitted again with it as a correction (issue 52),
    // and the script waits for it as for track_video.
    if (!a.argument.is_object() || a.argument.size() != 1)
      throw std::invalid_argument(R"(expects {"joint name": [x, y]})");
    markJoints(s, a);
    failuresBefore_ = s.jobs.failures;
    checkLoad_ = actions::letGoOfJoint(s);
  } else if (n == "set_clip") {
    // The refit runs in the background: its failure fails the script like a failed open.
    applyAction(s, a);
    failuresBefore_ = s.jobs.failures;
    checkLoad_ = true;
  } else if (n == "open" || n == "drop") {
    const auto paths = pathList(a);
    failuresBefore_ = s.jobs.failures;
    checkLoad_ = true;
    if (n == "open") {
      actions::open(s, paths);
    } else {
      actions::drop(s, paths);
    }
  } else if (n == "write_joint_mapping") {
    // The Data window's Joint mapping tab: the suggestion for every joint, written to "out".
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
    failuresBefore_ = s.jobs.failures;
    tab.write(s, openNow);
    checkLoad_ = openNow;
  } else if (n == "reload") {
    failuresBefore_ = s.jobs.failures;
    checkLoad_ = true;
    actions::reloadWithOverrides(s);
  } else if (n == "wait_frames") {
    const double v = number(a);
    if (v < 0 || v != std::floor(v)) throw std::invalid_argument("expects a whole number >= 0");
    waitFrames_ = static_cast<int>(v);
  } else if (n == "screenshot") {
    requestCapture(text(a));
  } else if (n == "export_png") {
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
    exportFailuresBefore_ = s.exports.failures;
    checkExport_ = true;
  } else if (n == "export_video") {
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
    exportFailuresBefore_ = s.exports.failures;
    checkExport_ = true;
  } else {
    applyAction(s, a);
  }
}

void ScriptRunner::applyExpectingFailure(AppState& s, const ScriptAction& a) {
  const ScriptAction inner = innerAction(a);
  try {
    apply(s, inner);
  } catch (const std::exception& e) {
    // Refused at once: reported as the window reports it (a refused drop gets the banner).
    checkLoad_ = false;
    if (inner.name == "open" || inner.name == "drop") {
      actions::reportOpenError(s, pathList(inner), e.what());
    } else {
      s.log.error(inner.name + ": " + e.what());
    }
    s.log.info("script: " + inner.name + " failed as expected");
    return;
  }
  if (!checkLoad_)
    throw std::invalid_argument(inner.name + " was expected to fail, but it succeeded");
  expectFailure_ = true;  // the load's outcome is checked once it is done (step)
}

void ScriptRunner::step(AppState& s) {
  if (failed()) return;
  // Everything waits for the background work (and reports a failed load).
  if (s.busy()) return;
  if (checkLoad_) {
    checkLoad_ = false;
    const bool expected = std::exchange(expectFailure_, false);
    if (expected && s.jobs.failures == failuresBefore_) {
      error_ = name_ + ": action " + std::to_string(actions_[next_ - 1].position) +
               " (expect_failure): the open was expected to fail, but it succeeded";
      return;
    }
    if (expected) {
      s.log.info("script: failed as expected");
    } else if (s.jobs.failures != failuresBefore_) {
      error_ = name_ + ": action " + std::to_string(actions_[next_ - 1].position) + " (" +
               actions_[next_ - 1].name + "): " + s.jobs.lastError;
      return;
    }
  }
  if (checkExport_) {
    checkExport_ = false;
    if (s.exports.failures != exportFailuresBefore_) {
      const ScriptAction& last = actions_[next_ - 1];
      error_ = name_ + ": action " + std::to_string(last.position) + " (" + last.name +
               "): " + s.exports.lastError;
      return;
    }
  }
  if (waitFrames_ > 0) {
    --waitFrames_;
    return;
  }
  if (capture_) {
    if (captureSettle_ > 0) {
      --captureSettle_;
    } else {
      captureDue_ = true;
    }
    return;
  }
  while (next_ < actions_.size()) {
    const ScriptAction& a = actions_[next_++];
    try {
      apply(s, a);
    } catch (const std::exception& e) {
      error_ = name_ + ": action " + std::to_string(a.position) + " (" + a.name + " " +
               a.argument.dump() + "): " + e.what();
      return;
    }
    s.log.info("script: " + a.name + " " + a.argument.dump());
    // Each action its own undo step, as each click is (the frame loop would merge a frame's).
    s.history.observe(captureParameters(s), captureParameterContext(s), true);
    // An action that started background work (a track, a fit, a model) yields, so that the
    // next one sees its result: `track_video` then `export_state` once exported the state
    // from before the track.
    if (a.name == "open" || a.name == "drop" || a.name == "reload" || a.name == "expect_failure" ||
        a.name == "write_joint_mapping" || a.name == "wait_frames" || a.name == "screenshot" ||
        a.name == "set_clip" || a.name == "export_png" || a.name == "export_video" || a.name == "mouse" ||
        checkLoad_ || s.busy())
      return;
  }
}

}  // namespace ew::ui
