#pragma once
// The eigenwalker model (METHOD §4; Zhang & Troje 2007, §3.1, eq. 3.3):
//   W = [w_1 … w_R] (225 × R), w̄ = mean column, X = W − w̄1ᵀ = U S Vᵀ (thin SVD),
//   e_n = U[:, n], λ_n = S_n² / (R − 1) (mm²), k_{n,r} = e_nᵀ (w_r − w̄),
//   w ≈ w̄ + Σ_n k_n e_n.
// Raw millimetres, no per-dimension standardisation.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace ew {

struct ModelOptions {
  // Smallest N whose cumulative share of the variance reaches this (METHOD §4 default 95 %).
  double varianceThreshold = 0.95;
  // Fixed N instead; an upper bound: clamped to R − 1 (the centred data's rank).
  std::optional<int> components;
};

// The paper's optimum MAP noise variance on its own data (Zhang & Troje 2007, §4.3): the
// fallback σ² for a model that does not record the optimum measured on its walkers.
inline constexpr double kPaperSigma2Mm2 = 70.0;

// The MAP σ² that reconstructs this model's own walkers best, measured when the model was
// built (core/experiments/model_build.h): a leave-one-subject-out sweep over a σ² grid,
// each held-out walker projected at every angle of `anglesDeg` and reconstructed by MAP
// with the model without its subject; the σ² with the smallest mean E_a (METHOD §7) wins.
struct Sigma2Optimum {
  double sigma2Mm2 = kPaperSigma2Mm2;  // the optimum, mm²
  double meanAbsErrorMm2 = 0.0;        // its mean E_a over subjects and angles, mm²
  std::vector<double> gridMm2;         // the σ² tried, mm²
  std::vector<double> anglesDeg;       // the view angles of each held-out walker
  std::string criterion;               // how the optimum was chosen, in words
  bool atGridEdge = false;             // the optimum is the grid's first or last value
  bool operator==(const Sigma2Optimum&) const = default;
};

struct EigenwalkerModel {
  Eigen::VectorXd mean;          // w̄, 225, mm
  Eigen::MatrixXd eigenwalkers;  // E, 225 × N, orthonormal columns
  Eigen::VectorXd eigenvalues;   // λ, N, mm², decreasing
  Eigen::VectorXd spectrum;      // all R − 1 eigenvalues (cumulative-variance plots), mm²
  Eigen::MatrixXd coefficients;  // k, N × R: column r holds walker r's coefficients
  std::vector<std::string> walkerIds;  // R
  std::vector<std::string> subjects;   // R, subject of each walker
  Eigen::VectorXd omegasRadS;          // R, ω of each walker (kept beside w)
  // R or none: each walker's mean overground speed (m/s), nullopt where it is unknown (a
  // treadmill, a trial without progression). Gait measures of the model's walkers (stride and
  // step length, speed) need it; empty for a model built from walkers alone or an older file.
  std::vector<std::optional<double>> speedsMps;
  std::vector<std::string> provenance; // free text: sources, files, options, …
  // The σ² optimum measured on the model's own walkers; unset for a model built without
  // the sweep (fewer than 3 subjects, a leave-one-out model) or read from an older file.
  std::optional<Sigma2Optimum> sigma2Optimum;

  int componentCount() const { return static_cast<int>(eigenwalkers.cols()); }
  int walkerCount() const { return static_cast<int>(walkerIds.size()); }
  // Walker r's recorded speed (speedsMps), nullopt where unknown or not recorded.
  std::optional<double> speedMpsOf(int r) const {
    return r >= 0 && static_cast<std::size_t>(r) < speedsMps.size() ? speedsMps[static_cast<std::size_t>(r)] : std::nullopt;
  }
  // Σ_{n ≤ N} λ_n / Σ λ over the whole spectrum.
  double explainedVariance() const;
};

