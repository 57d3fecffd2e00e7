#pragma once
// Gait events — foot strike and foot off of each foot — from the kinematics of any 3D walker
// (measured, reconstructed or synthesised), or from a file's own events (a C3D EVENT group).
//
// Kinematic events follow Zeni, Richards & Higginson (2008, Gait & Posture 27:710): in the
// walker's own frame, a foot strikes where its forward distance from the pelvis is largest and
// leaves the floor where it is smallest. Zeni use the heel for the strike and the toe for the
// foot off; the 15 joints have neither, so both come from the ankle centre. Extremes are
// located to a fraction of a frame by a parabola through the three samples around them.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/common/skeleton.h"
#include "core/common/trial.h"

namespace ew {

inline Joint ankleOf(Side side) { return side == Side::Left ? Joint::LAnkle : Joint::RAnkle; }

struct FootEvents {
  std::vector<double> strikesS;  // seconds from row 0, ascending
  std::vector<double> offsS;
};

struct GaitEventSet {
  FootEvents right, left;
  std::string method;  // "kinematics" or "file events"

  const FootEvents& of(Side side) const { return side == Side::Right ? right : left; }
};

// The ankle's forward lead on the pelvis (mm), smoothed over ~50 ms: y of the ankle minus y of
// the pelvis in a canonical frame (METHOD §2: y forward). framesX45: T × 45.
Eigen::VectorXd ankleLeadMm(const Eigen::Ref<const Eigen::MatrixXd>& framesX45, double rateHz,
                            Side side);

// The forward lead on the pelvis (mm) of a foot's heel or toe (feetX12: JointTrial::feetMm in
// the same canonical frame as framesX45), smoothed as the ankle's.
Eigen::VectorXd footPointLeadMm(const Eigen::Ref<const Eigen::MatrixXd>& framesX45,
                                const Eigen::Ref<const Eigen::MatrixXd>& feetX12, double rateHz, FootPoint p);

// A signal smoothed by a moving mean over ~50 ms (the window shortened at the ends).
Eigen::VectorXd smoothedLead(const Eigen::VectorXd& raw, double rateHz);

// Rows where `signal` has a local maximum above mean + 0.3·(max − mean) that dominates
// ±0.5/kMaxStrideHz seconds (one foot strikes at most kMaxStrideHz times a second).
std::vector<int> dominantPeaks(const Eigen::VectorXd& signal, double rateHz);

// The sub-frame position of the extreme at row i (a parabola through rows i−1, i, i+1;
// i itself at the ends), in rows.
double refinedExtreme(const Eigen::VectorXd& signal, int i);

// The ankle is at its rearmost while the toe still pushes: against the Schreiber-Moissenet
// C3D events (18 trials; docs/GAIT.md), Zeni's foot off from the ankle comes 52.4 ± 18.2 ms
// early and his strike 30.9 ± 14.7 ms early. Stance and swing are the time between the two,
// so the foot off is put this fraction of the stride after the ankle's rearmost point: the
// difference of the two, each as a fraction of its trial's stride (a slow walker's lag is
// longer). tests/gait/test_gait_measures.cpp measures it again, and again leaving each trial out.
inline constexpr double kAnkleFootOffLagOfStride = 0.0185;

// framesX45 in a canonical frame (x right, y forward, z up; progression may be removed).
// Empty lists when the trial is too short or not finite. footOffLag: see
// kAnkleFootOffLagOfStride, scaled by the median stride of both feet's strikes (0 gives Zeni's
// foot off from the ankle as it is; so does a trial with no complete stride).
GaitEventSet gaitEventsFromKinematics(const Eigen::Ref<const Eigen::MatrixXd>& framesX45,
                                      double rateHz, double footOffLag = kAnkleFootOffLagOfStride);

// A walk known to repeat every 1 / strideHz seconds (a Fourier walker synthesised at its own
// ω): each ankle's lead on the pelvis is fitted with harmonics of strideHz (least squares, up
// to the fourth), and Zeni's events put where that periodic lead is largest (strikes) and
// smallest (foot offs, with footOffLag of the stride), one of each per stride over the
// frames. Kinematic peaks of a short or oddly shaped walk can count two strikes in one
// stride; a periodic walk has one. Empty lists as gaitEventsFromKinematics's, and for a
// strideHz outside kMinStrideHz-kMaxStrideHz.
GaitEventSet gaitEventsOfPeriodicWalk(const Eigen::Ref<const Eigen::MatrixXd>& framesX45, double rateHz,
                                      double strideHz, double footOffLag = kAnkleFootOffLagOfStride);

// Zeni's rule on the points he used, where the input has the feet (JointTrial::feetMm): the
// strike where the heel is foremost on the pelvis, the foot off where the toe is rearmost.
// Against the Schreiber-Moissenet C3D events (18 trials; docs/GAIT.md, "Events from the
// feet") the heel's foremost point comes 32.5 ± 13.8 ms before the strike and the toe's
// rearmost 12.0 ± 11.6 ms before the foot off: the toe needs no lag, and the strike is put
// this fraction of the stride after the heel's foremost point, the difference of the two
// leads (stance otherwise reads 1.6 points long). FeetOnSharedWalkers
// (tests/gait/test_gait_measures.cpp) measures it again, and again leaving each trial out.
inline constexpr double kHeelStrikeLagOfStride = 0.0184;

// A foot's heel and toe stand in for its ankle when both are seen together over a run of at
// least this share of the frames (a detector's feet drop out where the walker enters or leaves
// the picture); the events are then the run's alone.
inline constexpr double kMinFeetSeenShare = 0.8;

// Each foot's strikes from its heel and its foot offs from its toe over the longest run where
// both points are finite, when it holds kMinFeetSeenShare of the frames; the ankle's events (gaitEventsFromKinematics, with its foot-off lag) for a foot
// that lacks either, so that a foot's strike and foot off always share one lead (the toe's
// accurate foot off after the ankle's early strike read stance 1.7 points long on
// gait-pig-nz.c3d, which has toe markers and no heels). method: "kinematics (heel and toe)" with
// both feet, "kinematics (heel and toe of one foot, the other's ankle)" with one; feetX12 empty,
// of another shape or lacking a point of each foot gives gaitEventsFromKinematics's events
// unchanged. heelStrikeLag scales by the median stride.
GaitEventSet gaitEventsFromFeet(const Eigen::Ref<const Eigen::MatrixXd>& framesX45,
                                const Eigen::Ref<const Eigen::MatrixXd>& feetX12, double rateHz,
                                double heelStrikeLag = kHeelStrikeLagOfStride);

// The median time between consecutive strikes of one foot, over both feet, counting only
// plausible strides (METHOD §3's stride frequencies); NaN without one.
double medianStrideS(const GaitEventSet& events);

// The file's foot strikes and foot offs between 0 and durationS, sorted per side.
GaitEventSet gaitEventsFromFile(const std::vector<GaitEvent>& events, double durationS);

}  // namespace ew
