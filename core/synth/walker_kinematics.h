#pragma once
// Forward kinematics of one synthetic walker (docs/SYNTHETIC.md, "Kinematics"):
// joint angles over the gait cycle (normative curves shaped by SynthParams) → 15 joint
// centres plus the feet, in the canonical frame of METHOD §2 (mm, x right, y forward, z up).
//
// The trunk and legs are chains of rigid segments, so every bone has a constant length.
// The pelvis is placed from the legs, not prescribed:
//   height    the lowest heel or ball of either foot touches the floor (a soft minimum
//             over the four contact points, 3 mm wide, so the body never goes below
//             the floor and the vertical bob, two per stride, comes out of the legs);
//   forward   the contact points carry no fore-aft velocity (no foot slide): the pelvis
//             moves by minus the contact-weighted velocity of the feet relative to it;
//   lateral   a prescribed sway; the legs' frontal angle puts the stance ankle on its
//             line (half the step width from the midline), so the stance foot does not
//             slide sideways either.
// The hip flexion amplitude is solved so the stride length the legs produce equals
// SynthParams::strideLengthMm.

#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "core/common/skeleton.h"
#include "core/synth/synth_params.h"

namespace ew {

struct SimulationOptions {
  double rateHz = 120.0;
  double cycles = 4.0;     // gait cycles to sample (the frame count is rounded)
  bool treadmill = false;  // walk in place (belt speed = mean speed) instead of along +y
};

struct SynthTrajectories {
  Eigen::MatrixXd jointsMm;  // frames × 45, joint-major x,y,z (METHOD §1 order)
  Eigen::MatrixXd toesMm;    // frames × 6: right toe tip x,y,z, left toe tip x,y,z
  double rateHz = 0.0;
  double strideLengthMm = 0.0;  // produced by the legs (≈ the target after solving)
  double strideHz = 0.0;        // 1 / mean cycle duration
  double startPhase = 0.0;      // phase of the right leg at frame 0 (0 = right contact)
};

// The hip gain (hip flexion curve × gain about its mean) that makes the legs' stride
// equal params.strideLengthMm; params.hipGain is ignored. Secant iteration; returns the
// best gain in [0.3, 2.5].
double solveHipGain(const SynthParams& params);

// The stride length (mm) the legs produce with params.hipGain.
double strideLengthFromLegs(const SynthParams& params);

// Samples the walker (params.hipGain used as given; call solveHipGain first). `seed`
// drives the start phase and the cycle-to-cycle stride time variation.
SynthTrajectories simulateWalker(const SynthParams& params, const SimulationOptions& options,
                                 std::uint64_t seed);

// Ranges of the sagittal angles the walker uses (right side), for the attribute table.
struct AngleSummary {
  double hipRomDeg = 0.0;
  double kneePeakSwingDeg = 0.0;
  double kneeLoadingPeakDeg = 0.0;
  double anklePeakPlantarDeg = 0.0;
};
AngleSummary summarizeAngles(const SynthParams& params);

}  // namespace ew
