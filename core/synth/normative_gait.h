#pragma once
// Normative sagittal joint angles of adult walking at self-selected speed, as smooth
// periodic functions of the gait cycle (phase 0 = initial contact of that leg, 1 = the
// next one). Tables read every 5 % of the cycle off the published mean curves of
// Winter (1991, "The biomechanics and motor control of human gait", normal cadence) and
// Perry & Burnfield (2010, "Gait analysis", ch. 5-8); docs/SYNTHETIC.md lists the key
// points each curve reproduces. The tables are turned into truncated Fourier series so
// the curves (and their derivatives) are smooth and periodic.

#include <array>
#include <vector>

namespace ew {

inline constexpr int kMaxHarmonics = 8;

// cos(2πh·phase) and sin(2πh·phase) for h = 1 … kMaxHarmonics, from one sin/cos pair by
// the angle-addition recurrence: many curves are evaluated at each phase, so the basis is
// computed once and shared.
struct HarmonicBasis {
  std::array<double, kMaxHarmonics> cos{}, sin{};
  explicit HarmonicBasis(double phase);
};

// f(phase) = a0 + Σ_{h=1..H} a_h cos(2πh·phase) + b_h sin(2πh·phase), degrees. H ≤ kMaxHarmonics.
struct PeriodicCurve {
  double a0 = 0.0;
  std::vector<double> a, b;  // a[h-1], b[h-1]

  double operator()(double phase) const { return (*this)(HarmonicBasis(phase)); }
  double operator()(const HarmonicBasis& basis) const;
  double mean() const { return a0; }
  int harmonics() const { return static_cast<int>(a.size()); }
};

// The trigonometric series of `samples` taken at phases k / n (k = 0 … n−1), truncated
// to `harmonics` (< n / 2): the least-squares fit, exact at the samples when untruncated.
PeriodicCurve periodicCurveFromSamples(const std::vector<double>& samples, int harmonics);

// `curve` shifted in phase: result(phase) = curve(phase − shift).
PeriodicCurve shiftedCurve(const PeriodicCurve& curve, double shift);

// amplitude · cos(2π·harmonic·(phase − peakPhase)) + mean: a peak at peakPhase.
PeriodicCurve cosineCurve(double mean, double amplitude, int harmonic, double peakPhase);

// Harmonics kept from the 20-point tables: 6 is enough for the knee's loading-response
// bump (width ~15 % of the cycle) while smoothing the reading error of the tables.
inline constexpr int kNormativeHarmonics = 6;

// Thigh angle from the vertical in the sagittal plane (+ flexion, knee forward):
// about +30° at initial contact, −8° at 55 %, peak +31° in terminal swing.
const PeriodicCurve& normativeHipFlexion();
// Knee flexion: 4° at contact, loading-response peak ~19° at 15 %, ~5° in midstance,
// ~40° at toe-off (62 %), swing peak ~61° at 73 %.
const PeriodicCurve& normativeKneeFlexion();
// Ankle dorsiflexion (+) relative to the neutral foot-perpendicular-to-shank: −4° after
// contact (first rocker), +10° at 45 %, −16° at 65 % (push-off), ~0° in swing.
const PeriodicCurve& normativeAnkleDorsiflexion();

}  // namespace ew
