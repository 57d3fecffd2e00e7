#include "core/experiments/experiments.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <mutex>
#include <numbers>
#include <random>

#include "core/engines/request.h"
#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/common/wall_time.h"
#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/projection.h"

namespace ew {
namespace {

// [SECTION] Helpers

struct Method {
  std::string name;
  EstimatorOptions estimator;
};

std::vector<Method> methods(const EvaluationOptions& o, double sigma2Mm2) {
  std::vector<Method> out;
  if (o.lsq) out.push_back({"lsq", {Estimator::Lsq, sigma2Mm2}});
  if (o.map) out.push_back({"map", {Estimator::Map, sigma2Mm2}});
  return out;
}

[[noreturn]] void optionError(const std::string& stage, const std::string& problem) {
  throw Error(ErrorKind::BadArgument, "", "", stage + ": " + problem);
}

// Every experiment's common preconditions: finite angles, and folds that index these
// walkers (folds built from another walker list would read past its end).
void checkInputs(const std::string& stage, const std::vector<ExperimentWalker>& walkers,
                 const std::vector<Fold>& folds, const EvaluationOptions& o) {
  for (double a : o.anglesDeg) {
    if (!std::isfinite(a))
      optionError(stage, "view angles must be finite, got " + std::to_string(a));
  }
  for (const Fold& f : folds) {
    for (int r : f.testWalkers) {
      if (r < 0 || static_cast<size_t>(r) >= walkers.size())
        optionError(stage, "fold '" + f.subject + "' names walker " + std::to_string(r) + " of " +
                               std::to_string(walkers.size()) + ": folds and walkers do not match");
    }
  }
}

void checkSigma2(const std::string& stage, double sigma2Mm2) {
  if (!(sigma2Mm2 >= 0.0 && std::isfinite(sigma2Mm2)))
    optionError(stage, "σ² must be finite and ≥ 0 mm², got " + std::to_string(sigma2Mm2));
}

std::vector<double> anglesOf(const EvaluationOptions& o) {
  if (!o.anglesDeg.empty()) return o.anglesDeg;
  std::vector<double> a;
  for (int d = -90; d <= 90; ++d) a.push_back(d);
  return a;
}

// Calls the user's progress function after each fold, one caller at a time.
class FoldProgress {
 public:
  FoldProgress(const EvaluationOptions& o, int total, std::string what)
      : fn_(o.progress), total_(total), what_(std::move(what)) {
    if (fn_) fn_(0, total_, what_);
  }
  void foldDone() {
    if (!fn_) return;
    std::lock_guard lock(mutex_);
    fn_(++done_, total_, what_);
  }

