#pragma once
// Building a model from data as the `build` command does (METHOD §4): load the walkers,
// build the eigenwalker model, and measure the MAP σ² that reconstructs the model's own
// walkers best (a leave-one-subject-out sweep, stored in the model: model.h
// Sigma2Optimum). The default model of real walkers is this over
// ../shared/data/walkers.csv (assets/README.md); its staleness test rebuilds it here.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/eigenwalker/model.h"
#include "core/experiments/leave_one_out.h"
#include "core/io/load_trial.h"

namespace ew {

// The σ² sweep run at build time: the evaluation's σ² grid (experiments.h,
// defaultSigma2GridMm2: 17 values, 1…5000 mm²) at every 5° from −90° to 90° (37 views),
// coarser than the evaluation's 1° grid so `build` stays quick (docs/MODEL_FORMAT.md has
// the timing).
struct Sigma2SweepPlan {
  std::vector<double> gridMm2;
  std::vector<double> anglesDeg;
};
Sigma2SweepPlan defaultBuildSigma2Plan();

// The optimum of the leave-one-subject-out sweep (experiments.h sigmaSweep: held-out
// walker projected at each angle, MAP with the model without its subject, mean E_a over
// subjects and angles; smallest wins). nullopt with fewer than 3 subjects (a fold's model
// needs 2 walkers and a direction of variation). `model` chooses N per fold as the
// evaluation does. Throws what sigmaSweep throws for a bad plan.
std::optional<Sigma2Optimum> measureSigma2Optimum(const std::vector<ExperimentWalker>& walkers,
                                                  const ModelOptions& model,
                                                  const Sigma2SweepPlan& plan, int threads);

struct ModelBuildOptions {
  ModelOptions model;
  bool measureSigma2 = true;
  Sigma2SweepPlan sigma2Plan = defaultBuildSigma2Plan();
  int threads = 1;  // the sweep's folds; the result does not depend on it
  LoadOptions load;  // how trials are read (e.g. a joint mapping file for unknown marker sets)
};

struct ModelBuildResult {
  EigenwalkerModel model;
  std::vector<std::string> warnings;  // trials skipped, fits that warned, σ² at the grid edge
  double sweepSeconds = 0.0;          // wall time of the σ² sweep (0 when not run)
};

// Loads `data` (files, folders, manifests: core/gait/dataset.h) and builds the model of
// every walker. Trial paths in the model's provenance are relative to the folder of the
// `data` entry they came from (a manifest's or a single file's folder, or the folder
// given), so a model never records where this machine keeps the data. Throws
// Error(BadData) naming the first data path when fewer than 2 walkers are usable, and what
// loading and buildModel throw.
ModelBuildResult buildModelFromData(const std::vector<std::filesystem::path>& data,
                                    const ModelBuildOptions& options = {});

}  // namespace ew
