#pragma once
// Leave-one-subject-out folds for the experiments (METHOD §4, §8): one eigenwalker model per
// held-out subject, built once and reused by every experiment, with its Gram blocks
// precomputed once (all joints observed).

#include <Eigen/Core>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/eigenwalker/walker_set.h"
#include "core/gait/dataset.h"

namespace ew {

// A walker as the experiments see it: its 3D Fourier fit (METHOD §3) and, for the
// experiments that start from frames (2D noise), the frames of its first trial.
struct ExperimentWalker {
  std::string id;       // subject/condition
  std::string subject;
  std::string source;
  FourierFit fit;             // 3D: w (225), ω, φ, harmonic shares
  Eigen::MatrixXd framesMm;   // T × 45, canonical frame (METHOD §2); empty if unknown
  double rateHz = 0.0;        // of framesMm
};

// Pairs each walker with the frames of its first trial in `dataset` (matched by file).
std::vector<ExperimentWalker> experimentWalkers(const std::vector<Walker>& walkers,
                                                const Dataset& dataset);

// Distinct subjects in first-seen order.
std::vector<std::string> walkerSubjects(const std::vector<ExperimentWalker>& walkers);

// W = [w_1 … w_R] (225 × R). Throws Error(BadArgument) naming a walker whose fit is not 3D.
Eigen::MatrixXd experimentWalkerMatrix(const std::vector<ExperimentWalker>& walkers);

// The model of all walkers (experiment 1, the `build` command's model).
EigenwalkerModel buildFullModel(const std::vector<ExperimentWalker>& walkers,
                                const ModelOptions& options = {});

struct Fold {
  std::string subject;            // held out
  std::vector<int> testWalkers;   // indices of the held-out subject's walkers
  EigenwalkerModel model;         // built without them
  ModelGram gram;                 // precomputeModelGram(model): every joint observed
};

// One fold per subject, in first-seen order, built on `threads` threads. Throws
// Error(BadData) with fewer than 3 subjects (a fold's model needs ≥ 2 walkers and one
// direction of variation).
std::vector<Fold> buildFolds(const std::vector<ExperimentWalker>& walkers,
                             const ModelOptions& options, int threads);

// Independent, schedule-free noise streams: one seed per (walker, angle, level) cell, the
// same whichever thread draws it.
std::uint64_t cellSeed(std::uint64_t seed, size_t walker, size_t angle, size_t level);

// Runs body(i) for i in [0, count) on up to `threads` threads (work pulled from a shared
// counter, so uneven folds balance). The first exception is rethrown after all finish.
void parallelFor(int count, int threads, const std::function<void(int)>& body);

}  // namespace ew
