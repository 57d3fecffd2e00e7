#pragma once
// The document's data: the walkers the viewer shows and builds its models from, with
// the facts the subject list displays. Loaded from files (a manifest, a folder, files)
// or the synthetic default population.

#include <array>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/eigenwalker/model.h"
#include "core/eigenwalker/walker_set.h"
#include "core/gait/dataset.h"

namespace ew::ui {

struct WalkerFacts {
  std::string format;                    // "C3D", "BVH", … or "synthetic"
  double strideHz = 0.0;                 // ω / 2π
  std::optional<double> speedMps;        // mean over the trials (absent: unknown / treadmill)
  std::vector<std::string> estimatedJoints;  // joints estimated rather than measured
  // Joints the trial's marker set lacks, filled in from a model (core/eigenwalker/
  // joint_completion.h): drawn differently, their errors reported apart.
  std::array<bool, kJointCount> modelEstimated{};
  int trials = 0;
  double h1Share = 0.0, h2Share = 0.0;   // variance shares of the two harmonics
};

struct Population {
  std::string label;                     // what was opened, for the header
  std::vector<Walker> walkers;
  std::vector<WalkerFacts> facts;        // one per walker
  std::vector<std::string> warnings;     // files skipped, fits that failed, …
  // Of several items opened together, those that did not load, each with its reason (also
  // in `warnings`): the viewer says so rather than failing the whole open.
  std::vector<std::string> skippedItems;

  int walkerCount() const { return static_cast<int>(walkers.size()); }
  // Index of the walker whose subject or id is `name`; -1 if none.
  int findWalker(const std::string& name) const;
};

// Walkers a leave-one-out population needs (each held out, at least 2 remain).
inline constexpr int kMinPopulation = 3;

// Reports (done, total, what) from the loading thread.
using LoadProgress = ProgressFn;

// Per-file load options (unit and frame-rate overrides), keyed by fileKey(path).
using FileOverrides = std::map<std::string, LoadOptions>;
// The key of a file in FileOverrides: its absolute, normalised path.
std::string fileKey(const std::filesystem::path& file);

// Loads and fits every trial the paths name (with each file's overrides). One path loads as
// core's loadDatasetPerFile loads it (a file named on its own that fails is the error). Of
// several paths (files and folders dropped together), one that fails is skipped with its
// reason in `skippedItems` and `warnings`, as a bad file inside a folder is. Throws ew::Error
// (or std::exception) when fewer than `minWalkers` usable walkers remain (kMinPopulation for
// a leave-one-out population; 1 for walkers to inspect against a model the viewer holds).
// Trials that lack joints (a lower-body marker set) are completed from `completion` when
// given (their walkers' facts flag the joints), and left out with a warning otherwise.
Population loadPopulation(const std::vector<std::filesystem::path>& paths,
                          const LoadProgress& progress = {}, const FileOverrides& overrides = {},
                          int minWalkers = kMinPopulation,
                          std::shared_ptr<const EigenwalkerModel> completion = nullptr);
// True when a walker of `p` has joints estimated from a model.
bool hasModelEstimated(const Population& p);

// The synthetic default population (no recorded data needed).
Population defaultPopulation(const LoadProgress& progress = {});

}  // namespace ew::ui
