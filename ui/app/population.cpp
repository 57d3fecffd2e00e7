#include "ui/app/population.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/common/errors.h"
#include "core/engine/synthetic_walkers.h"

namespace ew::ui {

int Population::findWalker(const std::string& name) const {
  for (int i = 0; i < walkerCount(); ++i) {
    const auto& w = walkers[static_cast<std::size_t>(i)];
    if (w.subject == name || w.id == name) return i;
  }
  return -1;
}

namespace {

void requireEnough(const Population& p, const std::string& what) {
  if (p.walkerCount() < 3) {
    std::string detail;
    for (const auto& w : p.warnings) detail += "\n  " + w;
    throw Error(ErrorKind::BadData, what, "",
                "only " + std::to_string(p.walkerCount()) +
                    " usable walker(s); a leave-one-out model needs at least 3" + detail);
  }
}

}  // namespace

Population loadPopulation(const std::vector<std::filesystem::path>& paths,
                          const LoadProgress& progress) {
  Population p;
  for (const auto& path : paths) {
    if (!p.label.empty()) p.label += ", ";
    p.label += path.filename().empty() ? path.string() : path.filename().string();
  }
  Dataset dataset = loadDataset(paths, {}, progress);
  p.warnings = dataset.warnings;
  if (progress) progress(0, 1, "fitting walkers");
  p.walkers = makeWalkers(dataset, &p.warnings);
  for (const auto& w : p.walkers) {
    WalkerFacts f;
    f.strideHz = w.fit.omegaRadS / (2.0 * std::numbers::pi);
    f.h1Share = w.fit.h1Share;
    f.h2Share = w.fit.h2Share;
    double speedSum = 0.0;
    int speedCount = 0;
    std::array<bool, kJointCount> estimated{};
    for (const auto& t : dataset.trials) {
      if (t.info.subject != w.subject || t.info.condition != w.condition) continue;
      if (std::find(w.files.begin(), w.files.end(), t.info.file) == w.files.end()) continue;
      ++f.trials;
      f.format = t.trial.joints.format;
      if (t.trial.speedMps > 0.0) {
        speedSum += t.trial.speedMps;
        ++speedCount;
      }
      for (int j = 0; j < kJointCount; ++j)
        estimated[static_cast<std::size_t>(j)] =
            estimated[static_cast<std::size_t>(j)] || t.trial.joints.estimated[static_cast<std::size_t>(j)];
    }
    if (speedCount > 0) f.speedMps = speedSum / speedCount;
    for (int j = 0; j < kJointCount; ++j)
      if (estimated[static_cast<std::size_t>(j)])
        f.estimatedJoints.emplace_back(kJointNames[static_cast<std::size_t>(j)]);
    p.facts.push_back(std::move(f));
  }
  requireEnough(p, p.label);
  return p;
}

Population defaultPopulation(const LoadProgress& progress) {
  // The synthetic population of core/engine/synthetic_walkers.h: 24 walkers, each
  // phase-aligned, with stride frequencies spread around 0.9 Hz.
  constexpr int kCount = 24;
  if (progress) progress(0, 1, "synthesising the default population");
  const Eigen::MatrixXd w = syntheticWalkerSet(kCount, 20070501u);
  Population p;
  p.label = "synthetic default population";
  for (int r = 0; r < kCount; ++r) {
    Walker walker;
    char name[16];
    std::snprintf(name, sizeof name, "SYN%02d", r + 1);
    walker.subject = name;
    walker.condition = "synthetic";
    walker.id = walker.subject + "/" + walker.condition;
    walker.source = "synthetic";
    walker.fit.w = w.col(r);
    const double strideHz = 0.82 + 0.16 * std::fmod(0.618034 * (r + 1), 1.0);
    walker.fit.omegaRadS = 2.0 * std::numbers::pi * strideHz;
    walker.fit.phaseRad = 0.0;
    walker.fit.omegaSource = "synthetic";
    WalkerFacts f;
    f.format = "synthetic";
    f.strideHz = strideHz;
    f.trials = 1;
    p.facts.push_back(f);
    p.walkers.push_back(std::move(walker));
  }
  if (progress) progress(1, 1, "synthesised");
  return p;
}

}  // namespace ew::ui
