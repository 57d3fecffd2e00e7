#include "core/synth/synth_params.h"

#include <algorithm>
#include <cmath>

namespace ew {
namespace {

// A normal draw restricted to [lo, hi] by redrawing (no pile-up at the bounds); the
// clamp after 16 misses only guards against an absurd call.
double truncatedNormal(Rng& rng, double mean, double sd, double lo, double hi) {
  for (int attempt = 0; attempt < 16; ++attempt) {
    const double x = rng.normal(mean, sd);
    if (x >= lo && x <= hi) return x;
  }
  return std::clamp(mean, lo, hi);
}

// A ratio of stature with a small individual deviation (CV 3 %, see docs/SYNTHETIC.md).
double segment(Rng& rng, double heightMm, double ratio) {
  return heightMm * ratio * truncatedNormal(rng, 1.0, 0.03, 0.91, 1.09);
}

CurveStyle drawStyle(Rng& rng, double sdDeg) {
  CurveStyle s;
  for (size_t h = 0; h < s.cosDeg.size(); ++h) {
    s.cosDeg[h] = truncatedNormal(rng, 0.0, sdDeg, -3 * sdDeg, 3 * sdDeg);
    s.sinDeg[h] = truncatedNormal(rng, 0.0, sdDeg, -3 * sdDeg, 3 * sdDeg);
  }
  return s;
}

// Stature (ANSUR II, Gordon et al. 2014): men 1756 ± 69 mm, women 1629 ± 64 mm.
constexpr double kHeightMeanMm[2] = {1756.0, 1629.0};  // [male, female]
constexpr double kHeightSdMm[2] = {69.0, 64.0};
// Self-selected cadence (Perry & Burnfield 2010, Table 4-1): men 111, women 117 steps/min.
constexpr double kCadenceSpm[2] = {111.0, 117.0};
// Walk ratio step length / cadence, normalised by stature (Sekiya & Nagasaki 1998),
// calibrated so the mean stride is Perry & Burnfield's 1.46 m (men) and 1.28 m (women).
constexpr double kWalkRatioPerSpm[2] = {1460.0 / (2 * 1756.0 * 111.0),
                                        1280.0 / (2 * 1629.0 * 117.0)};
constexpr double kReferenceSpeedMps = 1.37;  // Perry & Burnfield's mean free speed

void drawGait(SynthParams& p, Rng& rng) {
  const int sex = p.female ? 1 : 0;
  const double h = p.body.heightMm;
  // Taller people step more slowly (pendulum scaling, f ∝ 1/√leg length) and longer.
  p.cadenceSpm = kCadenceSpm[sex] * std::sqrt(kHeightMeanMm[sex] / h) *
                 truncatedNormal(rng, 1.0, 0.065, 0.8, 1.2);
  const double walkRatio = kWalkRatioPerSpm[sex] * truncatedNormal(rng, 1.0, 0.08, 0.76, 1.24);
  p.strideLengthMm = 2.0 * walkRatio * h * p.cadenceSpm;
  const double speedRatio = p.speedMps() / kReferenceSpeedMps;
  // The thigh's mean angle to the vertical varies little between people: the feet land
  // about as far ahead of the pelvis as they leave behind it (differences in hip flexion
  // are mostly pelvic tilt, which moves the trunk, not the feet). A larger offset here
  // shifts the ankle's fore-aft timing against its lift, unlike real walkers.
  p.hipOffsetDeg = truncatedNormal(rng, 0.0, 0.75, -2.25, 2.25);
  // Knee flexion grows with speed (Lelas et al. 2003): ~+25 % of the curve per +100 % speed.
  p.kneeGain = truncatedNormal(rng, 1.0, 0.08, 0.76, 1.24) * (1.0 + 0.25 * (speedRatio - 1.0));
  p.kneeOffsetDeg = truncatedNormal(rng, 0.0, 1.5, -4.5, 4.5);
  p.ankleGain = truncatedNormal(rng, 1.0, 0.15, 0.6, 1.5);
  p.hipStyle = drawStyle(rng, 1.0);
  p.kneeStyle = drawStyle(rng, 1.5);
  p.ankleStyle = drawStyle(rng, 1.0);
  p.shoulderStyle = drawStyle(rng, 1.0);
}

void drawPelvisTrunk(SynthParams& p, Rng& rng) {
  p.pelvisRotationDeg = truncatedNormal(rng, 4.5, 1.5, 1.5, 9.0);
  p.pelvisObliquityDeg = truncatedNormal(rng, 3.5, 1.2, 1.0, 7.0);
  p.pelvisTiltDeg = truncatedNormal(rng, 1.5, 0.5, 0.5, 3.0);
  p.lateralSwayMm = truncatedNormal(rng, 22.0, 6.0, 8.0, 45.0);
  p.pelvisSurgeMm = truncatedNormal(rng, 20.0, 6.0, 6.0, 40.0);
  p.stepWidthMm = truncatedNormal(rng, 100.0, 25.0, 40.0, 180.0);
  p.trunkLeanDeg = truncatedNormal(rng, 4.0, 3.0, -3.0, 12.0);
  p.trunkRotationDeg = truncatedNormal(rng, 4.0, 1.5, 1.0, 9.0);
  p.trunkBendDeg = truncatedNormal(rng, 2.5, 0.8, 0.5, 5.0);
}

void drawArms(SynthParams& p, Rng& rng) {
  p.armSwingDeg = truncatedNormal(rng, 16.0, 5.0, 3.0, 30.0);
  p.shoulderMeanDeg = truncatedNormal(rng, -4.0, 3.0, -12.0, 5.0);
  p.armAbductionDeg = truncatedNormal(rng, 6.0, 2.0, 2.0, 12.0);
  p.elbowMeanDeg = truncatedNormal(rng, 25.0, 7.0, 8.0, 45.0);
  p.elbowSwingDeg = truncatedNormal(rng, 10.0, 4.0, 2.0, 20.0);
  p.armLagCycles = truncatedNormal(rng, 0.03, 0.02, -0.03, 0.10);
}

void drawAsymmetry(SynthParams& p, Rng& rng) {
  p.toeOutDeg = truncatedNormal(rng, 7.0, 4.0, -5.0, 20.0);
  p.asymmetry.hipGainRatio = truncatedNormal(rng, 1.0, 0.03, 0.9, 1.1);
  p.asymmetry.kneeGainRatio = truncatedNormal(rng, 1.0, 0.04, 0.88, 1.12);
  p.asymmetry.armSwingRatio = truncatedNormal(rng, 1.0, 0.10, 0.7, 1.3);
  p.asymmetry.leftPhaseOffset = truncatedNormal(rng, 0.0, 0.006, -0.02, 0.02);
  p.strideTimeCv = truncatedNormal(rng, 0.02, 0.006, 0.008, 0.04);
}

JointPlacement drawPlacement(bool female, Rng& rng) {
  JointPlacement j;
  for (auto& shoulder : j.shoulderMm) {
    for (double& v : shoulder) v = truncatedNormal(rng, 0.0, 10.0, -30.0, 30.0);
  }
  for (double& v : j.headMm) v = truncatedNormal(rng, 0.0, 12.0, -36.0, 36.0);
  for (double& v : j.kneeValgusDeg) v = truncatedNormal(rng, 0.0, 2.5, -7.5, 7.5);
  // Carrying angle: about 10° in men, 13° in women (Paraskevas et al. 2004), SD 3°.
  for (double& v : j.carryingAngleDeg)
    v = truncatedNormal(rng, female ? 13.0 : 10.0, 3.0, 2.0, 22.0);
  // Leg-length difference: a few mm in most adults (Knutson 2005: mean 5 mm).
  j.leftLegRatio = truncatedNormal(rng, 1.0, 0.005, 0.985, 1.015);
  return j;
}

}  // namespace

BodyDimensions drawBody(double heightMm, bool female, Rng& rng) {
  BodyDimensions b;
  b.heightMm = heightMm;
  b.thighMm = segment(rng, heightMm, 0.245);
  b.shankMm = segment(rng, heightMm, 0.246);
  b.hipWidthMm = segment(rng, heightMm, female ? 0.110 : 0.100);
  b.trunkMm = segment(rng, heightMm, 0.310);
  b.neckHeadMm = segment(rng, heightMm, 0.110);
  b.shoulderWidthMm = segment(rng, heightMm, female ? 0.205 : 0.215);
  b.shoulderDropMm = segment(rng, heightMm, 0.045);
  b.shoulderBackMm = segment(rng, heightMm, 0.010);
  b.upperArmMm = segment(rng, heightMm, 0.162);
  b.forearmMm = segment(rng, heightMm, 0.146);
  b.handMm = segment(rng, heightMm, 0.108);
  b.footMm = segment(rng, heightMm, 0.152);
  b.ankleHeightMm = segment(rng, heightMm, 0.039);
  return b;
}

SynthParams drawSubjectParams(Rng& rng) {
  SynthParams p;
  p.female = rng.uniform() < 0.5;
  const int sex = p.female ? 1 : 0;
  const double h = truncatedNormal(rng, kHeightMeanMm[sex], kHeightSdMm[sex],
                                   kHeightMeanMm[sex] - 3 * kHeightSdMm[sex],
                                   kHeightMeanMm[sex] + 3 * kHeightSdMm[sex]);
  p.body = drawBody(h, p.female, rng);
  p.placement = drawPlacement(p.female, rng);
  drawGait(p, rng);
  drawPelvisTrunk(p, rng);
  drawArms(p, rng);
  drawAsymmetry(p, rng);
  return p;
}

SynthParams jitterTrialParams(const SynthParams& subject, Rng& rng) {
  // Between-trial variation of one person on one day: about 2 % in cadence and stride
  // length and about 1° in posture (test-retest spreads, docs/SYNTHETIC.md).
  SynthParams p = subject;
  p.cadenceSpm *= truncatedNormal(rng, 1.0, 0.02, 0.94, 1.06);
  p.strideLengthMm *= truncatedNormal(rng, 1.0, 0.015, 0.955, 1.045);
  p.hipOffsetDeg += truncatedNormal(rng, 0.0, 0.7, -2.1, 2.1);
  p.kneeOffsetDeg += truncatedNormal(rng, 0.0, 0.7, -2.1, 2.1);
  p.trunkLeanDeg += truncatedNormal(rng, 0.0, 0.7, -2.1, 2.1);
  p.armSwingDeg *= truncatedNormal(rng, 1.0, 0.06, 0.82, 1.18);
  return p;
}

}  // namespace ew
