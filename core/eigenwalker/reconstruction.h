#pragma once
// 3D reconstruction of a walker from its 2D Fourier representation (METHOD §6; Zhang &
// Troje 2007, §3.2, §4.3, appendices A–B).
//
// Notation: ŵ (150, mm) the observed 2D Fourier vector at view α; ŵ̄(α) = C(α) w̄,
// Ê(α) = C(α) E (150 × N); r(k) = ŵ − ŵ̄(α) − Ê(α) k.
//   LSQ (approach I, eq. 3.9):  k = argmin ‖r‖²            = G⁻¹ b
//   MAP (approach II, eq. 3.15): k = argmin ‖r‖² + σ² Σ k_n²/λ_n = (G + σ²Λ⁻¹)⁻¹ b
// with G(α) = ÊᵀÊ and b(α) = Êᵀ(ŵ − ŵ̄(α)), solved by Cholesky (LDLT if G is singular),
// never an explicit inverse. The objective J = ‖r‖² (+ σ² Σ k²/λ for MAP), mm², is the
// MAP objective of eq. 3.14 times 2σ², and at the optimum equals ‖ŵ − ŵ̄‖² − kᵀb.
//
// Speed: with x, y, z the per-axis rows of E (each 75 × N, one row per block and joint),
//   G(α) = c²·ExᵀEx + s²·EyᵀEy + cs·(ExᵀEy + EyᵀEx) + EzᵀEz     (c = cos α, s = sin α)
// and b(α), ‖ŵ − ŵ̄(α)‖² combine likewise from per-axis products, so ModelGram holds the
// α-independent blocks and one evaluation of J costs O(N³) (Cholesky), not O(150·N²).

#include <Eigen/Core>
#include <vector>

#include "core/eigenwalker/model.h"

