#include "core/experiments/model_build.h"

#include <chrono>
#include <cmath>

#include "core/common/errors.h"
#include "core/common/wall_time.h"
#include "core/eigenwalker/walker_set.h"
#include "core/experiments/experiments.h"
#include "core/gait/dataset.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

// [SECTION] Paths in provenance

// The folder a data argument's relative trial paths are read against.
fs::path dataRoot(const fs::path& entry) {
  std::error_code ec;
  return fs::is_directory(entry, ec) ? entry : entry.parent_path();
}

// `file` relative to the first data root that holds it (lexically: the loaders keep the
// paths as given), else its file name alone: never an absolute path of this machine.
std::string relativeToData(const std::string& file, const std::vector<fs::path>& data) {
  const fs::path f(file);
  for (const auto& entry : data) {
    const fs::path root = dataRoot(entry);
    const fs::path rel = f.lexically_normal().lexically_relative(root.lexically_normal());
    if (!rel.empty() && *rel.begin() != "..") return rel.generic_string();
  }
  return f.filename().generic_string();
}

std::string dataNames(const std::vector<fs::path>& data) {
  std::string names;
  for (const auto& entry : data) {
    const fs::path name = entry.lexically_normal().filename();
    names +=
        (names.empty() ? "" : ", ") + (name.empty() ? std::string(".") : name.generic_string());
  }
  return names;
}

// [SECTION] σ² optimum

std::string formatAngles(const std::vector<double>& a) {
  if (a.empty()) return "no angles";
  return std::to_string(a.size()) + " view angles from " +
         std::to_string(static_cast<int>(std::lround(a.front()))) + " to " +
         std::to_string(static_cast<int>(std::lround(a.back()))) + " deg";
}

}  // namespace

Sigma2SweepPlan defaultBuildSigma2Plan() {
  Sigma2SweepPlan plan;
  plan.gridMm2 = defaultSigma2GridMm2();
  for (int d = -90; d <= 90; d += 5) plan.anglesDeg.push_back(d);
  return plan;
}

std::optional<Sigma2Optimum> measureSigma2Optimum(const std::vector<ExperimentWalker>& walkers,
                                                  const ModelOptions& model,
                                                  const Sigma2SweepPlan& plan, int threads) {
  if (walkerSubjects(walkers).size() < 3) return std::nullopt;
  EvaluationOptions o;
  o.anglesDeg = plan.anglesDeg;
  o.sigma2GridMm2 = plan.gridMm2;
  o.lsq = false;
  o.model = model;
  o.threads = threads;
  const std::vector<Fold> folds = buildFolds(walkers, model, threads);
  const std::vector<SigmaSweepRow> rows = sigmaSweep(walkers, folds, o);
  const SigmaSweepRow* best = nullptr;
  for (const auto& r : rows) {
    if (r.method == "map" && (!best || r.meanAbsErrorMm2 < best->meanAbsErrorMm2)) best = &r;
  }
  if (!best) return std::nullopt;
  Sigma2Optimum s;
  s.sigma2Mm2 = best->sigma2Mm2;
  s.meanAbsErrorMm2 = best->meanAbsErrorMm2;
  s.gridMm2 = plan.gridMm2;
  s.anglesDeg = plan.anglesDeg;
  s.criterion = "smallest mean E_a (docs/METHOD.md §7, mm2) of MAP over subjects and " +
                formatAngles(plan.anglesDeg) +
                ", leave-one-subject-out (each held-out walker reconstructed by the model without "
                "its subject)";
  s.atGridEdge = plan.gridMm2.size() > 1 &&
                 (s.sigma2Mm2 == plan.gridMm2.front() || s.sigma2Mm2 == plan.gridMm2.back());
  return s;
}

ModelBuildResult buildModelFromData(const std::vector<fs::path>& data,
                                    const ModelBuildOptions& options) {
  if (data.empty())
    throw Error(ErrorKind::BadArgument, "--data", "", "no data to build a model from");
  const Dataset dataset = loadDataset(data, options.load);
  ModelBuildResult result;
  result.warnings = dataset.warnings;
  std::vector<Walker> walkers = makeWalkers(dataset, &result.warnings);
  if (walkers.size() < 2)
    throwBadData(data.front().string(), "",
                 "a model needs at least 2 usable walkers, got " + std::to_string(walkers.size()));
  if (options.measureSigma2) {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<ExperimentWalker> sweepWalkers = experimentWalkers(walkers, dataset);
    result.model.sigma2Optimum =
        measureSigma2Optimum(sweepWalkers, options.model, options.sigma2Plan, options.threads);
    result.sweepSeconds = secondsSince(start);
  }
  std::vector<std::optional<double>> speeds;  // matched by the trials' own paths, before they are made relative
  for (const Walker& w : walkers) speeds.push_back(walkerSpeedMps(dataset, w));
  for (Walker& w : walkers) {
    for (std::string& f : w.files) f = relativeToData(f, data);
  }
  const auto optimum = result.model.sigma2Optimum;
  result.model = buildModel(walkers, options.model);
  result.model.sigma2Optimum = optimum;
  result.model.speedsMps = std::move(speeds);
  result.model.provenance.insert(
      result.model.provenance.begin(),
      "built from " + dataNames(data) +
          " (trial paths relative to its folder): " + std::to_string(walkers.size()) + " walkers");
  if (options.measureSigma2 && !optimum)
    result.warnings.push_back(
        "sigma2 optimum not measured: fewer than 3 subjects; MAP will use the paper's 70 mm2");
  if (optimum && optimum->atGridEdge)
    result.warnings.push_back(
        "the sigma2 optimum sits at the edge of the grid: the true optimum may lie outside it");
  return result;
}

}  // namespace ew
