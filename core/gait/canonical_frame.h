#pragma once
// METHOD §2: the canonical frame. Millimetres; x = walker's right, y = walking direction,
// z = up (right-handed). All functions work in place on T x 45 joint-major matrices with
// no NaN (gaps are handled before). They read the 15 joints only; further points after them
// (T x (45 + 3k): the feet, JointTrial::feetMm) are moved with the joints, NaN or not.

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/common/trial.h"

namespace ew {

// The axis along which (head - mean of ankles) is largest on average, with its sign.
SignedAxis detectUpAxis(const Eigen::MatrixXd& framesX45);

// A proper rotation taking the file's up axis to +z.
Eigen::Matrix3d rotationToZUp(const SignedAxis& up);

void rotateFrames(Eigen::MatrixXd& framesX45, const Eigen::Matrix3d& rotation);

// Mean over frames of the horizontal part of z x (r_hip - l_hip), normalised: the facing
// direction (z-up frames). Zero vector when the hips coincide throughout.
Eigen::Vector2d facingDirection(const Eigen::MatrixXd& framesX45);

// Rotates about z so the facing direction becomes +y; returns the applied angle (rad).
double rotateFacingToY(Eigen::MatrixXd& framesX45);

// Subtracts the least-squares linear trend of the pelvis's horizontal trajectory from
// every joint (removes progression and the mean, keeps the sway). Returns the removed
// horizontal velocity in mm/s.
Eigen::Vector2d removeProgression(Eigen::MatrixXd& framesX45, double rateHz);

// Shifts vertically so the 5th percentile of min(z_l_ankle, z_r_ankle) is 0.
void placeOnFloor(Eigen::MatrixXd& framesX45);

}  // namespace ew
