#pragma once
// The Fourier representation of one walker (METHOD §3; Zhang & Troje 2007, eq. 3.1–3.2):
//
//   p(t) = p0 + p1 sin(ωt+φ) + q1 cos(ωt+φ) + p2 sin(2(ωt+φ)) + q2 cos(2(ωt+φ))
//
// Frames are rows (t_i = i / fs, i counted from the first row given, in seconds); columns
// are joint-major: 45 (x,y,z per joint, mm) in 3D or 30 (u,v per joint, mm) in 2D.
// w = [p0, p1, q1, p2, q2] is block-major, then joint, then coordinate: 225 values in 3D,
// 150 in 2D. ω (rad/s) and φ (rad) are kept beside w, not inside it.

#include <Eigen/Core>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace ew {

inline constexpr int kFourierBlocks = 5;            // p0, p1, q1, p2, q2
inline constexpr int kFourierDims3 = 5 * 45;        // 225
inline constexpr int kFourierDims2 = 5 * 30;        // 150

struct FourierFitOptions {
  // Stride frequency from gait events or foot contacts (GaitCycles::strideHz · 2π).
  // The scan still runs; see fitFourier for how the two are combined.
  std::optional<double> omegaHintRadS;
  // Use exactly this ω (no scan): for data whose frequency is known, e.g. synthetic tests
  // or 2D frames rendered from a known walker.
  std::optional<double> omegaFixedRadS;
  double omegaMinRadS = 2.0 * std::numbers::pi * 0.3;  // METHOD §3 scan range
  double omegaMaxRadS = 2.0 * std::numbers::pi * 2.5;
  // More missing frames than this fraction is an error (METHOD §3: the fit must see the cycle).
  double maxMissingFraction = 0.2;
  // The hint and the scan's best ω "agree" when within this relative difference.
  double hintAgreement = 0.10;
  // Named in error messages and warnings.
  std::string file;
};

struct FourierFit {
  Eigen::VectorXd w;          // 225 (3D) or 150 (2D): [p0, p1, q1, p2, q2], mm
  double omegaRadS = 0.0;     // fundamental angular frequency ω
  double phaseRad = 0.0;      // φ in (−π, π]: fundamental of the ankle reference is +sine
  double h1Share = 0.0;       // fraction of the variance around p0 in the 1st harmonic
  double h2Share = 0.0;       // … in the 2nd harmonic
  double residualShare = 0.0; // … left in the residual (measured, not 1 − h1 − h2)
  double cycles = 0.0;        // gait cycles covered by the frames: ω · T / (2π fs)
  int framesUsed = 0;
  int framesDropped = 0;      // frames with a NaN, left out of the fit
  double scanOmegaRadS = 0.0; // best ω of the variance-explained scan (0 if ω was fixed)
  std::string omegaSource;    // "fixed", "scan", "scan, agrees with hint", "hint", …
  std::vector<std::string> warnings;

  int frameDims() const { return static_cast<int>(w.size()) / kFourierBlocks; }  // 45 or 30
};

// Fits w, ω and φ to frames (T × 45 or T × 30, mm) sampled at rateHz.
//
// ω: the variance explained by the 2-harmonic fit, as a function of ω, is scanned over
// [omegaMin, omegaMax] (never below one cycle of the data) on a grid of step π/(4·duration)
// using the data's 6 dominant principal components (exact when the centred frames have
// rank ≤ 6, as a 2-harmonic walker's have: ≤ 4), then the best grid maximum is refined by Brent's method to
// 1e-9 relative. With a hint, the grid maximum nearest the hint is refined too:
//   - same peak as the scan's best  → that ω ("scan, agrees with hint");
//   - different peak, but within hintAgreement of the hint and explaining at most 2
//     percentage points less variance → the hint's peak, with a warning ("hint");
//   - otherwise → the scan's best, with a warning naming both frequencies.
// NaNs: a frame with any NaN is dropped as a whole (one time base for every joint, so the
// ω scan and the phase reference see the same samples); more than maxMissingFraction of
// the frames dropped → Error(BadData).
// Fewer than 0.99 cycles at the chosen ω (or at omegaMax) → Error(BadData).
// Every error names options.file and reads "Fourier fit: …". Error(BadArgument) for columns
// other than 45/30, a rate that is not positive and finite, a fixed ω or hint that is not
// positive and finite, a scan range other than 0 < min < max < ∞, a missing fraction
// outside [0, 1]. Error(BadData) for no frames, fewer than 8 complete ones, coordinates
// whose squares overflow, a rate at or below 4× the stride frequency (the second harmonic
// aliases: 2ω ≥ π·fs), or a duration needing more than 1e6 scan points (a wrong rate).
// A frame with ±∞ is a missing frame, like NaN. The result is always finite.
FourierFit fitFourier(const Eigen::Ref<const Eigen::MatrixXd>& frames, double rateHz,
                      const FourierFitOptions& options = {});

// p(t) for each time (s): rows = times, columns = w.size() / 5 (45 or 30). w, ω, φ and
// the times must be finite (Error(BadArgument) "Fourier synthesis: …").
Eigen::MatrixXd synthesizeFrames(const Eigen::Ref<const Eigen::VectorXd>& w, double omegaRadS,
                                 double phaseRad, const Eigen::Ref<const Eigen::VectorXd>& timesS);

// The synthesis basis [1, sin θ, cos θ, sin 2θ, cos 2θ] at θ = ω t + φ, a row per time (T × 5):
// synthesizeFrames(w, ω, φ, t) = fourierBasis(ω, φ, t) · (w as 5 blocks of w.size() / 5)ᵀ.
// Unchecked (synthesizeFrames checks); for a caller synthesising many walkers at one ω and φ.
Eigen::MatrixXd fourierBasis(double omegaRadS, double phaseRad, const Eigen::Ref<const Eigen::VectorXd>& timesS);

// fourierBasis's derivative with respect to the phase φ (T × 5): [0, cos θ, −sin θ, 2 cos 2θ,
// −2 sin 2θ]. With respect to ω it is this times each row's time.
Eigen::MatrixXd fourierBasisPhaseDerivative(double omegaRadS, double phaseRad,
                                            const Eigen::Ref<const Eigen::VectorXd>& timesS);

// Times i / rateHz for i = 0 … count − 1 (the frame times fitFourier assumes). count ≥ 0
// and a positive, finite rate, else Error(BadArgument).
Eigen::VectorXd frameTimes(int count, double rateHz);

// Re-expresses w for another phase origin: the returned w' satisfies
// synthesizeFrames(w', ω, toPhase, t) == synthesizeFrames(w, ω, fromPhase, t) for all t
// (harmonic h's (p, q) pair rotates by h·(fromPhase − toPhase)). w: 225 or 150 values;
// phases finite (else Error(BadArgument)).
Eigen::VectorXd rephase(const Eigen::Ref<const Eigen::VectorXd>& w, double fromPhaseRad,
                        double toPhaseRad);

}  // namespace ew
