#pragma once
// A calibration's lens distortion taken out of image points (docs/CAMERA.md, "Lens
// distortion"): the Brown–Conrady model OpenCV and Pose2Sim calibrate, with k1, k2 radial
// and p1, p2 tangential terms. For a point (x, y) in normalised camera coordinates and
// r² = x² + y², the lens images it at
//   x_d = x (1 + k1 r² + k2 r⁴) + 2 p1 x y + p2 (r² + 2 x²)
//   y_d = y (1 + k1 r² + k2 r⁴) + p1 (r² + 2 y²) + 2 p2 x y
// and a pixel is u = f_x x_d + c_x, v = f_y y_d + c_y. The fit's pinhole is the undistorted
// image (x, y), so keypoints from a calibrated camera are undistorted before it.

#include <Eigen/Core>

#include "core/camera/calibration_file.h"

namespace ew {

struct KeypointTrial;

bool hasDistortion(const CalibratedCamera& c);

// Pixels (u, v) where an ideal pinhole with the camera's intrinsics would have imaged the point
// the lens imaged at `distorted`. Fixed-point iteration (as OpenCV's undistortPoints);
// false when it does not converge to 1e-10 of the normalised coordinates, as for a point far
// outside the field the distortion was calibrated on.
bool undistortPixel(const CalibratedCamera& c, const Eigen::Vector2d& distorted, Eigen::Vector2d& undistorted);
// The lens's image of the pinhole pixel `undistorted` (the model above).
Eigen::Vector2d distortPixel(const CalibratedCamera& c, const Eigen::Vector2d& undistorted);

// Every (u, v) pair of `px` (T × 2J, NaN = missing) undistorted in place; a point that does
// not converge becomes missing. Returns how many did not.
int undistortPixels(const CalibratedCamera& c, Eigen::MatrixXd& px);
// The trial's walker and every other person's joints undistorted, its seen joints counted again
// (countSeenJoints); returns the points lost. Error(BadData) naming the trial's file when the
// walk's minimum joints are no longer seen (requireWalkJoints).
int undistortTrial(const CalibratedCamera& c, KeypointTrial& trial);

}  // namespace ew