namespace ew {

enum class Estimator { Lsq, Map };

struct EstimatorOptions {
  Estimator estimator = Estimator::Lsq;
  double sigma2Mm2 = 70.0;  // MAP noise variance σ² (mm²); the paper's optimum on its data
};

// Everything that depends only on the model and on which joints are observed.
struct ModelGram {
  int components = 0;                  // N
  std::vector<int> missingJoints;      // joint indices (0…14) with no 2D data, sorted
  std::vector<int> observedPoints;     // triple indices block·15 + joint that are observed
  Eigen::MatrixXd ex, ey, ez;          // observed rows of E per axis, m × N (m = 5 · joints seen)
  Eigen::VectorXd mx, my, mz;          // observed rows of w̄ per axis, m
  Eigen::MatrixXd gxx, gyy, gxySym, gzz;        // ExᵀEx, EyᵀEy, ExᵀEy + EyᵀEx, EzᵀEz (N × N)
  Eigen::VectorXd exMx, eyMy, exMyEyMx, ezMz;   // Exᵀw̄x, Eyᵀw̄y, Exᵀw̄y + Eyᵀw̄x, Ezᵀw̄z (N)
  double mxMx = 0.0, myMy = 0.0, mxMy = 0.0;    // w̄xᵀw̄x, w̄yᵀw̄y, w̄xᵀw̄y
  Eigen::VectorXd inverseLambda;       // 1/λ_n (λ floored at 1e-12 · λ_1)
  Eigen::VectorXd mean;                // w̄ (225) and E (225 × N), for the outputs
  Eigen::MatrixXd eigenwalkers;
};

// missingJoints: joints whose u, v are not observed (their rows of Ê are dropped).
// Throws Error(BadArgument) "reconstruction: …" for a joint index outside 0…14, all joints
// missing, or a model that checkModel rejects (empty, inconsistent, non-finite, λ < 0).
ModelGram precomputeModelGram(const EigenwalkerModel& model,
                              const std::vector<int>& missingJoints = {});

struct Reconstruction {
  double alphaDeg = 0.0;
  Eigen::VectorXd k;                // N coefficients
  Eigen::VectorXd w;                // 225: model synthesis w̄ + E k
  Eigen::VectorXd wDataPreserving;  // 225: observed u, v kept, depth from w (eq. 3.16);
                                    // joints not observed are taken from w entirely
  double objective = 0.0;           // J(α) from the Gram terms (the value searches compare)
  double residualSq = 0.0;          // ‖r‖² on the observed rows, computed directly
};

// Known view. `observed` is ŵ (150); entries of missing joints are ignored (may be NaN).
// Every reconstruction throws Error "reconstruction: …": BadArgument for a gram not made by
// precomputeModelGram, ŵ of the wrong size or non-finite at an observed joint, a non-finite
// α, or MAP with σ² negative or non-finite; BadData when ŵ's magnitude overflows the sums
// or the solve gives non-finite k or J (never a NaN result).
Reconstruction reconstructKnownView(const ModelGram& gram,
                                    const Eigen::Ref<const Eigen::VectorXd>& observed,
                                    double alphaDeg, const EstimatorOptions& estimator = {});
Reconstruction reconstructLsq(const ModelGram& gram,
                              const Eigen::Ref<const Eigen::VectorXd>& observed, double alphaDeg);
Reconstruction reconstructMap(const ModelGram& gram,
                              const Eigen::Ref<const Eigen::VectorXd>& observed, double alphaDeg,
                              double sigma2Mm2);

struct ViewSearchOptions {
  double coarseStepDeg = 1.0;        // METHOD §6.4: 1° scan of (−180, 180]
  double toleranceDeg = 1e-4;        // refinement bracket width (METHOD §6.4)
  double relationToleranceDeg = 20.0;  // how close to −α̂, 180° − α̂, α̂ + 180° (see below)
};

// One local minimum of the profile objective J(α).
//
// An orthographic image is unchanged when the depth of every point changes sign
// (reflection through the image plane: the Necker reversal). The reflected body is a
// mirror image, which the model can read in two ways (derivation in docs/ENGINE.md):
//   - a front-back reflected walker seen at −α̂  ("depth reversed": labels stay on their
//     side; only forward/backward asymmetries such as knee flexion tell it apart);
//   - a left-right mirrored walker seen at 180° − α̂ ("mirror": the labelled left side
//     appears on the right; only the lateral offsets of the joints tell it apart).
// Besides these, α̂ + 180° ("facing") shows the walker from the opposite side (image
// flipped). A minimum within relationToleranceDeg of such an angle carries its flag; at
// α̂ = ±90° "depth reversed" and "facing" coincide, at α̂ = 0° "mirror" and "facing" do.
struct ViewMinimum {
  double alphaDeg = 0.0;
  double objective = 0.0;
  bool depthReversedOfBest = false;  // ≈ −α̂
  bool mirrorOfBest = false;         // ≈ 180° − α̂
  bool facingOfBest = false;         // ≈ α̂ + 180°
};

struct ViewSearch {
  Reconstruction best;               // at α̂ = minima.front().alphaDeg
  std::vector<ViewMinimum> minima;   // every local minimum, best first
  Eigen::VectorXd scanAlphaDeg;      // the coarse grid (−180, 180]
  Eigen::VectorXd scanObjective;     // J on the grid
  int evaluations = 0;               // evaluations of J (grid + refinement)
};

// Unknown view: minimises J(α) over (−180°, 180°] (coarse scan, Brent refinement of every
// local minimum of the circular grid), then reconstructs at the best α̂. Options: coarse
// step in [0.001°, 30°], tolerance positive and finite, relation tolerance in [0°, 180°].
ViewSearch searchViewAngle(const ModelGram& gram,
                           const Eigen::Ref<const Eigen::VectorXd>& observed,
                           const EstimatorOptions& estimator = {},
                           const ViewSearchOptions& options = {});

// J(α) for each angle (plots, tests); same values the search compares.
Eigen::VectorXd viewObjective(const ModelGram& gram,
                              const Eigen::Ref<const Eigen::VectorXd>& observed,
                              const Eigen::Ref<const Eigen::VectorXd>& alphasDeg,
                              const EstimatorOptions& estimator = {});

// The relations of `alphaDeg` to `bestDeg` used for ViewMinimum's flags.
bool isDepthReversedView(double alphaDeg, double bestDeg, double toleranceDeg);
bool isMirrorView(double alphaDeg, double bestDeg, double toleranceDeg);
bool isFacingView(double alphaDeg, double bestDeg, double toleranceDeg);

}  // namespace ew