 private:
  const ExperimentProgressFn& fn_;
  std::mutex mutex_;
  int done_ = 0, total_;
  std::string what_;
};

template <class Row>
std::vector<Row> concat(std::vector<std::vector<Row>>&& parts) {
  std::vector<Row> out;
  for (auto& p : parts) out.insert(out.end(), std::make_move_iterator(p.begin()), std::make_move_iterator(p.end()));
  return out;
}

// Runs `fold(fold, rows)` for every fold on the options' threads, with progress, and joins
// the folds' rows in fold order (so the output does not depend on the thread count).
template <class Row, class FoldBody>
std::vector<Row> rowsOverFolds(const std::vector<Fold>& folds, const EvaluationOptions& options,
                               const std::string& what, const FoldBody& fold) {
  std::vector<std::vector<Row>> parts(folds.size());
  FoldProgress progress(options, static_cast<int>(folds.size()), what);
  parallelFor(static_cast<int>(folds.size()), options.threads, [&](int f) {
    fold(folds[static_cast<size_t>(f)], parts[static_cast<size_t>(f)]);
    progress.foldDone();
  });
  return concat(std::move(parts));
}

ViewErrorRow scoreView(const std::string& subject, const std::string& condition, double alphaDeg,
                       const std::string& method, const Eigen::VectorXd& wTrue,
                       const Eigen::VectorXd& wRec) {
  const DepthErrors e = depthErrors(wTrue, wRec, alphaDeg);
  return {subject, condition, alphaDeg, method, e.absMean, e.relMean, e.sigmaM2Mm2, mpjpe(wTrue, wRec)};
}

std::string formatLevel(double mm) {
  std::string s = std::to_string(mm);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

// Rows of ŵ (150: block, joint, u/v) that belong to hidden joints become NaN, so a test
// would notice if the reconstruction read them.
void hideJoints(Eigen::VectorXd& observed, const std::vector<int>& joints) {
  for (int b = 0; b < kFourierBlocks; ++b) {
    for (int j : joints) observed.segment(b * kDims2 + 2 * j, 2).setConstant(std::numeric_limits<double>::quiet_NaN());
  }
}

// The extensions (noise, missing joints) multiply the conditions: on a fine angle grid they
// use its multiples of 10° (−90…90 → 19 angles), which shows the same angle dependence.
std::vector<double> extensionAngles(const EvaluationOptions& o) {
  const auto all = anglesOf(o);
  if (all.size() <= 19) return all;
  std::vector<double> coarse;
  for (double a : all) {
    if (std::abs(std::remainder(a, 10.0)) < 1e-9) coarse.push_back(a);
  }
  return coarse.empty() ? all : coarse;
}

}  // namespace

// [SECTION] Names and defaults

std::string experimentName(Experiment e) {
  switch (e) {
    case Experiment::Variance: return "variance";
    case Experiment::SigmaSweep: return "sigma-sweep";
    case Experiment::KnownView: return "known-view";
    case Experiment::UnknownView: return "unknown-view";
    case Experiment::Noise: return "noise";
    case Experiment::MissingJoints: return "missing-joints";
    case Experiment::LowerBody: return "lower-body";
    case Experiment::Camera: return "camera";
    case Experiment::CameraWide: return "camera-wide";
    case Experiment::Snippet: return "snippet";
    case Experiment::SnippetClusters: return "snippet-clusters";
    case Experiment::Engines: return "engines";
    case Experiment::Semantic: return "semantic";
  }
  return "";
}

const std::vector<Experiment>& allExperiments() {
  static const std::vector<Experiment> kAll = {
      Experiment::Variance,    Experiment::SigmaSweep, Experiment::KnownView,
      Experiment::UnknownView, Experiment::Noise,      Experiment::MissingJoints,
      Experiment::LowerBody};
  return kAll;
}

std::optional<Experiment> experimentFromName(const std::string& name) {
  for (Experiment e : allExperiments()) {
    if (experimentName(e) == name) return e;
  }
  for (Experiment e : {Experiment::Camera, Experiment::CameraWide, Experiment::Snippet, Experiment::SnippetClusters, Experiment::Engines,
                       Experiment::Semantic})
    if (name == experimentName(e)) return e;
  return std::nullopt;
}

std::vector<double> defaultSigma2GridMm2() {
  return {1, 2, 5, 10, 20, 50, 70, 100, 200, 350, 500, 700, 1000, 1500, 2000, 3000, 5000};
}

std::vector<JointSet> defaultMissingJointSets() {
  std::vector<JointSet> sets;
  for (int j = 0; j < kJointCount; ++j) sets.push_back({std::string(kJointNames[static_cast<size_t>(j)]), {j}});
  const auto i = [](Joint j) { return index(j); };
  sets.push_back({"both_wrists", {i(Joint::RWrist), i(Joint::LWrist)}});
  sets.push_back({"both_arms", {i(Joint::RElbow), i(Joint::RWrist), i(Joint::LElbow), i(Joint::LWrist)}});
  sets.push_back({"both_ankles", {i(Joint::RAnkle), i(Joint::LAnkle)}});
  sets.push_back({"both_lower_legs", {i(Joint::RKnee), i(Joint::RAnkle), i(Joint::LKnee), i(Joint::LAnkle)}});
  return sets;
}

// [SECTION] Experiment 1: harmonics and eigenwalker variance

std::vector<HarmonicsRow> harmonicsTable(const std::vector<ExperimentWalker>& walkers) {
  std::vector<HarmonicsRow> rows;
  for (const auto& w : walkers) {
    rows.push_back({w.id, w.subject, w.source, w.fit.omegaRadS / (2.0 * std::numbers::pi),
                    w.fit.h1Share, w.fit.h2Share, w.fit.residualShare});
  }
  return rows;
}

std::vector<VarianceRow> varianceTable(const EigenwalkerModel& model) {
  std::vector<VarianceRow> rows;
  const double total = model.spectrum.sum();
  double cumulative = 0.0;
  for (Eigen::Index n = 0; n < model.spectrum.size(); ++n) {
    const double share = total > 0 ? model.spectrum(n) / total : 0.0;
    cumulative += share;
    rows.push_back({static_cast<int>(n) + 1, model.spectrum(n), share, cumulative});
  }
  return rows;
}

int componentsForShare(const std::vector<VarianceRow>& variance, double share) {
  for (const auto& r : variance) {
    if (r.cumulativeShare >= share - 1e-12) return r.component;
  }
  return variance.empty() ? 0 : variance.back().component;
}

// [SECTION] Experiment 2: σ² sweep (paper fig. 3)

// The sweep samples MPJPE at 24 phases per cycle (it scores 17 σ² per cell; the other
// experiments use 120): the ranking of σ² rests on E_a, MPJPE is only reported.
constexpr int kSweepMpjpeSamples = 24;

std::vector<SigmaSweepRow> sigmaSweep(const std::vector<ExperimentWalker>& walkers,
                                      const std::vector<Fold>& folds,
                                      const EvaluationOptions& options) {
  checkInputs("σ² sweep", walkers, folds, options);
  if (folds.empty()) optionError("σ² sweep", "no folds to evaluate");
  if (options.sigma2GridMm2.empty()) optionError("σ² sweep", "the σ² grid is empty");
  for (double s2 : options.sigma2GridMm2) {
    // Positive: the sweep is read on a log scale (fig. 3).
    if (!(s2 > 0.0 && std::isfinite(s2)))
      optionError("σ² sweep",
                  "grid values must be positive and finite, got " + std::to_string(s2) + " mm²");
  }
  const auto angles = anglesOf(options);
  const auto& grid = options.sigma2GridMm2;
  const size_t cols = grid.size() + 1;  // last column: LSQ
  // Per fold: sums of E_a, E_r, MPJPE per σ² (and LSQ), and the number of cells.
  std::vector<Eigen::MatrixXd> sums(folds.size(), Eigen::MatrixXd::Zero(3, static_cast<Eigen::Index>(cols)));
  std::vector<int> cells(folds.size(), 0);
  FoldProgress progress(options, static_cast<int>(folds.size()), "sigma-sweep");
  parallelFor(static_cast<int>(folds.size()), options.threads, [&](int f) {
    const Fold& fold = folds[static_cast<size_t>(f)];
    Eigen::MatrixXd& s = sums[static_cast<size_t>(f)];
    for (int r : fold.testWalkers) {
      const Eigen::VectorXd& wTrue = walkers[static_cast<size_t>(r)].fit.w;
      for (double a : angles) {
        const Eigen::VectorXd obs = projectToView(wTrue, a);
        for (size_t g = 0; g < cols; ++g) {
          const Eigen::VectorXd wRec = g < grid.size() ? reconstructMap(fold.gram, obs, a, grid[g]).w
                                                       : reconstructLsq(fold.gram, obs, a).w;
          const DepthErrors e = depthErrors(wTrue, wRec, a);
          const auto c = static_cast<Eigen::Index>(g);
          s(0, c) += e.absMean;
          s(1, c) += e.relMean;
          s(2, c) += mpjpe(wTrue, wRec, kSweepMpjpeSamples);
        }
        ++cells[static_cast<size_t>(f)];
      }
    }
    progress.foldDone();
  });
  Eigen::MatrixXd total = Eigen::MatrixXd::Zero(3, static_cast<Eigen::Index>(cols));
  int count = 0;
  for (size_t f = 0; f < folds.size(); ++f) {
    total += sums[f];
    count += cells[f];
  }
  total /= std::max(count, 1);
  std::vector<SigmaSweepRow> rows;
  for (size_t g = 0; g < grid.size(); ++g) {
    const auto c = static_cast<Eigen::Index>(g);
    const auto lsq = static_cast<Eigen::Index>(grid.size());
    rows.push_back({grid[g], "map", total(0, c), total(1, c), total(2, c)});
    if (options.lsq) rows.push_back({grid[g], "lsq", total(0, lsq), total(1, lsq), total(2, lsq)});
  }
  return rows;
}

// [SECTION] Experiment 3: known view (paper fig. 5)

std::vector<ViewErrorRow> knownViewErrors(const std::vector<ExperimentWalker>& walkers,
                                          const std::vector<Fold>& folds,
                                          const EvaluationOptions& options, double sigma2Mm2) {
  checkInputs("known view", walkers, folds, options);
  checkSigma2("known view", sigma2Mm2);
  const auto angles = anglesOf(options);
  const auto ms = methods(options, sigma2Mm2);
  return rowsOverFolds<ViewErrorRow>(folds, options, "known-view", [&](const Fold& fold, auto& rows) {
    for (int r : fold.testWalkers) {
      const Eigen::VectorXd& wTrue = walkers[static_cast<size_t>(r)].fit.w;
      for (double a : angles) {
        const Eigen::VectorXd obs = projectToView(wTrue, a);
        for (const Method& m : ms) {
          const Reconstruction rec = reconstructFourierView(fold.gram, obs, a, m.estimator).reconstruction;
          rows.push_back(scoreView(fold.subject, "", a, m.name, wTrue, rec.w));
        }
      }
    }
  });
}

// [SECTION] Experiment 4: unknown view (paper fig. 6)

std::vector<UnknownViewRow> unknownViewErrors(const std::vector<ExperimentWalker>& walkers,
                                              const std::vector<Fold>& folds,
                                              const EvaluationOptions& options, double sigma2Mm2) {
  checkInputs("unknown view", walkers, folds, options);
  checkSigma2("unknown view", sigma2Mm2);
  const auto angles = anglesOf(options);
  const auto ms = methods(options, sigma2Mm2);
  return rowsOverFolds<UnknownViewRow>(folds, options, "unknown-view", [&](const Fold& fold, auto& rows) {
    for (int r : fold.testWalkers) {
      const Eigen::VectorXd& wTrue = walkers[static_cast<size_t>(r)].fit.w;
      for (double a : angles) {
        const Eigen::VectorXd obs = projectToView(wTrue, a);
        for (const Method& m : ms) {
          const ViewSearch s = *reconstructFourierView(fold.gram, obs, std::nullopt, m.estimator).search;
          const double est = s.best.alphaDeg;
          // Depth at the true view: the reconstruction is a walker in its own frame.
          rows.push_back({fold.subject, a, m.name, est, viewAngleErrorDeg(est, a),
                          depthErrors(wTrue, s.best.w, a).absMean, mpjpe(wTrue, s.best.w)});
        }
      }
    }
  });
}

// [SECTION] Beyond the paper: 2D noise before the Fourier fit, missing joints

std::vector<ViewErrorRow> noiseErrors(const std::vector<ExperimentWalker>& walkers,
                                      const std::vector<Fold>& folds,
                                      const EvaluationOptions& options, double sigma2Mm2,
                                      std::vector<std::string>& warnings) {
  checkInputs("noise", walkers, folds, options);
  checkSigma2("noise", sigma2Mm2);
  for (double level : options.noiseLevelsMm) {
    if (!(level >= 0.0 && std::isfinite(level)))
      optionError("noise", "noise levels must be finite and ≥ 0 mm, got " + std::to_string(level));
  }
  const auto angles = extensionAngles(options);
  const auto ms = methods(options, sigma2Mm2);
  // Each fold's notes apart, joined in fold order as the rows are.
  std::vector<std::vector<std::string>> notes(folds.size());
  auto rows = rowsOverFolds<ViewErrorRow>(folds, options, "noise", [&](const Fold& fold, auto& foldRows) {
    const auto f = static_cast<size_t>(&fold - folds.data());
    for (int r : fold.testWalkers) {
      const ExperimentWalker& w = walkers[static_cast<size_t>(r)];
      if (w.framesMm.rows() == 0) {
        notes[f].push_back("noise: walker " + w.id + " has no frames; skipped");
        continue;
      }
      FourierFitOptions fitOptions;
      fitOptions.omegaFixedRadS = w.fit.omegaRadS;
      fitOptions.file = w.id;
      // The reference: the same frames' 3D fit at the same ω (φ from the same ankle signal).
      // Frames that cannot be fitted there (too short for the walker's mean ω, a bad rate)
      // skip the walker with a note instead of ending the whole evaluation.
      FourierFit truth;
      try {
        truth = fitFourier(w.framesMm, w.rateHz, fitOptions);
      } catch (const Error& e) {
        notes[f].push_back("noise: walker " + w.id + ": its frames cannot be fitted (" + e.what() + "); skipped");
        continue;
      }
      for (size_t ai = 0; ai < angles.size(); ++ai) {
        const double a = angles[ai];
        const Eigen::MatrixXd clean = projectFramesToView(w.framesMm, a);
        for (size_t li = 0; li < options.noiseLevelsMm.size(); ++li) {
          const double level = options.noiseLevelsMm[li];
          Eigen::MatrixXd noisy = clean;
          if (level > 0) {  // a normal distribution needs SD > 0: none is made for level 0
            std::mt19937_64 rng(cellSeed(options.noiseSeed, static_cast<size_t>(r), ai, li));
            std::normal_distribution<double> noise(0.0, level);
            for (Eigen::Index i = 0; i < noisy.size(); ++i) noisy.data()[i] += noise(rng);
          }
          FourierFit fit2d;
          try {
            fit2d = fitFourier(noisy, w.rateHz, fitOptions);
          } catch (const Error& e) {
            notes[f].push_back("noise: " + w.id + " at " + formatLevel(a) + "°, " + formatLevel(level) +
                               " mm: " + e.what());
            continue;
          }
          for (const Method& m : ms) {
            const Reconstruction rec = reconstructFourierView(fold.gram, fit2d.w, a, m.estimator).reconstruction;
            const Eigen::VectorXd wRec = rephase(rec.w, fit2d.phaseRad, truth.phaseRad);
            foldRows.push_back(scoreView(fold.subject, formatLevel(level), a, m.name, truth.w, wRec));
          }
        }
      }
    }
  });
  for (auto& n : notes) warnings.insert(warnings.end(), n.begin(), n.end());
  return rows;
}

std::vector<ViewErrorRow> missingJointErrors(const std::vector<ExperimentWalker>& walkers,
                                             const std::vector<Fold>& folds,
                                             const EvaluationOptions& options, double sigma2Mm2) {
  checkInputs("missing joints", walkers, folds, options);
  checkSigma2("missing joints", sigma2Mm2);
  // Checked up front, naming the set: hideJoints writes at these indices.
  for (const JointSet& set : options.missingJointSets) {
    std::vector<int> distinct;
    for (int j : set.joints) {
      if (j < 0 || j >= kJointCount)
        optionError("missing joints",
                    "set '" + set.name + "' has joint index " + std::to_string(j) + " (0…14)");
      if (std::find(distinct.begin(), distinct.end(), j) == distinct.end()) distinct.push_back(j);
    }
    if (static_cast<int>(distinct.size()) == kJointCount)
      optionError("missing joints", "set '" + set.name + "' hides every joint");
  }
  const auto angles = extensionAngles(options);
  const auto ms = methods(options, sigma2Mm2);
  return rowsOverFolds<ViewErrorRow>(folds, options, "missing-joints", [&](const Fold& fold, auto& rows) {
    for (const JointSet& set : options.missingJointSets) {
      const ModelGram gram = precomputeModelGram(fold.model, set.joints);
      for (int r : fold.testWalkers) {
        const Eigen::VectorXd& wTrue = walkers[static_cast<size_t>(r)].fit.w;
        for (double a : angles) {
          Eigen::VectorXd obs = projectToView(wTrue, a);
          hideJoints(obs, set.joints);
          for (const Method& m : ms) {
            const Reconstruction rec = reconstructFourierView(gram, obs, a, m.estimator).reconstruction;
            rows.push_back(scoreView(fold.subject, set.name, a, m.name, wTrue, rec.w));
          }
        }
      }
    }
  });
}

// [SECTION] The whole evaluation

namespace {

// A factor's level as a folder name: letters and digits kept, runs of anything else one '_'.
std::string folderNameOf(const std::string& text) {
  std::string out;
  for (char c : text) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-';
    if (keep) out += c;
    else if (!out.empty() && out.back() != '_') out += '_';
  }
  while (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

// The eigenwalker folds: every experiment but the variance table and the snippet ones
// (which build their own folds from the dataset's trials).
bool needsFolds(const std::set<Experiment>& e) {
  for (Experiment x : e)
    if (x != Experiment::Variance && x != Experiment::Snippet && x != Experiment::SnippetClusters &&
        x != Experiment::Engines && x != Experiment::Semantic)
      return true;
  return false;
}

// σ² for MAP: the user's, else the sweep's optimum (the sweep then runs and is reported).
void chooseSigma2(const std::vector<ExperimentWalker>& walkers, const std::vector<Fold>& folds,
                  const std::set<Experiment>& experiments, const EvaluationOptions& options,
                  EvaluationResults& res) {
  const bool mapUsed = options.map && needsFolds(experiments);
  const bool sweep = experiments.count(Experiment::SigmaSweep) || (mapUsed && !options.sigma2Mm2);
  res.sigma2UsedMm2 = options.sigma2Mm2.value_or(70.0);
  if (!sweep) return;
  const auto start = std::chrono::steady_clock::now();
  EvaluationOptions o = options;
  o.map = true;
  res.sigmaSweep = sigmaSweep(walkers, folds, o);
  res.timingsS.emplace_back("sigma-sweep", secondsSince(start));
  res.ran.insert(Experiment::SigmaSweep);
  const SigmaSweepRow* best = nullptr;
  for (const auto& r : res.sigmaSweep) {
    if (r.method == "map" && (!best || r.meanAbsErrorMm2 < best->meanAbsErrorMm2)) best = &r;
  }
  if (!best) return;
  res.sigma2OptMm2 = best->sigma2Mm2;
  const auto& grid = options.sigma2GridMm2;
  res.sigma2OptAtGridEdge = grid.size() > 1 && (best->sigma2Mm2 == grid.front() || best->sigma2Mm2 == grid.back());
  if (res.sigma2OptAtGridEdge) {
    res.warnings.push_back("the sigma2 optimum " + formatLevel(best->sigma2Mm2) +
                           " mm2 sits at the edge of the grid: the true optimum may lie outside it");
  }
  if (!options.sigma2Mm2) res.sigma2UsedMm2 = best->sigma2Mm2;
}

}  // namespace

EvaluationResults runEvaluation(const std::vector<ExperimentWalker>& walkers,
                                const std::set<Experiment>& experiments,
                                const EvaluationOptions& options) {
  if (!options.lsq && !options.map) throw Error(ErrorKind::BadArgument, "--method", "", "no method chosen");
  // Too few walkers is the data's fault (exit 1 in the CLI), not a caller mistake.
  if (walkers.size() < 2)
    throwBadData(
        "", "",
        "evaluation: a model needs at least 2 walkers, got " + std::to_string(walkers.size()));
  if (options.sigma2Mm2) checkSigma2("evaluation", *options.sigma2Mm2);
  checkInputs("evaluation", walkers, {}, options);
  EvaluationResults res;
  res.walkers = static_cast<int>(walkers.size());
  res.subjects = static_cast<int>(walkerSubjects(walkers).size());
  auto start = std::chrono::steady_clock::now();
  const EigenwalkerModel full = buildFullModel(walkers, options.model);
  res.components = full.componentCount();
  res.variance = varianceTable(full);
  res.components95 = componentsForShare(res.variance, 0.95);
  res.harmonics = harmonicsTable(walkers);
  if (experiments.count(Experiment::Variance)) {
    res.ran.insert(Experiment::Variance);
    res.timingsS.emplace_back("variance", secondsSince(start));
  }
  if (!needsFolds(experiments)) return res;

  start = std::chrono::steady_clock::now();
  const std::vector<Fold> folds = buildFolds(walkers, options.model, options.threads);
  res.timingsS.emplace_back("folds", secondsSince(start));
  chooseSigma2(walkers, folds, experiments, options, res);

  const auto timed = [&](Experiment e, const auto& run) {
    if (!experiments.count(e)) return;
    const auto t0 = std::chrono::steady_clock::now();
    run();
    res.timingsS.emplace_back(experimentName(e), secondsSince(t0));
    res.ran.insert(e);
  };
  const double s2 = res.sigma2UsedMm2;
  timed(Experiment::KnownView, [&] { res.knownView = knownViewErrors(walkers, folds, options, s2); });
  timed(Experiment::UnknownView, [&] { res.unknownView = unknownViewErrors(walkers, folds, options, s2); });
  timed(Experiment::Noise, [&] { res.noise = noiseErrors(walkers, folds, options, s2, res.warnings); });
  timed(Experiment::MissingJoints, [&] { res.missingJoints = missingJointErrors(walkers, folds, options, s2); });
  timed(Experiment::LowerBody, [&] {
    res.lowerBody = lowerBodyErrors(walkers, folds, options.lsq, options.map, s2, options.threads);
  });
  timed(Experiment::Camera, [&] {
    CameraExperimentOptions camera;
    camera.sigma2Mm2 = s2;
    camera.threads = options.threads;
    camera.skeleton = options.cameraSkeleton;
    camera.snippet = options.cameraSnippet;
    camera.detectorHipOffsetMm = options.cameraDetectorHipOffsetMm;
    camera.allowForDetectorOffsets = options.cameraAllowForDetectorOffsets;
    camera.keepClipsDir = options.keepClipsDir;
    res.camera = cameraErrors(walkers, folds, camera);
  });
  timed(Experiment::CameraWide, [&] {
    CameraExperimentOptions base;  // the eigenwalker alone at 2 px
    base.sigma2Mm2 = s2;
    base.threads = options.threads;
    base.skeleton = base.snippet = false;
    base.noisePx = {2.0};
    if (options.cameraWideCameras) base.camerasPerWalker = *options.cameraWideCameras;
    auto conditions = cameraWideConditions(base, options.cameraWideFactors);
    // Each level's clips in a folder of its own (the levels reuse the walkers and cameras).
    if (options.keepClipsDir)
      for (auto& c : conditions) c.options.keepClipsDir = *options.keepClipsDir / folderNameOf(c.factor + " " + c.level);
    res.cameraWide = cameraWideErrors(walkers, folds, conditions);
  });
  return res;
}

// [SECTION] Angle lists

namespace {

double parseNumber(const std::string& text, const std::string& spec) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) {
    throw Error(ErrorKind::BadArgument, "--angles", "", "'" + spec + "': '" + text + "' is not a number");
  }
  return v;
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  size_t begin = 0;
  for (size_t i = 0; i <= s.size(); ++i) {
    if (i == s.size() || s[i] == sep) {
      parts.push_back(s.substr(begin, i - begin));
      begin = i + 1;
    }
  }
  return parts;
}

}  // namespace

std::vector<double> parseAngleSpec(const std::string& spec) {
  const auto bad = [&](const std::string& why) {
    throw Error(ErrorKind::BadArgument, "--angles", "", "'" + spec + "': " + why);
  };
  std::vector<double> angles;
  if (spec.find(':') != std::string::npos) {
    const auto p = split(spec, ':');
    if (p.size() != 3) bad("expected FROM:TO:STEP, e.g. -90:90:1");
    const double from = parseNumber(p[0], spec), to = parseNumber(p[1], spec), step = parseNumber(p[2], spec);
    if (step <= 0) bad("the step must be positive");
    if (to < from) bad("TO must not be below FROM");
    const double n = std::floor((to - from) / step + 1e-9) + 1;
    if (n > 10000) bad("more than 10000 angles");
    for (int i = 0; i < static_cast<int>(n); ++i) angles.push_back(from + i * step);
  } else {
    for (const auto& t : split(spec, ',')) angles.push_back(parseNumber(t, spec));
    if (angles.size() > 10000) bad("more than 10000 angles");
  }
  return angles;
}

}  // namespace ew
