#pragma once
// Experiment "lower-body" (issue 12; beyond the paper): a lower-body marker set measures
// the pelvis, hips, knees and ankles; how well does the eigenwalker model estimate the
// trunk, head and arms from them (core/eigenwalker/joint_completion.h)?
//
// Protocol: leave-one-subject-out (leave_one_out.h). The held-out walker's own 3D Fourier
// vector w keeps the seven lower-body joints (all 5 blocks, x,y,z); the other eight are
// estimated from the fold's model by the conditional-Gaussian (MAP) completion
//   ĉ = (E_Oᵀ E_O + σ² Λ⁻¹)⁻¹ E_Oᵀ (w_O − w̄_O),  ŵ_M = w̄_M + E_M ĉ
// ("map" with the evaluation's σ², "lsq" with σ² = 0) and scored per joint by MPJPE over
// one cycle (METHOD §7). Baseline "mean": the fold model's mean walker's joints in their
// place — the same canonical frame (METHOD §2) and phase alignment (METHOD §3), so no other
// placement is needed. The measured joints are kept as measured: their error is 0 by
// construction and is not listed.

#include <array>
#include <string>
#include <vector>

#include "core/experiments/leave_one_out.h"
#include "core/gait/missing_joints.h"

namespace ew {

// The joints kept: pelvis, hips, knees, ankles.
JointMask lowerBodyMeasured();

// One held-out walker × estimated joint × method.
struct LowerBodyRow {
  std::string subject;
  std::string walker;
  std::string joint;   // METHOD §1 name of an estimated joint
  std::string method;  // "map", "lsq" or "mean" (baseline)
  double mpjpeMm = 0;  // MPJPE of that joint over one cycle, mm
};

// Error(BadArgument) "lower body: …" for σ² negative or non-finite, folds that do not
// index `walkers`, or no method. Per fold on `threads` threads.
std::vector<LowerBodyRow> lowerBodyErrors(const std::vector<ExperimentWalker>& walkers,
                                          const std::vector<Fold>& folds, bool lsq, bool map,
                                          double sigma2Mm2, int threads);

// Mean MPJPE (mm) of each method per estimated joint, and over all estimated joints
// ("all"), in joint order: {method, joint, mean}.
struct LowerBodySummary {
  std::string method, joint;
  double meanMpjpeMm = 0;
};
std::vector<LowerBodySummary> summarizeLowerBody(const std::vector<LowerBodyRow>& rows);

}  // namespace ew
