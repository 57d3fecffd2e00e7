#pragma once
// Gait cycles: foot strikes from the file's events when it has them, else from the
// kinematics (Zeni, Richards & Higginson 2008, Gait & Posture 27:710: heel strike at the
// maximum of the ankle's forward distance from the pelvis), giving the stride frequency.

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/common/trial.h"
#include "core/gait/walking_trial.h"

namespace ew {

inline constexpr double kMinStrideHz = 0.3;  // METHOD §3's ω range, as strides per second
inline constexpr double kMaxStrideHz = 2.5;
// A walking foot moves ~±250-400 mm fore-aft relative to the pelvis; standing, swaying
// or gesturing moves it a few cm. Below this range the trial is not walking.
inline constexpr double kMinAnkleExcursionMm = 150.0;

// Foot strikes per side, in seconds from row 0, from the kinematics of canonical frames.
std::vector<double> footStrikesFromKinematics(const Eigen::MatrixXd& framesX45, double rateHz,
                                              Side side);

// Events given in seconds from row 0 of framesX45 (already shifted to the window).
// Throws Error(BadData) naming `file` when the trial is not walking or is shorter than
// one gait cycle.
GaitCycles detectGaitCycles(const Eigen::MatrixXd& framesX45, double rateHz,
                            const std::vector<GaitEvent>& events, const std::string& file);

}  // namespace ew
