#pragma once
// Reconstruction errors (METHOD §7; Zhang & Troje 2007, eq. 4.1–4.4).
//
// Depth d_j(t) = −x_j sin α + y_j cos α of joint j at view α (METHOD §5), mm.
//   E_abs(j) = mean over one cycle of (d_j(t) − d̃_j(t))²       (mm²)
//            = Δp0² + ½(Δp1² + Δq1² + Δp2² + Δq2²)  for Fourier vectors (closed form)
//   E_a      = mean over the 15 joints of E_abs(j)
//   σ_m²     = (1/15) Σ_j Var_t d_j(t) = (1/15) Σ_j ½(p1² + q1² + p2² + q2²) of the true depth
//   E_rel(j) = E_abs(j) / σ_m²,  E_r = mean over joints
// Both walkers must share ω and φ (the reconstruction is synthesised with the test
// walker's own ω and φ, METHOD §6), so Fourier coefficients compare directly.
//
// Preconditions (Error "error measures: …"): walkers of 225 finite values, frames T × 45,
// finite angles, rates positive and finite (BadArgument); at least one complete frame, two
// for depthErrorsFrames (BadData). A true walker without depth motion (σ_m² = 0) gives
// E_rel = NaN on purpose: the relative error is undefined, E_abs is still reported.

#include <Eigen/Core>
#include <array>

#include "core/common/skeleton.h"

namespace ew {

struct DepthErrors {
  Eigen::VectorXd absPerJoint;  // E_abs(j), 15, mm²
  Eigen::VectorXd relPerJoint;  // E_rel(j), 15
  double absMean = 0.0;         // E_a, mm²
  double relMean = 0.0;         // E_r
  double sigmaM2Mm2 = 0.0;      // σ_m², mm²
};

// Against the walker's own 2-harmonic Fourier approximation, exactly one cycle
// (closed form). wTrue, wRec: 225.
DepthErrors depthErrors(const Eigen::Ref<const Eigen::VectorXd>& wTrue,
                        const Eigen::Ref<const Eigen::VectorXd>& wRec, double alphaDeg);

// Against raw frames (T × 45; frames with a NaN are skipped): the reconstruction is
// synthesised at t_i = i / rateHz with ω, φ and compared frame by frame; σ_m² here is
// the frames' own depth variance over time (mean over joints). Throws Error(BadData)
// when no frame is complete.
DepthErrors depthErrorsFrames(const Eigen::Ref<const Eigen::MatrixXd>& framesTrue, double rateHz,
                              const Eigen::Ref<const Eigen::VectorXd>& wRec, double omegaRadS,
                              double phaseRad, double alphaDeg);

// Variance of the missing dimension, σ_m² of the true walker at α (mm²).
double depthVarianceMm2(const Eigen::Ref<const Eigen::VectorXd>& wTrue, double alphaDeg);

// MPJPE (mm): mean over joints and time of the 3D Euclidean error. Fourier version: over
// one cycle, sampled at `samples` equally spaced phases (the mean of a norm has no closed
// form; 120 samples ≈ a 120 Hz cycle).
double mpjpe(const Eigen::Ref<const Eigen::VectorXd>& wTrue,
             const Eigen::Ref<const Eigen::VectorXd>& wRec, int samples = 120);

// MPJPE of each joint (15, mm), same sampling as mpjpe: the errors of measured and of
// model-estimated joints (core/eigenwalker/joint_completion.h) are reported apart.
Eigen::VectorXd mpjpePerJoint(const Eigen::Ref<const Eigen::VectorXd>& wTrue,
                              const Eigen::Ref<const Eigen::VectorXd>& wRec, int samples = 120);

// Mean of perJoint (15) over the joints flagged in `joints`; NaN when none is flagged
// (no such joint: nothing to report, not a zero error).
double meanOverJoints(const Eigen::Ref<const Eigen::VectorXd>& perJoint,
                      const std::array<bool, kJointCount>& joints);

// MPJPE against raw frames (T × 45; NaN frames skipped), reconstruction at ω, φ.
double mpjpeFrames(const Eigen::Ref<const Eigen::MatrixXd>& framesTrue, double rateHz,
                   const Eigen::Ref<const Eigen::VectorXd>& wRec, double omegaRadS,
                   double phaseRad);

// MPJPE (mm) of frames against frames (both T × 45) once their mean offset is taken out: a
// camera fit places the walker up to a translation (the camera experiment's score).
double mpjpeWithoutTranslation(const Eigen::Ref<const Eigen::MatrixXd>& rec,
                               const Eigen::Ref<const Eigen::MatrixXd>& truth);

// |α̂ − α| wrapped to [0°, 180°].
double viewAngleErrorDeg(double estimatedDeg, double trueDeg);

}  // namespace ew
