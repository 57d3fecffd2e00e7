// `eigenwalker-cli build --data PATH… [--components N | --variance 0.95] --out MODEL`:
// loads the walkers, builds the eigenwalker model (SPEC §4) and saves it
// (docs/MODEL_FORMAT.md).
#include <iomanip>
#include <iostream>

#include "app/cli/commands.h"
#include "core/common/errors.h"
#include "core/engine/model_file.h"
#include "core/engine/walker_set.h"
#include "core/gait/dataset.h"

namespace ew::cli {
namespace {

struct BuildArgs {
  std::vector<std::string> data;
  std::string out;
  int components = 0;
  double variance = 0.0;
};

int runBuild(const BuildArgs& a) {
  ModelOptions options;
  if (a.components > 0) options.components = a.components;
  if (a.variance > 0) options.varianceThreshold = a.variance;
  const std::vector<std::filesystem::path> paths(a.data.begin(), a.data.end());
  const Dataset dataset = loadDataset(paths);
  std::vector<std::string> warnings = dataset.warnings;
  const std::vector<Walker> walkers = makeWalkers(dataset, &warnings);
  for (const auto& w : warnings) std::cerr << "warning: " << w << "\n";
  if (walkers.size() < 2) {
    throwBadData(a.data.front(), "", "a model needs at least 2 usable walkers, got " + std::to_string(walkers.size()));
  }
  const EigenwalkerModel model = buildModel(walkers, options);
  saveModel(model, a.out);
  std::cerr << std::fixed << std::setprecision(1) << "model of " << model.walkerCount() << " walkers: "
            << model.componentCount() << " eigenwalkers, " << 100.0 * model.explainedVariance()
            << " % of the variance; wrote " << a.out << "\n";
  return 0;
}

}  // namespace

void addBuildCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<BuildArgs>();
  auto* cmd = app.add_subcommand("build", "Build an eigenwalker model (SPEC §4) from walking trials and save it");
  cmd->add_option("--data", args->data, "Trial files, folders (recursive) or manifest CSVs")->required();
  cmd->add_option("--out", args->out, "Model file to write (atomically)")->required();
  auto* components = cmd->add_option("--components", args->components, "Number of eigenwalkers (at most walkers - 1)")
                         ->check(CLI::Range(1, 100000));
  auto* variance = cmd->add_option("--variance", args->variance,
                                   "Smallest N reaching this share of the variance (default 0.95)")
                       ->check(CLI::Range(0.01, 1.0));
  components->excludes(variance);
  cmd->callback([args, &exitCode] { exitCode = runBuild(*args); });
}

}  // namespace ew::cli
