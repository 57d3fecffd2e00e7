#pragma once
// The snippet prior (Howe, Leventon & Freeman 1999, eq. 1): a mixture of m Gaussians over
// snippet vectors x ∈ R^D (D = S·45, core/snippet/snippet_data.h). The paper clusters the
// training snippets with k-means and models each cluster by its SVD truncated to 50
// components, A_j = U_j S_j² U_jᵀ — singular, so eq. 1 is not a proper density. Here each
// cluster is a probabilistic PCA (Tipping & Bishop 1999):
//   C_j = U_j diag(λ_j) U_jᵀ + σ_j² (I − U_j U_jᵀ)
// with λ_j the q largest sample variances of the cluster and σ_j² the mean of the others
// (the maximum-likelihood PPCA), floored so C_j stays well conditioned. Then
//   p(x) = Σ_j π_j N(x; μ_j, C_j),  π_j = n_j / n,
// evaluated through C_j⁻¹ = (I − U_j diag(1 − σ_j²/λ_j) U_jᵀ)/σ_j² and
// log det C_j = Σ log λ_j + (D − q) log σ_j², O(D·q) per cluster, never a D × D matrix.

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/snippet/snippet_data.h"

namespace ew {

struct PpcaComponent {
  double weight = 0.0;        // π_j
  int members = 0;            // training snippets in the cluster
  Eigen::VectorXd mean;       // μ_j (D)
  Eigen::MatrixXd basis;      // U_j (D × q_j), orthonormal columns
  Eigen::VectorXd variances;  // λ_j (q_j), each > noiseVariance
  double noiseVariance = 0.0; // σ_j² (mm²)
};

struct SnippetPrior {
  int frames = 11;            // S
  double rateHz = 30.0;       // the rate every trial was resampled to
  std::vector<PpcaComponent> components;
  std::vector<std::string> subjects;  // the subjects it learnt from
  int trainingSnippets = 0;
  int emIterations = 0;       // EM refinement steps after k-means (0: the paper's clustering)

  int dimension() const { return frames * kSnippetJointValues; }
};

struct SnippetPriorOptions {
  int frames = 11;             // paper: 11 frames ≈ 1/3 s at 30 Hz
  double rateHz = 30.0;
  int clusters = 8;            // m (docs/SNIPPETS.md: chosen by held-out likelihood)
  int components = 50;         // q (paper: 50); fewer when a cluster is small
  int hop = 1;                 // a snippet starts at every hop-th frame of a trial
  int kmeansIterations = 100;
  std::uint64_t seed = 1;      // k-means++ seeding
  int emIterations = 0;        // EM steps on the full mixture after k-means
  double minNoiseVarianceMm2 = 1.0;  // floor for σ_j²
};

// Mixture from snippet vectors (columns of `snippets`, D × n). Throws Error(BadArgument)
// "snippet prior: …" for fewer snippets than 2 per cluster, bad options or non-finite data.
SnippetPrior fitSnippetMixture(const Eigen::Ref<const Eigen::MatrixXd>& snippets,
                               const SnippetPriorOptions& options);

// The whole training path: cut snippets from the trials (resampled), fit the mixture,
// record the subjects. Throws Error(BadData) naming the trials when they give too few
// snippets.
SnippetPrior trainSnippetPrior(const std::vector<SnippetTrainingTrial>& trials,
                               const SnippetPriorOptions& options);

// log N(x; μ_j, C_j).
double componentLogDensity(const PpcaComponent& component, const Eigen::Ref<const Eigen::VectorXd>& x);

// (log π_j + log N(x; μ_j, C_j)) for every j.
Eigen::VectorXd weightedLogDensities(const SnippetPrior& prior, const Eigen::Ref<const Eigen::VectorXd>& x);

// log p(x) (eq. 1, normalised).
double logDensity(const SnippetPrior& prior, const Eigen::Ref<const Eigen::VectorXd>& x);

// Mean log p over the columns (held-out likelihood, per snippet).
double meanLogDensity(const SnippetPrior& prior, const Eigen::Ref<const Eigen::MatrixXd>& snippets);

// Responsibilities from weighted log densities (softmax, stable).
Eigen::VectorXd responsibilitiesFromLog(const Eigen::Ref<const Eigen::VectorXd>& logWeighted);

// C_j⁻¹ v.
Eigen::VectorXd applyInverseCovariance(const PpcaComponent& component,
                                       const Eigen::Ref<const Eigen::VectorXd>& v);

// Throws Error(BadArgument) "snippet prior: …" for an inconsistent prior (sizes, weights,
// non-finite values, variances not above σ², σ² not positive).
void checkSnippetPrior(const SnippetPrior& prior);

}  // namespace ew
