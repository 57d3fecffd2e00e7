#pragma once
// Settings that persist between runs (docs/VIEWER.md "Settings"): theme, UI scale, overlays,
// the last data opened and recent files, the export folder, the window size. One JSON file,
// $XDG_CONFIG_HOME/eigenwalker/settings.json (else ~/.config/eigenwalker/settings.json),
// written atomically when the viewer exits. --no-settings or EIGENWALKER_NO_SETTINGS=1
// (any non-empty value but "0") turns reading and writing off, for hermetic tests/scripts.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ew::ui {

struct AppState;

struct Settings {
  std::optional<std::string> theme;             // "dark", "light", "projector"
  std::optional<float> uiScale;
  std::optional<int> windowWidth, windowHeight;  // screen coordinates
  std::vector<std::pair<std::string, bool>> overlays;  // by overlay name (actions::overlayNames)
  std::vector<std::string> data;                // the paths last opened (empty: the synthetic default)
  std::vector<std::string> recent;              // recently opened files / folders, newest first
  std::optional<std::string> exportFolder;
};

// The settings file, or nothing when neither XDG_CONFIG_HOME nor HOME is set.
std::optional<std::filesystem::path> settingsFile();
// True when EIGENWALKER_NO_SETTINGS is set to anything but "" or "0".
bool settingsDisabledByEnvironment();

// Reads the file; a missing file gives empty settings. Throws std::runtime_error naming the
// file for unreadable or malformed JSON (the app logs it and starts with defaults).
Settings readSettings(const std::filesystem::path& file);
// Writes atomically, creating the folder. Throws std::runtime_error on failure.
void writeSettings(const std::filesystem::path& file, const Settings& settings);

nlohmann::json settingsToJson(const Settings& settings);
Settings settingsFromJson(const nlohmann::json& json);  // unknown keys and wrong types ignored

// Between the app state and the settings (values the command line gave win; the app decides).
void applySettings(AppState& s, const Settings& settings);
Settings captureSettings(const AppState& s, int windowWidth, int windowHeight);

}  // namespace ew::ui
