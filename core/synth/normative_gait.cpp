#include "core/synth/normative_gait.h"

#include <cmath>
#include <numbers>

namespace ew {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Mean adult curves every 5 % of the cycle (0 % … 95 %), degrees, read off Winter (1991)
// Fig. 2.4-2.6 and Perry & Burnfield (2010) Fig. 5-1, 6-1, 7-1 (values rounded to 1°).
const std::vector<double> kHipTable = {30, 29, 27, 23, 19, 14, 10, 6,  2,  -2,
                                       -6, -8, -5, 2,  11, 19, 25, 29, 31, 31};
const std::vector<double> kKneeTable = {4,  11, 17, 19, 17, 13, 9,  6,  5,  6,
                                        10, 19, 32, 47, 58, 61, 55, 41, 23, 9};
const std::vector<double> kAnkleTable = {0, -4, -3, 0,   3,   5,  7,  8, 9, 10,
                                         8, 2,  -9, -16, -12, -5, -1, 1, 1, 0};

}  // namespace

HarmonicBasis::HarmonicBasis(double phase) {
  cos[0] = std::cos(kTwoPi * phase);
  sin[0] = std::sin(kTwoPi * phase);
  for (size_t h = 1; h < kMaxHarmonics; ++h) {
    cos[h] = cos[h - 1] * cos[0] - sin[h - 1] * sin[0];
    sin[h] = sin[h - 1] * cos[0] + cos[h - 1] * sin[0];
  }
}

double PeriodicCurve::operator()(const HarmonicBasis& basis) const {
  double value = a0;
  for (size_t h = 0; h < a.size(); ++h) value += a[h] * basis.cos[h] + b[h] * basis.sin[h];
  return value;
}

PeriodicCurve cosineCurve(double mean, double amplitude, int harmonic, double peakPhase) {
  PeriodicCurve c;
  c.a0 = mean;
  c.a.assign(static_cast<size_t>(harmonic), 0.0);
  c.b.assign(static_cast<size_t>(harmonic), 0.0);
  c.a.back() = amplitude;
  return shiftedCurve(c, peakPhase);
}

PeriodicCurve periodicCurveFromSamples(const std::vector<double>& samples, int harmonics) {
  // Equally spaced samples of a period: the trigonometric functions are orthogonal on
  // the grid, so the least-squares coefficients are the discrete Fourier sums.
  const auto n = static_cast<double>(samples.size());
  PeriodicCurve c;
  for (double s : samples) c.a0 += s / n;
  for (int h = 1; h <= harmonics; ++h) {
    double ah = 0.0, bh = 0.0;
    for (size_t k = 0; k < samples.size(); ++k) {
      const double angle = kTwoPi * h * static_cast<double>(k) / n;
      ah += samples[k] * std::cos(angle);
      bh += samples[k] * std::sin(angle);
    }
    c.a.push_back(2.0 * ah / n);
    c.b.push_back(2.0 * bh / n);
  }
  return c;
}

PeriodicCurve shiftedCurve(const PeriodicCurve& curve, double shift) {
  // cos(h(θ − δ)) = cos hθ cos hδ + sin hθ sin hδ; sin(h(θ − δ)) = sin hθ cos hδ − cos hθ sin hδ.
  PeriodicCurve out = curve;
  for (size_t h = 0; h < curve.a.size(); ++h) {
    const double d = kTwoPi * static_cast<double>(h + 1) * shift;
    out.a[h] = curve.a[h] * std::cos(d) - curve.b[h] * std::sin(d);
    out.b[h] = curve.b[h] * std::cos(d) + curve.a[h] * std::sin(d);
  }
  return out;
}

const PeriodicCurve& normativeHipFlexion() {
  static const PeriodicCurve curve = periodicCurveFromSamples(kHipTable, kNormativeHarmonics);
  return curve;
}

const PeriodicCurve& normativeKneeFlexion() {
  static const PeriodicCurve curve = periodicCurveFromSamples(kKneeTable, kNormativeHarmonics);
  return curve;
}

const PeriodicCurve& normativeAnkleDorsiflexion() {
  static const PeriodicCurve curve = periodicCurveFromSamples(kAnkleTable, kNormativeHarmonics);
  return curve;
}

}  // namespace ew
