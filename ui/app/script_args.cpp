#include "ui/app/script_args.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/keypoints/keypoint_frames.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"

namespace ew::ui::script_args {

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
//  "hold_to_horizon": true | false, "layout": "BODY_25B" | "", "fps": 30 | 0, "person": 1 | -1, "image_size": "1920x1080" | null}}:
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
    } else if (key == "hold_to_horizon") {
      if (!v.is_boolean()) throw std::invalid_argument("hold_to_horizon must be true or false");
      actions::setClipHoldToHorizon(s, v.get<bool>());
    } else if (key == "layout") {
      if (!v.is_string()) throw std::invalid_argument("layout must be a string");
      actions::setClipLayout(s, v.get<std::string>());
    } else if (key == "fps") {
      actions::setClipFps(s, optionalNumber(v, key).value_or(0.0));
    } else if (key == "person") {
      if (!v.is_number_integer()) throw std::invalid_argument("person must be a whole number");
      actions::setClipPerson(s, v.get<int>());
    } else if (key == "calibration") {
      if (!v.is_null() && !v.is_string()) throw std::invalid_argument("calibration must be a file's path or null");
      const auto camera = a.argument.find("calibration_camera");
      if (camera != a.argument.end() && !camera->is_string())
        throw std::invalid_argument("calibration_camera must be a camera's name");
      actions::setClipCalibration(s, v.is_null() ? std::filesystem::path() : std::filesystem::path(v.get<std::string>()),
                                  camera == a.argument.end() ? "" : camera->get<std::string>());
    } else if (key == "calibration_camera") {
      if (!a.argument.contains("calibration")) throw std::invalid_argument("calibration_camera goes with calibration");
    } else if (key == "image_size") {
      if (!v.is_null() && !v.is_string()) throw std::invalid_argument("image_size must be \"WxH\" or null");
      actions::setClipImageSize(s, v.is_null() ? std::nullopt
                                               : std::optional(parseKeypointImageSize(v.get<std::string>(), "image_size")));
    } else {
      throw std::invalid_argument(
          "unknown clip setting \"" + key +
          "\" (known: focal_px, azimuth_deg, elevation_deg, hold_to_horizon, layout, fps, person, image_size, "
          "calibration, calibration_camera)");
    }
  }
}

}  // namespace ew::ui::script_args
