#include "ui/app/population.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>

#include "core/common/errors.h"
#include "core/eigenwalker/joint_completion.h"
#include "core/gait/missing_joints.h"
#include "core/synth/population.h"
#include "ui/app/background_job.h"

namespace ew::ui {

int Population::findWalker(const std::string& name) const {
  for (int i = 0; i < walkerCount(); ++i) {
    const auto& w = walkers[static_cast<std::size_t>(i)];
    if (w.subject == name || w.id == name) return i;
  }
  return -1;
}

namespace {

void requireEnough(const Population& p, const std::string& what, int minWalkers) {
  if (p.walkerCount() >= minWalkers) return;
  std::string detail;
  for (const auto& w : p.warnings) detail += "\n  " + w;
  if (p.walkerCount() == 0) throw Error(ErrorKind::BadData, what, "", "no usable walker" + detail);
  throw Error(ErrorKind::BadData, what, "",
              "only " + std::to_string(p.walkerCount()) +
                  " usable walker(s); a leave-one-out model needs at least " +
                  std::to_string(kMinPopulation) + " (open a folder, a manifest or several files)" +
                  detail);
}

}  // namespace

namespace {

// Trials that lack joints, completed from `model` (the joints flagged modelEstimated and no
// longer missing, so that they make walkers); without a model they stay as they are and
// makeWalkers leaves them out with its warning.
void completeTrials(Dataset& dataset, const EigenwalkerModel* model,
                    std::vector<std::string>& warnings) {
  if (!model) return;
  auto& trials = dataset.trials;
  for (auto it = trials.begin(); it != trials.end();) {
    it->trial.joints.missing = missingJointsOf(it->trial.joints);
    if (!anyJoint(it->trial.joints.missing)) {
      ++it;
      continue;
    }
    try {
      CompletedTrial done = completeWalkingTrial(it->trial, *model);
      done.trial.joints.missing = {};
      it->trial = std::move(done.trial);
      ++it;
    } catch (const std::exception& e) {
      warnings.push_back(it->info.file + ": " + e.what());
      it = trials.erase(it);
    }
  }
}

// Walkers and their facts from a loaded dataset (METHOD §3-4: fit, average per subject).
Population populationFromDataset(Dataset dataset, std::string label, const LoadProgress& progress,
                                 int minWalkers, const EigenwalkerModel* completion = nullptr) {
  Population p;
  p.label = std::move(label);
  p.warnings = dataset.warnings;
  if (progress) progress(0, 1, "fitting walkers");
  completeTrials(dataset, completion, p.warnings);
  p.walkers = makeWalkers(dataset, &p.warnings);
  for (const auto& w : p.walkers) {
    WalkerFacts f;
    f.strideHz = w.fit.omegaRadS / (2.0 * std::numbers::pi);
    f.h1Share = w.fit.h1Share;
    f.h2Share = w.fit.h2Share;
    std::array<bool, kJointCount> estimated{};
    for (const auto& t : dataset.trials) {
      if (!isTrialOf(w, t.info)) continue;
      ++f.trials;
      f.format = t.trial.joints.format;
      for (std::size_t j = 0; j < estimated.size(); ++j) {
        estimated[j] = estimated[j] || t.trial.joints.estimated[j];
        f.modelEstimated[j] = f.modelEstimated[j] || t.trial.modelEstimated[j];
      }
    }
    f.speedMps = walkerSpeedMps(dataset, w);
    for (std::size_t j = 0; j < estimated.size(); ++j)
      if (estimated[j]) f.estimatedJoints.emplace_back(kJointNames[j]);
    p.facts.push_back(std::move(f));
  }
  if (progress) progress(1, 1, "fitted");
  requireEnough(p, p.label, minWalkers);
  return p;
}

}  // namespace

std::string fileKey(const std::filesystem::path& file) {
  std::error_code ec;
  const auto abs = std::filesystem::weakly_canonical(file, ec);
  return (ec ? std::filesystem::absolute(file).lexically_normal() : abs).string();
}

bool hasModelEstimated(const Population& p) {
  return std::any_of(p.facts.begin(), p.facts.end(), [](const WalkerFacts& f) {
    return std::any_of(f.modelEstimated.begin(), f.modelEstimated.end(), [](bool b) { return b; });
  });
}

Population loadPopulation(const std::vector<std::filesystem::path>& paths,
                          const LoadProgress& progress, const FileOverrides& overrides,
                          int minWalkers, std::shared_ptr<const EigenwalkerModel> completion) {
  // "walkers.csv", "a.c3d, b.c3d": what the header shows.
  const auto labelOf = [](const std::vector<std::filesystem::path>& items) {
    std::string label;
    for (const auto& path : items) {
      if (!label.empty()) label += ", ";
      label += path.filename().empty() ? path.string() : path.filename().string();
    }
    return label;
  };
  const std::string label = labelOf(paths);
  const LoadOptionsFn optionsFor = [&overrides](const std::filesystem::path& file) {
    if (overrides.empty()) return LoadOptions{};
    const auto it = overrides.find(fileKey(file));
    return it == overrides.end() ? LoadOptions{} : it->second;
  };
  if (paths.size() <= 1)
    return populationFromDataset(loadDatasetPerFile(paths, optionsFor, progress), label, progress,
                                 minWalkers, completion.get());
  // "x.asf + y.amc" dropped together is the trial y (its skeleton opens with it), not y
  // twice plus every motion beside x.
  const std::vector<std::filesystem::path> itemPaths = withoutSkeletonsOfGivenMotions(paths);
  // Several items: each on its own, so that one bad file does not lose the others. Progress
  // runs over the items, each item's share split by its own files.
  constexpr int kStepsPerItem = 1000;
  const int items = static_cast<int>(itemPaths.size());
  Dataset all;
  std::vector<std::string> skipped;
  std::vector<std::filesystem::path> loaded;
  for (int i = 0; i < items; ++i) {
    ProgressFn itemProgress;
    if (progress) {
      itemProgress = [&progress, i, items](int done, int total, const std::string& what) {
        const long long share =
            total > 0 ? static_cast<long long>(done) * kStepsPerItem / total : 0;
        progress(i * kStepsPerItem + static_cast<int>(share), items * kStepsPerItem, what);
      };
    }
    try {
      Dataset one =
          loadDatasetPerFile({itemPaths[static_cast<std::size_t>(i)]}, optionsFor, itemProgress);
      std::move(one.trials.begin(), one.trials.end(), std::back_inserter(all.trials));
      std::move(one.warnings.begin(), one.warnings.end(), std::back_inserter(all.warnings));
      loaded.push_back(itemPaths[static_cast<std::size_t>(i)]);
    } catch (const JobCancelled&) {
      throw;
    } catch (const std::exception& e) {
      skipped.emplace_back(e.what());
      all.warnings.push_back(std::string("skipped: ") + e.what());
    }
  }
  // The label names what loaded (the skipped items are in the warnings).
  Population p = populationFromDataset(std::move(all), loaded.empty() ? label : labelOf(loaded),
                                       progress, minWalkers, completion.get());
  p.skippedItems = std::move(skipped);
  return p;
}

Population defaultPopulation(const LoadProgress& progress) {
  // core/synth's embedded default population (docs/SYNTHETIC.md): simulated trials that go
  // through the same preparation and Fourier fit as recorded data.
  if (progress) progress(0, 1, "simulating the synthetic population");
  const Dataset dataset = syntheticDataset();
  return populationFromDataset(dataset, "synthetic default population", progress, kMinPopulation);
}

}  // namespace ew::ui
