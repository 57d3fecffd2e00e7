#pragma once
// The parameters of one synthetic walker: body dimensions and gait style, and the
// documented distributions they are drawn from (docs/SYNTHETIC.md has the table and the
// sources). Lengths in mm, angles in degrees, phases in gait cycles.

#include <array>
#include <cstdint>

#include "core/synth/random.h"

namespace ew {

// Joint-centre geometry (METHOD §1 joints) plus the foot, which the kinematics needs for
// floor contact and the BVH writer for the toes.
struct BodyDimensions {
  double heightMm = 1750.0;
  double thighMm = 0.0;          // hip centre → knee centre
  double shankMm = 0.0;          // knee centre → ankle centre
  double hipWidthMm = 0.0;       // between the hip joint centres
  double trunkMm = 0.0;          // pelvis (mid-hips) → sternum (jugular notch)
  double neckHeadMm = 0.0;       // sternum → head centre
  double shoulderWidthMm = 0.0;  // between the glenohumeral centres
  double shoulderDropMm = 0.0;   // glenohumeral centre below the jugular notch
  double shoulderBackMm = 0.0;   // … and behind it
  double upperArmMm = 0.0;       // shoulder → elbow
  double forearmMm = 0.0;        // elbow → wrist
  double handMm = 0.0;           // wrist → fingertip (BVH end site only)
  double footMm = 0.0;           // heel → toe tip
  double ankleHeightMm = 0.0;    // ankle centre above the sole
};

// The left/right differences of one walker (ratios left over right; phase in cycles).
struct Asymmetry {
  double hipGainRatio = 1.0;
  double kneeGainRatio = 1.0;
  double armSwingRatio = 1.0;
  double leftPhaseOffset = 0.0;  // left contact at 0.5 + this (fraction of the cycle)
};

// Individual shape of a curve beyond its amplitude: extra 2nd-4th harmonics (degrees).
struct CurveStyle {
  std::array<double, 3> cosDeg{};
  std::array<double, 3> sinDeg{};
};

// Individual joint-centre geometry beyond the proportions: where a person's joints sit
// relative to their segments (and where a lab's joint-centre estimate puts them, which
// differs by 10-20 mm between methods: docs/SYNTHETIC.md). Constant per walker, in the
// segment's own frame, so bone lengths stay constant. Index [right, left].
struct JointPlacement {
  std::array<std::array<double, 3>, 2> shoulderMm{};  // thorax frame: x right, y forward, z up
  std::array<double, 3> headMm{};                     // head frame
  std::array<double, 2> kneeValgusDeg{};              // shank tilted out (+) from the thigh plane
  std::array<double, 2> carryingAngleDeg{};           // forearm abducted beyond the upper arm
  double leftLegRatio = 1.0;                          // left thigh and shank over right
};

struct SynthParams {
  bool female = false;
  BodyDimensions body;
  JointPlacement placement;

  // Spatio-temporal targets at self-selected speed.
  double cadenceSpm = 113.0;       // steps per minute
  double strideLengthMm = 1410.0;  // the hip excursion is solved to reach it

  // Sagittal angles: normative curve × gain (about its mean) + offset + style.
  double hipGain = 1.0;  // solved from strideLengthMm (walkerKinematics)
  double hipOffsetDeg = 0.0;
  double kneeGain = 1.0;
  double kneeOffsetDeg = 0.0;
  double ankleGain = 1.0;
  CurveStyle hipStyle, kneeStyle, ankleStyle, shoulderStyle;

  // Pelvis and trunk (amplitudes of the oscillation, degrees / mm).
  double pelvisRotationDeg = 4.5;   // transverse, peak at contact of the same side
  double pelvisObliquityDeg = 3.5;  // frontal, contralateral drop in loading response
  double pelvisTiltDeg = 1.5;       // sagittal, two per stride (carried by the trunk)
  double lateralSwayMm = 22.0;      // pelvis towards the stance leg
  double pelvisSurgeMm = 20.0;      // fore-aft oscillation about constant speed, peak to peak
  double stepWidthMm = 100.0;       // between the ankle centres in stance
  double trunkLeanDeg = 4.0;        // mean forward lean of pelvis → sternum
  double trunkRotationDeg = 4.0;    // thorax rotation, opposite the pelvis
  double trunkBendDeg = 2.5;        // lateral bend towards the stance side

  // Arms.
  double armSwingDeg = 16.0;      // shoulder flexion amplitude (half the range)
  double shoulderMeanDeg = -4.0;  // mean shoulder flexion (− = arm behind the trunk line)
  double armAbductionDeg = 6.0;
  double elbowMeanDeg = 25.0;
  double elbowSwingDeg = 10.0;  // elbow flexion amplitude (half the range)
  double armLagCycles = 0.03;   // arm swing lags the opposite leg

  double toeOutDeg = 7.0;  // foot progression angle (BVH toes only)
  Asymmetry asymmetry;

  // Trial-level variability.
  double strideTimeCv = 0.02;  // cycle-to-cycle stride time variation (SD / mean)

  double strideHz() const { return cadenceSpm / 120.0; }
  double speedMps() const { return strideLengthMm * strideHz() / 1000.0; }
};

// Anthropometric proportions of stature (Winter 2009, Fig. 4.1, after Drillis & Contini
// 1966) with a small per-walker variation of each ratio.
BodyDimensions drawBody(double heightMm, bool female, Rng& rng);

// A whole walker from the population distributions of docs/SYNTHETIC.md.
SynthParams drawSubjectParams(Rng& rng);

// Another trial of the same walker: small day-to-day variation of the gait parameters
// (cadence, stride length, angle offsets), body unchanged.
SynthParams jitterTrialParams(const SynthParams& subject, Rng& rng);

}  // namespace ew
