#pragma once
// MAP reconstruction of one 3D snippet from its 2D view (Howe, Leventon & Freeman 1999,
// eq. 2): maximise over the snippet x and the rendering (view angle α about the vertical,
// scale s, image shift t)
//   L(x, α, s, t) = log N(y; s C(α) x + t, ν I) + log p(x)
// with p the snippet prior (snippet_prior.h), C(α) METHOD §5's orthographic view of every
// frame (u = x cos α + y sin α, v = z) and ν the image noise variance. EM over the mixture:
//   E  responsibilities r_j ∝ π_j N(x; μ_j, C_j) at the current x;
//   M  x maximising log N(y | x) + Σ_j r_j log N(x; μ_j, C_j): for one cluster the
//      linear-Gaussian posterior mean jointly with the shift t, in closed form through the
//      cluster's PPCA factors (x̂ = μ + W z̄ + σ² β Aᵀ(r − B z̄), B = A W centred, a q × q
//      solve); for several, conjugate gradients on the summed precisions (t fixed);
//   M  the camera given x: (s, t) by linear least squares for each α, α by Brent's method
//      near the current value.
// Each step cannot lower L, so neither can an iteration (tested). The start: every
// cluster's mean seen from each start angle, ranked by the marginal likelihood
// p(y | cluster, camera) = N(y; A μ_j + t, B Bᵀ + (s²σ_j² + ν) I).
// Outliers (the paper's second noise process): after EM converges, a point whose residual
// a broad Gaussian (SD 10 × the robust inlier SD, prior 5 %) explains better than the
// inlier Gaussian is dropped from the likelihood and EM resumes (at most 3 rounds).

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/snippet/snippet_prior.h"

namespace ew {

// The prior with each cluster's PPCA factors W_j = U_j diag(√(λ_j − σ_j²)) split by axis and
// their Gram blocks, so one cluster's posterior at a new view angle costs O(q³), not O(D·q²)
// (the same trick as the eigenwalker's ModelGram, reconstruction.h).
struct ClusterFactors {
  Eigen::MatrixXd wx, wy, wz;       // (S·15) × q: W's x, y, z rows, point-major
  Eigen::VectorXd mx, my, mz;       // μ's x, y, z values (S·15)
  Eigen::MatrixXd gxx, gyy, gxySym, gzz;  // WxᵀWx, WyᵀWy, WxᵀWy + WyᵀWx, WzᵀWz
};

struct PreparedSnippetPrior {
  SnippetPrior prior;
  std::vector<ClusterFactors> factors;
};

// Checks the prior (checkSnippetPrior) and precomputes the factors.
PreparedSnippetPrior prepareSnippetPrior(const SnippetPrior& prior);

struct SnippetCamera {
  double alphaDeg = 0.0;
  double scale = 1.0;                 // image units per mm
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();  // image units, added to (u, v)
};

struct SnippetFitOptions {
  std::optional<double> alphaDeg;     // known view; else searched over the whole circle
  std::optional<double> alphaStartDeg; // unknown view started here only (not the whole circle)
  double alphaStepDeg = 30.0;         // start angles for an unknown view
  int alphaStarts = 3;                // best-ranked distinct start angles refined by EM
  double alphaWindowDeg = 180.0;      // how far one camera step may move α (≤ 180)
  std::optional<double> scale;        // known scale (1 for views in mm); else estimated
  double noiseSdMm = 5.0;             // image noise SD, in mm at the walker (ν = s²·SD²)
  bool rejectOutliers = true;
  double outlierFloorMm = 20.0;       // the inlier SD the outlier test assumes at least
  int maxIterations = 60;
  double tolerance = 1e-7;            // relative change of L that ends EM
};

struct SnippetFit {
  Eigen::VectorXd snippet;            // x (D), the snippet's own frame
  SnippetCamera camera;
  Eigen::VectorXd responsibilities;   // r_j at the end
  int cluster = 0;                    // argmax r_j
  double logPosterior = 0.0;          // L at the end
  std::vector<double> trace;          // L after each iteration of the kept start
  std::vector<bool> outlierPoints;    // S·15, true where dropped as an outlier
  int iterations = 0;
  double reprojectionRms = 0.0;       // image units, over the points used
};

// y: S × 30 (u, v of each joint in each frame, image units, v up), NaN = not seen (the
// joint's point is left out of the likelihood). Throws Error(BadArgument) "snippet fit: …"
// for a wrong shape, a prior checkSnippetPrior rejects, fewer than 3 points seen, or bad
// options.
SnippetFit fitSnippet(const PreparedSnippetPrior& prepared, const Eigen::Ref<const Eigen::MatrixXd>& y,
                      const SnippetFitOptions& options = {});

// s C(α) x + t: the snippet's image (S × 30).
Eigen::MatrixXd renderSnippet(const Eigen::Ref<const Eigen::VectorXd>& snippet, int frames,
                              const SnippetCamera& camera);

// L for a given x and camera (points marked in `used`, S·15, all when empty).
double snippetLogPosterior(const SnippetPrior& prior, const Eigen::Ref<const Eigen::MatrixXd>& y,
                           const Eigen::Ref<const Eigen::VectorXd>& snippet,
                           const SnippetCamera& camera, double noiseVariance,
                           const std::vector<bool>& used = {});

// The joint MAP of x and the image shift t under one Gaussian cluster, α and s fixed (the
// closed form the EM's M-step uses; t has a flat prior): exposed for tests against a
// dense solve. camera.shift is not used.
struct ClusterMap {
  Eigen::VectorXd snippet;
  Eigen::Vector2d shift;
};
ClusterMap clusterMap(const PpcaComponent& component, const Eigen::Ref<const Eigen::MatrixXd>& y,
                      const SnippetCamera& camera, double noiseVariance, const std::vector<bool>& used = {});

}  // namespace ew
