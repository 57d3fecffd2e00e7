#pragma once
// Gait cycles of a walker seen in an image (pixels), before any 3D: the walker's progression
// across the image gives the walking direction d (a 2D unit vector; for a walker coming
// towards the camera it points down the image); each ankle's lead (ankle − pelvis)·d peaks
// at its foot strikes (Zeni et al. 2008, as core/gait/gait_cycles.h does in 3D), and the
// strikes give the stride frequency.

#include <Eigen/Core>
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
  double travelPx = 0.0;                                 // pelvis, first to last tenth
  std::vector<double> rightStrikesS, leftStrikesS;       // seconds from frame 0
  double strideHz = 0.0;
  double cycles = 0.0;                                   // clip duration × stride frequency
};

// Throws Error(BadData) naming the file with "not walking: …" when the pelvis does not
// cross the image, an ankle does not swing, or the strikes give no stride frequency in
// kMinStrideHz-kMaxStrideHz, and "shorter than one gait cycle" below one cycle.
ImageGait imageGaitCycles(const KeypointTrial& trial);

}  // namespace ew
