#pragma once
// Gait cycles of a walker seen in an image (pixels), before any 3D: the walker's progression
// across the image gives the walking direction d (a 2D unit vector; for a walker coming
// towards the camera it points down the image); each ankle's lead (ankle − pelvis)·d peaks
// at its foot strikes (Zeni et al. 2008, as core/gait/gait_cycles.h does in 3D), and the
// strikes give the stride frequency.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/keypoints/keypoint_trial.h"

namespace ew {

// The pelvis must cross at least this share of the walker's height in the image to walk.
inline constexpr double kMinImageTravelOfHeight = 0.5;
// Each ankle's lead must span this share of the walker's height (150 mm of ~1.7 m).
inline constexpr double kMinImageAnkleLeadOfHeight = 0.08;

struct ImageGait {
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // progression in the image, unit
  double travelPx = 0.0;                                // pelvis, first to last tenth
  std::vector<double> rightStrikesS, leftStrikesS;      // seconds from frame 0
  double strideHz = 0.0;
  double strikesStrideHz = 0.0;  // what the strikes alone read (0: none), held stride or not
  double cycles = 0.0;           // clip duration × stride frequency
};

// Throws Error(BadData) naming the file with "not walking: …" when the pelvis does not
// cross the image, an ankle does not swing, or the strikes give no stride frequency in
// kMinStrideHz-kMaxStrideHz, and "shorter than one gait cycle" below one cycle.
// `heldStrideHz`: the stride frequency known otherwise (the trunk's bob, below), which then
// stands for the strikes' (a tracker's lost ankles may strike irregularly or not at all).
ImageGait imageGaitCycles(const KeypointTrial& trial,
                          std::optional<double> heldStrideHz = std::nullopt);

// The stride frequency from the trunk's bob: the head, the sternum and the shoulders rise and
// fall twice a stride (once a step), in any view (the pelvis and hips too, but a tracker's
// slip under the thigh tops once a stride; docs/TRACKING.md). The vertical image paths of
// those seen in at least 60 % of the frames, each detrended by a parabola in time (a walker
// nearing the camera sinks along a curve), are fitted with a sinusoid over
// step frequencies 1.0 … 3.2 Hz (strides of 0.5 … 1.6 Hz, 0.005 Hz apart); the frequency whose
// fit takes the largest share of their summed variance among the band's inner peaks (not its
// edges), halved. Unset when fewer than two such joints, no inner peak, the clip is shorter
// than two steps at that frequency, or the best fit takes less than `minShare` of the variance
// (no clear bob). For a joint tracker's output, whose trunk holds
// where the feet are lost (docs/TRACKING.md, "The model loop").
std::optional<double> trunkBobStrideHz(const KeypointTrial& trial, double minShare = 0.3);

}  // namespace ew
