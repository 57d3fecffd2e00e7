// `eigenwalker-cli build --data PATH… [--components N | --variance 0.95] [--no-sigma2-sweep]
//  [--threads N] --out MODEL`: loads the walkers, builds the eigenwalker model (METHOD §4),
// measures the MAP σ² optimum on its own walkers (leave-one-subject-out sweep) and saves
// both (docs/MODEL_FORMAT.md).
// `build --engine snippet --data PATH… [--clusters M] [--components Q] [--em-iterations K]
//  --out PRIOR.ewsp`: the snippet engine's prior (core/snippet, docs/SNIPPET_FORMAT.md)
// learnt from every trial's snippets, overground.
#include <chrono>
#include <iomanip>
#include <iostream>
#include <thread>

#include "app/cli/checks.h"
#include "app/cli/commands.h"
#include "core/common/errors.h"
#include "core/eigenwalker/model_file.h"
#include "core/engines/engine.h"
#include "core/experiments/model_build.h"
#include "core/experiments/snippet_experiment.h"
#include "core/snippet/snippet_file.h"

namespace ew::cli {
namespace {

struct BuildArgs {
  std::vector<std::string> data;
  std::string out;
  int components = 0;
  double variance = 0.0;
  bool noSigma2Sweep = false;
  int threads = 0;  // 0 = hardware concurrency
  std::string mapping;  // joint mapping file (--mapping)
  std::string engine = "eigenwalker";
  int clusters = 0;       // snippet: m (0 = the default, docs/SNIPPETS.md)
  int emIterations = 0;   // snippet: EM steps after k-means
};

void printSigma2(const ModelBuildResult& r) {
  if (!r.model.sigma2Optimum) return;
  const Sigma2Optimum& s = *r.model.sigma2Optimum;
  std::cerr << std::setprecision(4) << "MAP sigma2 optimum on the model's walkers: " << s.sigma2Mm2
            << " mm2 (mean E_a " << std::setprecision(1) << std::fixed << s.meanAbsErrorMm2
            << " mm2; " << s.gridMm2.size() << " sigma2 x " << s.anglesDeg.size()
            << " angles, leave-one-subject-out, " << std::setprecision(2) << r.sweepSeconds
            << " s)\n";
  std::cerr.unsetf(std::ios::floatfield);
}

int runBuildSnippetPrior(const BuildArgs& a) {
  if (a.variance > 0 || a.noSigma2Sweep)
    throw Error(ErrorKind::BadArgument, a.variance > 0 ? "--variance" : "--no-sigma2-sweep", "",
                "applies to the eigenwalker model only (--engine eigenwalker)");
  SnippetPriorOptions options;
  if (a.clusters > 0) options.clusters = a.clusters;
  if (a.components > 0) options.components = a.components;
  options.emIterations = a.emIterations;
  LoadOptions load;
  if (!a.mapping.empty()) load.mappingFile = a.mapping;
  const Dataset dataset = loadDataset({a.data.begin(), a.data.end()}, load);
  for (const auto& w : dataset.warnings) std::cerr << "warning: " << w << "\n";
  const auto t0 = std::chrono::steady_clock::now();
  const SnippetPrior prior = trainSnippetPrior(snippetTrainingTrials(dataset), options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  saveSnippetPrior(prior, a.out);
  std::cerr << std::fixed << std::setprecision(2) << "snippet prior of " << prior.subjects.size() << " subjects: "
            << prior.trainingSnippets << " snippets of " << prior.frames << " frames at " << prior.rateHz << " Hz, "
            << prior.components.size() << " clusters, " << prior.emIterations << " EM steps (" << seconds
            << " s); wrote " << a.out << "\n";
  return 0;
}

int runBuild(const BuildArgs& a) {
  const EngineKind engine = parseEngineKind(a.engine, "--engine");
  if (engine == EngineKind::Snippet) return runBuildSnippetPrior(a);
  if (engine == EngineKind::Skeleton)
    throw Error(ErrorKind::BadArgument, "--engine", "",
                "the skeleton engine learns nothing from data (geometry and bone lengths only): there is nothing to build");
  if (a.clusters > 0 || a.emIterations > 0)
    throw Error(ErrorKind::BadArgument, a.clusters > 0 ? "--clusters" : "--em-iterations", "",
                "applies to the snippet prior only (--engine snippet)");
  ModelBuildOptions options;
  if (a.components > 0) options.model.components = a.components;
  if (a.variance > 0) options.model.varianceThreshold = a.variance;
  options.measureSigma2 = !a.noSigma2Sweep;
  if (!a.mapping.empty()) options.load.mappingFile = a.mapping;
  options.threads = a.threads > 0
                        ? a.threads
                        : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const ModelBuildResult r = buildModelFromData({a.data.begin(), a.data.end()}, options);
  for (const auto& w : r.warnings) std::cerr << "warning: " << w << "\n";
  printSigma2(r);
  saveModel(r.model, a.out);
  std::cerr << std::fixed << std::setprecision(1) << "model of " << r.model.walkerCount()
            << " walkers: " << r.model.componentCount() << " eigenwalkers, "
            << 100.0 * r.model.explainedVariance() << " % of the variance; wrote " << a.out << "\n";
  return 0;
}

}  // namespace

void addBuildCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<BuildArgs>();
  auto* cmd = app.add_subcommand("build",
                                 "Build an eigenwalker model (docs/METHOD.md §4) or, with --engine snippet, a snippet prior "
                                 "(docs/SNIPPETS.md) from walking trials and save it");
  cmd->add_option("--engine", args->engine, "eigenwalker (a .ewm model) or snippet (a .ewsp prior)")
      ->check(CLI::IsMember({"eigenwalker", "snippet", "skeleton"}))
      ->capture_default_str();
  cmd->add_option("--data", args->data, "Trial files, folders (recursive) or manifest CSVs")->required();
  cmd->add_option("--mapping", args->mapping,
                  "Joint mapping file (JSON, docs/FORMATS.md) for marker files whose set the "
                  "program does not know");
  cmd->add_option("--out", args->out, "Model file to write (atomically)")->required();
  auto* components = cmd->add_option("--components", args->components, "Number of eigenwalkers (at most walkers - 1); snippet: PCA components per cluster (default 50)")
                         ->check(finiteIn(1, 100000));
  auto* variance = cmd->add_option("--variance", args->variance,
                                   "Smallest N reaching this share of the variance (default 0.95)")
                       ->check(finiteIn(0.01, 1.0));
  components->excludes(variance);
  cmd->add_option("--clusters", args->clusters, "Snippet prior: mixture components m (default 8, docs/SNIPPETS.md)")
      ->check(finiteIn(1, 256));
  cmd->add_option("--em-iterations", args->emIterations,
                  "Snippet prior: EM steps on the mixture after k-means (default 0: the paper's clustering)")
      ->check(finiteIn(0, 1000));
  cmd->add_flag("--no-sigma2-sweep", args->noSigma2Sweep,
                "Do not measure the MAP sigma2 optimum (reconstruct then falls back to 70 mm2)");
  cmd->add_option("--threads", args->threads,
                  "Worker threads of the sigma2 sweep (default: all cores)")
      ->check(finiteIn(1, 1024));
  cmd->callback([args, &exitCode] { exitCode = runBuild(*args); });
}

}  // namespace ew::cli
