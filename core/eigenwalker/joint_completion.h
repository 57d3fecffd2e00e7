#pragma once
// Joints a marker set lacks, estimated from the eigenwalker model ("model-estimated").
//
// A lower-body marker set measures pelvis, hips, knees and ankles; the trunk, head and
// arms are unknown in every frame (JointTrial::missing). Zhang & Troje (2007) close with
// "the same machinery recovers occluded markers": the reconstruction of METHOD §6 with the
// projection C(α) replaced by the selection S_O of the measured entries of w.
//
// Derivation. Split w (225) into the entries O of measured joints (all 5 blocks × x,y,z)
// and M of missing ones. The model (METHOD §4) says w = w̄ + E c with the prior
// c ~ N(0, Λ), Λ = diag(λ_n); the measured entries carry noise ε ~ N(0, σ² I):
//   w_O = w̄_O + E_O c + ε.
// The posterior of c is Gaussian; its mean (= its mode, the MAP estimate) is
//   ĉ = (E_Oᵀ E_O + σ² Λ⁻¹)⁻¹ E_Oᵀ (w_O − w̄_O)                         (eq. 3.15 with C = S_O)
// and the conditional-Gaussian estimate of the missing entries is
//   ŵ_M = w̄_M + E_M ĉ.
// The measured entries are kept as measured (the data-preserving variant, eq. 3.16): only
// the missing joints come from the model. Solved by Cholesky (LDLT when singular), never
// an explicit inverse. With nothing missing, w passes through unchanged (ĉ = Eᵀ(w − w̄)
// projection is still reported). σ² (mm²): the caller's, else EstimatorOptions' default.
//
// Phase: the model's walkers are phase-aligned by the ankle reference of METHOD §3
// (z_l_ankle − z_r_ankle a pure +sine); a partial walker's fit uses the same reference,
// so its w is aligned the same way and the ankles are part of the minimum below.
//
// Minimum (core/gait/missing_joints.h): both ankles (the floor, the gait cycles and the
// phase reference), both hips or both knees (the heading, METHOD §2), the pelvis or both
// hips (the progression). Below it: Error(BadData) naming the missing joints and saying
// too few were measured to estimate the rest.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/common/skeleton.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/model.h"
#include "core/gait/missing_joints.h"
#include "core/gait/walking_trial.h"

namespace ew {

// JointMask, anyJoint, jointList, lackingForMinimum, requireMinimumMeasured and
// missingJointsOf: core/gait/missing_joints.h.

// [SECTION] Fourier fit of the measured joints only

// fitFourier on frames (T × 45, or T × 30 for a 2D view) whose missing joints' columns are
// ignored (they may be NaN throughout): those columns are held at 0 for the fit, so they
// add nothing to the ω scan, the phase reference or the variance shares; their
// coefficients in w are 0 (unknown) — completeJoints (3D) or a reconstruction with those
// joints' rows of Ê dropped (2D) fills them. Frames with a NaN in a measured joint are
// dropped as usual. Error(BadArgument) for other widths; Error(BadData) when an ankle is
// missing (the phase reference).
FourierFit fitFourierMeasured(const Eigen::Ref<const Eigen::MatrixXd>& frames, double rateHz,
                              const JointMask& missing, const FourierFitOptions& options = {});

// [SECTION] Completion of a Fourier vector

struct CompletionOptions {
  // MAP noise variance on the measured entries (mm²); unset = the model's default σ².
  std::optional<double> sigma2Mm2;
};

struct JointCompletion {
  Eigen::VectorXd w;           // 225: measured joints as given, missing ones w̄_M + E_M ĉ
  Eigen::VectorXd k;           // ĉ, N (for nothing missing: Eᵀ(w − w̄))
  JointMask modelEstimated{};  // the joints taken from the model (= the missing mask)
  double sigma2Mm2 = 0.0;      // σ² used
};

// w: 225 values, finite at the measured joints (missing joints' entries are ignored and
// may be NaN). Error(BadArgument) "joint completion: …" for a wrong size, a non-finite
// measured entry, a model checkModel rejects, σ² negative or non-finite; Error(BadData)
// when every joint is missing or the solve is not finite. Nothing missing: w unchanged.
JointCompletion completeJoints(const EigenwalkerModel& model,
                               const Eigen::Ref<const Eigen::VectorXd>& w, const JointMask& missing,
                               const CompletionOptions& options = {});

// [SECTION] Completion of a prepared trial

struct CompletedTrial {
  WalkingTrial trial;  // the model-estimated joints' frames synthesised on the
                       // trial's own time base (t_i = i / rate, ω and φ of the fit);
                       // trial.modelEstimated flags them
  FourierFit fit;      // fit of the measured joints (missing coefficients filled)
  JointCompletion completion;
};

// Fits the measured joints of a prepared trial (WalkingTrial::joints.missing), completes w
// from the model and fills the missing joints' columns. A trial with nothing missing is
// returned unchanged (fit of all joints, modelEstimated all false).
CompletedTrial completeWalkingTrial(const WalkingTrial& trial, const EigenwalkerModel& model,
                                    const CompletionOptions& options = {});

}  // namespace ew
