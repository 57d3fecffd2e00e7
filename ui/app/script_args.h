#pragma once
// Reading script actions' arguments (script_actions.cpp): each throws std::invalid_argument
// saying what the action expects.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "ui/app/script.h"

namespace ew::ui {
struct AppState;
}

namespace ew::ui::script_args {

// The `mouse` action's button: "left", "right" or "middle".
std::size_t mouseButton(const nlohmann::json& v);
// {"at": [x, y]} (window pixels, as a screenshot's), {"press": B}, {"release": B},
// {"wheel": notches} (up is positive), {"away": true}; several keys apply in that order.
void applyMouse(AppState& s, const nlohmann::json& arg);
double number(const ScriptAction& a);
bool boolean(const ScriptAction& a);
std::string text(const ScriptAction& a);
// A path string, or {"path": P, "cycles": N}.
std::pair<std::filesystem::path, std::optional<double>> pathAndCycles(const ScriptAction& a);
double numberField(const nlohmann::json& o, const char* key, double fallback);
// The paths of "open" (a path, a list, or null: none) and "drop" (a list).
std::vector<std::filesystem::path> pathList(const ScriptAction& a);
int wholeNumber(const ScriptAction& a);
// {"mark_joints": {"head": [x, y], …}}: each joint placed on the frame shown, as clicks would
// (video pixels, x right, y down), each an edit of its own.
void markJoints(AppState& s, const ScriptAction& a);
// {"set_clip": {"focal_px": F | null, "azimuth_deg": A | null, "elevation_deg": E | null,
//  "layout": "BODY_25B" | "", "fps": 30 | 0, "person": 1 | -1, "image_size": "1920x1080" | null}}:
// null / "" / 0 / -1 estimate, guess or take the default again.
void applyClipSettings(AppState& s, const ScriptAction& a);

}  // namespace ew::ui::script_args