// The walkers the model was built from as it stores them, one column each (225 × R): w̄ + E k_r,
// exact when the model kept every component (R − 1), else their N eigenwalkers' part.
Eigen::MatrixXd storedWalkerVectors(const EigenwalkerModel& model);

// The σ² a MAP reconstruction with this model uses when the user gives none: the optimum
// stored in the model, else kPaperSigma2Mm2.
double defaultSigma2Mm2(const EigenwalkerModel& model);
// Where that σ² comes from, for reports: "optimum measured on the model's 24 walkers
// (leave-one-subject-out sweep)" or "the paper's 70 mm² (the model records no optimum)".
std::string defaultSigma2Source(const EigenwalkerModel& model);

// The model reduced to its first `components` eigenwalkers (clamped to 1 … N): E, λ and k
// truncated, the mean and spectrum kept. Exact for PCA: the first n principal directions
// of the full fit are those of a fit with n components. The viewer's N and the CLI's
// `--components N` both mean this.
EigenwalkerModel leadingComponents(const EigenwalkerModel& model, int components);

// Builds the model from W (225 × R, R ≥ 2). ids, subjects and omegas have R entries.
// Eigenvector signs are fixed (largest-magnitude entry positive) so a rebuild is
// reproducible. Throws Error(BadArgument) "model: …" on inconsistent sizes, fewer than 2
// walkers, non-finite coefficients (naming the walker), a non-positive or non-finite ω, or
// a variance threshold outside (0, 1] (when `components` is unset).
EigenwalkerModel buildModel(const Eigen::Ref<const Eigen::MatrixXd>& w,
                            std::vector<std::string> walkerIds, std::vector<std::string> subjects,
                            const Eigen::Ref<const Eigen::VectorXd>& omegasRadS,
                            const ModelOptions& options = {});

// The model without every walker of `heldOutSubject` (METHOD §4 leave-one-subject-out):
// a refit of the remaining columns of W, so N follows the options on the R' remaining
// walkers (at most R' − 1). Refit rather than an SVD downdate: a thin SVD of 225 × R' costs
// O(225·R'²), well under a millisecond for R' in the tens, and is exact (docs/ENGINE.md).
// Throws Error(BadArgument) "model: …" if the subject is unknown or fewer than 2 walkers
// remain (and for what buildModel rejects).
EigenwalkerModel buildModelWithoutSubject(const Eigen::Ref<const Eigen::MatrixXd>& w,
                                          const std::vector<std::string>& walkerIds,
                                          const std::vector<std::string>& subjects,
                                          const Eigen::Ref<const Eigen::VectorXd>& omegasRadS,
                                          const std::string& heldOutSubject,
                                          const ModelOptions& options = {});

// Throws Error(BadArgument) "STAGE: …" unless the model is usable: mean 225, E 225 × N with
// N ≥ 1, N eigenvalues, all finite, eigenvalues ≥ 0 (O(225·N): once per model, not per use).
void checkModel(const EigenwalkerModel& model, const std::string& stage);

// Model synthesis w̄ + E k (225). k must have N finite values; the model's shapes are
// checked (Error(BadArgument)).
Eigen::VectorXd synthesizeWalker(const EigenwalkerModel& model,
                                 const Eigen::Ref<const Eigen::VectorXd>& k);

// Coefficients of a 3D walker: Eᵀ (w − w̄) (N); w: 225 finite values.
Eigen::VectorXd projectOntoModel(const EigenwalkerModel& model,
                                 const Eigen::Ref<const Eigen::VectorXd>& w);

// p(t) of the model walker with coefficients k, at ω and φ (T × 45).
Eigen::MatrixXd synthesizeWalkerFrames(const EigenwalkerModel& model,
                                       const Eigen::Ref<const Eigen::VectorXd>& k, double omegaRadS,
                                       double phaseRad,
                                       const Eigen::Ref<const Eigen::VectorXd>& timesS);

}  // namespace ew
