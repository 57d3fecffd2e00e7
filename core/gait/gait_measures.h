#pragma once
// The spatiotemporal gait measures a clinical gait report gives, from any 3D walker in a
// canonical frame (METHOD §2: mm, x right, y forward, z up; progression may have been removed,
// as it is from prepared trials and from reconstructions), and the joint-angle curves over
// the normalised gait cycle.
//
// Definitions (Perry & Burnfield, Gait Analysis, 2nd ed., ch. 1; Baker, Measuring Walking,
// ch. 3), with the ankle centre standing for the foot, as the 15 joints have no heel or toe:
//   stride time     from a foot strike to the next strike of the same foot (mean over strides)
//   cadence         steps per minute = 120 / stride time
//   footprint       where a foot stood in one stance: its ankle's mean position over foot flat
//                   (10-30 % of the stride after its strike), on the floor
//   step length     from the other foot's footprint to this foot's next one, along y;
//                   stride length = right step + left step (the ankle at the strike event
//                   itself is no footprint: Zeni's strike comes while the foot still swings)
//   step width      the mediolateral (x) distance between the same two footprints
//   stance %        from a foot's strike to its foot off, in % of its stride; swing = 100 − stance
//   double support  both feet down: stance right % + stance left % − 100 (walking has no flight)
//   speed           the walker's progression when known (motion capture), else from the stance
//                   feet: a flat foot stands still on the floor, so the walker's speed is the
//                   pelvis's mean velocity (its least-squares line) minus the stance ankle's
//                   (the median over foot-flat windows of its slope) — whether the frame carries
//                   the walker forward or has its progression removed, as a reconstruction does.
// Footprints are put on the floor by adding the progression back (along y), or without it by
// taking the stance ankle's slope (x and y) out of its track. The slide is measured a
// little slow — the ankle is not quite still from 10 to 30 % — by a median 1.5 % (up to 4 %)
// on the shared walkers against their progression (docs/GAIT.md), and stride length with it.
// A side's stride counts only when its strike, foot off and next strike are all in the trial.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/gait/gait_events.h"

namespace ew {

struct StrideRecord {
  Side side = Side::Right;
  double strikeS = 0.0;      // this stride's foot strike
  double nextStrikeS = 0.0;  // the same foot's next strike
  double offS = NAN;         // its foot off in between (NaN when the trial lacks it)
};

struct GaitMeasures {
  GaitEventSet events;
  std::vector<StrideRecord> strides;  // complete strides of both feet, in time order
  double strideTimeS = NAN;  // strike to strike (the clinical definition)
  // The gait cycle's period from every event: each foot's strike-to-strike and off-to-off
  // intervals a stride apart, mean. Twice the intervals of a short trial (docs/GAIT.md).
  double strideTimeAllEventsS = NAN;
  double cadenceSpm = NAN;
  double stepLengthRightM = NAN;  // the right foot's step (right ankle ahead at right strike)
  double stepLengthLeftM = NAN;
  double strideLengthM = NAN;
  double stepWidthM = NAN;
  double speedMps = NAN;
  // "progression", "stance feet", "stance feet of a two-harmonic walker" (fourier_walker_gait.h)
  // or "stride length × stride frequency"
  std::string speedSource;
  double stanceFootSpeedMps = NAN;  // from the stance feet, whatever speedSource is
  double stanceRightPct = NAN;
  double stanceLeftPct = NAN;
  double stancePct = NAN;  // mean of the two sides (or the one side measured)
  double swingPct = NAN;
  double doubleSupportPct = NAN;
  std::vector<std::string> notes;  // what could not be measured, and why
};

// framesX45: T × 45 in a canonical frame at rateHz. progressionSpeedMps: the walker's mean
// speed when the frames had progression removed (WalkingTrial::speedMps), empty for a
// reconstruction; ignored, with a note, when it is under half the stance feet's speed (a
// treadmill, or frames whose progression was removed before they were given). Throws Error(BadArgument) naming `name` for a bad shape or rate and
// Error(BadData) when no complete stride of either foot is found (a trial shorter than a
// stride, or not walking). Measures the events cannot give are NaN with a note.
GaitMeasures measureGait(const Eigen::Ref<const Eigen::MatrixXd>& framesX45, double rateHz,
                         const GaitEventSet& events, std::optional<double> progressionSpeedMps,
                         const std::string& name);

// Curves over the normalised gait cycle: each stride of a side resampled to `samples`
// points from its strike (0 %) to its next strike (100 %), mean and SD over strides.
struct CycleCurve {
  std::string name;        // e.g. "knee_angle_r"
  Eigen::VectorXd meanDeg; // samples
  Eigen::VectorXd sdDeg;   // samples; 0 for one stride
  int strides = 0;
};

// The flexion curves a gait report shows (hip, knee, shoulder, elbow; both sides), from
// per-frame joint angles (core/gait/joint_angles.h, columns by name) at rateHz. A curve with
// no complete stride, or with a stride whose frames are not finite, is left out.
std::vector<CycleCurve> flexionCycleCurves(const Eigen::Ref<const Eigen::MatrixXd>& anglesDeg,
                                           const std::vector<std::string>& names, double rateHz,
                                           const GaitMeasures& measures, int samples = 101);

// The names flexionCycleCurves reports, right side then left.
const std::vector<std::string>& flexionCurveNames();

// The ankle's flexion curves (ankle_angle_r, ankle_angle_l; joint_angles.h's
// jointAnglesWithFeet), resampled as flexionCycleCurves does; none without the feet.
std::vector<CycleCurve> footCycleCurves(const Eigen::Ref<const Eigen::MatrixXd>& anglesDeg,
                                        const std::vector<std::string>& names, double rateHz,
                                        const GaitMeasures& measures, int samples = 101);

// The foot progression angle of each foot in stance (toe out positive; jointAnglesWithFeet's
// foot_progression_r/_l): its mean over each stride's foot flat, 10–30 % of the stride after
// the strike (the footprint's window), then over strides. NaN for a side without that column,
// a finite sample there or a stride.
struct FootProgression {
  double rightDeg = NAN, leftDeg = NAN;
};
FootProgression footProgressionDeg(const Eigen::Ref<const Eigen::MatrixXd>& anglesDeg,
                                   const std::vector<std::string>& names, double rateHz,
                                   const GaitMeasures& measures);

// A measure by its column name, as `gait --out` writes it and the viewer's report exports it:
// cadence_spm, stride_time_s, stride_length_m, step_length_r_m, step_length_l_m, step_width_m,
// speed_mps, stance_pct, swing_pct, double_support_pct, hip_flexion_range_deg,
// knee_flexion_range_deg, ankle_flexion_range_deg (these three from `curves`). NaN for another
// name or a measure not taken.
double gaitMeasureByName(const GaitMeasures& g, const std::vector<CycleCurve>& curves, const std::string& key);

// The range (max − min, degrees) of a flexion's stride-averaged curve, the mean over the two
// sides present; `base` without the side suffix ("knee_angle", "hip_flexion"). NaN when
// neither side has a curve.
double flexionRangeDeg(const std::vector<CycleCurve>& curves, const std::string& base);

}  // namespace ew
