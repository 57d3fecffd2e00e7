#pragma once
// Opening data (docs/VIEWER.md, "Models and walkers"): the open under way, the one waiting
// for it, the population being read and its models being built, and what was shown before.
// The feature's whole state is LoadingFeature (AppState::loading); its actions are
// ui/app/load_actions.h. What went wrong is said by the notices (AppState::jobs, notice_actions.h).

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ui/app/background_job.h"
#include "ui/app/document.h"
#include "ui/app/model_set.h"
#include "ui/app/population.h"

namespace ew::ui {

// An open: the paths to load (empty = the synthetic default) and the dropped items that were
// left out before loading (not motion capture, missing), each with its reason.
struct OpenRequest {
  std::vector<std::filesystem::path> paths;
  std::vector<std::string> refused;
  std::vector<std::filesystem::path> named;  // every item the user named (empty: `paths`)
  // The population loaded is shown with the model held (a .ewm opened with nothing else
  // loaded: the synthetic walkers are inspected against it) instead of its own.
  bool keepModel = false;
};

// The data shown before a load replaced it, kept until the new data's models are built: a
// model build that fails puts it back.
struct LoadedData {
  std::shared_ptr<const Population> population;
  std::shared_ptr<const ModelSet> models;
  std::vector<std::filesystem::path> sourcePaths;
  int walker = 0;
  std::vector<double> editedSd, exploreSd;
  ModelSource modelSource = ModelSource::Population;
};

// Everything the viewer keeps of opening data, in one place. What is loaded is the Document's
// (population, models, source paths): this is only the work of getting there.
struct LoadingFeature {
  BackgroundJob<std::shared_ptr<const Population>> population;  // reading the files
  BackgroundJob<std::shared_ptr<const ModelSet>> models;         // then building their models
  OpenRequest request;                   // the open under way (or the last one)
  std::optional<OpenRequest> pending;    // one requested while a load ran: started after it
  std::optional<LoadedData> before;      // until the models of the new data are built

  bool busy() const { return population.running() || models.running() || pending.has_value(); }
};

}  // namespace ew::ui
