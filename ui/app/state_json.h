#pragma once
// What the viewer holds, as JSON: the data (label, walkers, files, generation, whether the
// models are built), the selection and the reconstruction settings, the view settings, the
// error banner and the log. Written by the script action "export_state" so that tests can
// check that an action changed what it should, and nothing else.

#include <nlohmann/json.hpp>

namespace ew::ui {

struct AppState;

nlohmann::json stateJson(const AppState& s);

}  // namespace ew::ui
