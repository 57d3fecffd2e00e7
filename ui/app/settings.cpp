#include "ui/app/settings.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/io/atomic_write.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/theme.h"

namespace ew::ui {

std::optional<std::filesystem::path> settingsFile() {
  const char* xdg = std::getenv("XDG_CONFIG_HOME");
  if (xdg && *xdg) return std::filesystem::path(xdg) / "eigenwalker" / "settings.json";
  const char* home = std::getenv("HOME");
  if (home && *home) return std::filesystem::path(home) / ".config" / "eigenwalker" / "settings.json";
  return std::nullopt;
}

bool settingsDisabledByEnvironment() {
  const char* v = std::getenv("EIGENWALKER_NO_SETTINGS");
  return v && *v && std::string(v) != "0";
}

nlohmann::json settingsToJson(const Settings& st) {
  nlohmann::json j;
  j["version"] = 1;
  if (st.theme) j["theme"] = *st.theme;
  if (st.uiScale) j["ui_scale"] = *st.uiScale;
  if (st.windowWidth && st.windowHeight) j["window"] = {{"width", *st.windowWidth}, {"height", *st.windowHeight}};
  nlohmann::json overlays = nlohmann::json::object();
  for (const auto& [name, on] : st.overlays) overlays[name] = on;
  j["overlays"] = overlays;
  j["data"] = st.data;
  j["recent"] = st.recent;
  if (st.exportFolder) j["export_folder"] = *st.exportFolder;
  return j;
}

namespace {

std::vector<std::string> stringList(const nlohmann::json& j, const char* key) {
  std::vector<std::string> out;
  if (j.contains(key) && j[key].is_array())
    for (const auto& v : j[key])
      if (v.is_string()) out.push_back(v.get<std::string>());
  return out;
}

}  // namespace

Settings settingsFromJson(const nlohmann::json& j) {
  Settings st;
  if (!j.is_object()) return st;
  if (j.contains("theme") && j["theme"].is_string()) st.theme = j["theme"].get<std::string>();
  if (j.contains("ui_scale") && j["ui_scale"].is_number()) st.uiScale = j["ui_scale"].get<float>();
  if (j.contains("window") && j["window"].is_object()) {
    const auto& w = j["window"];
    if (w.contains("width") && w["width"].is_number_integer() && w.contains("height") &&
        w["height"].is_number_integer()) {
      st.windowWidth = w["width"].get<int>();
      st.windowHeight = w["height"].get<int>();
    }
  }
  if (j.contains("overlays") && j["overlays"].is_object())
    for (const auto& [name, v] : j["overlays"].items())
      if (v.is_boolean()) st.overlays.emplace_back(name, v.get<bool>());
  st.data = stringList(j, "data");
  st.recent = stringList(j, "recent");
  if (j.contains("export_folder") && j["export_folder"].is_string())
    st.exportFolder = j["export_folder"].get<std::string>();
  return st;
}

Settings readSettings(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return {};
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read the settings");
  try {
    nlohmann::json j;
    in >> j;
    return settingsFromJson(j);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": settings are not valid JSON (" + e.what() + "); using defaults");
  }
}

void writeSettings(const std::filesystem::path& file, const Settings& settings) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  const std::string text = settingsToJson(settings).dump(2) + "\n";
  try {
    writeFileAtomically(file, [&text](std::ostream& out) { out << text; });
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("cannot save the settings: ") + e.what());
  }
}

void applySettings(AppState& s, const Settings& st) {
  if (st.theme) {
    try {
      s.view.theme = themeFromName(*st.theme);
    } catch (const std::exception& e) {
      s.log.warning(std::string("settings: ") + e.what());
    }
  }
  if (st.uiScale && *st.uiScale >= 0.5f && *st.uiScale <= 4.0f) s.view.uiScale = *st.uiScale;
  for (const auto& [name, on] : st.overlays) {
    try {
      actions::setOverlay(s, name, on);
    } catch (const std::exception& e) {
      s.log.warning(std::string("settings: ") + e.what());
    }
  }
  for (const auto& r : st.recent) s.recentPaths.emplace_back(r);
  if (st.exportFolder && st.exportFolder->size() < s.panels.exports.folder.size()) {
    std::copy(st.exportFolder->begin(), st.exportFolder->end(), s.panels.exports.folder.begin());
    s.panels.exports.folder[st.exportFolder->size()] = '\0';
  }
}

Settings captureSettings(const AppState& s, int windowWidth, int windowHeight) {
  Settings st;
  st.theme = themeName(s.view.theme);
  st.uiScale = s.view.uiScale;
  st.windowWidth = windowWidth;
  st.windowHeight = windowHeight;
  for (const auto& name : actions::overlayNames()) st.overlays.emplace_back(name, actions::overlay(s, name));
  for (const auto& p : s.doc.sourcePaths) st.data.push_back(p.string());
  for (const auto& p : s.recentPaths) st.recent.push_back(p.string());
  st.exportFolder = std::string(s.panels.exports.folder.data());
  return st;
}

}  // namespace ew::ui
