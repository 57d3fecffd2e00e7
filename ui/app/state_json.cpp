#include "ui/app/state_json.h"

#include <string>

#include "ui/app/app_state.h"
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
  if (d.population && d.walker >= 0 && d.walker < d.population->walkerCount()) {
    const auto& w = d.population->walkers[static_cast<std::size_t>(d.walker)];
    j["id"] = w.id;
    j["subject"] = w.subject;
  }
  return j;
}

const char* levelName(LogLevel level) {
  return level == LogLevel::Error ? "error" : level == LogLevel::Warning ? "warning" : "info";
}

}  // namespace

nlohmann::json stateJson(const AppState& s) {
  const Document& d = s.doc;
  const ViewState& v = s.view;
  nlohmann::json j;
  j["data"] = dataJson(d);
  j["walker"] = selectionJson(d);
  j["mode"] = d.mode == Mode::Reconstruct ? "reconstruct" : "explore";
  j["angle_deg"] = d.recon.alphaDeg;
  j["method"] = d.recon.estimator == Estimator::Lsq ? "lsq" : "map";
  j["sigma2_mm2"] = d.recon.sigma2Mm2;
  j["components"] = d.recon.components;
  j["unknown_angle"] = d.recon.unknownAngle;
  j["edited_sd"] = d.editedSd;
  j["explore_sd"] = d.exploreSd;
  j["view"] = {{"phase", v.playback.phase()},
               {"playing", v.playback.playing},
               {"speed", v.playback.speed},
               {"theme", themeName(v.theme)},
               {"ui_scale", v.uiScale},
               {"camera",
                {{"yaw_deg", v.camera.yawDeg},
                 {"pitch_deg", v.camera.pitchDeg},
                 {"distance_mm", v.camera.distanceMm}}},
               {"point_lights", v.overlays.pointLights}};
  j["busy"] = s.busy();
  j["failures"] = s.jobs.failures;
  j["error"] = s.jobs.lastError;
  if (s.jobs.notice) {
    const auto& n = *s.jobs.notice;
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
