#include "core/camera/lens_distortion.h"

#include <cmath>
#include <limits>

#include "core/keypoints/keypoint_trial.h"

namespace ew {

namespace {

constexpr int kMaxIterations = 50;
constexpr double kConvergedNormalised = 1e-10;

double radialFactor(const std::array<double, 4>& d, const Eigen::Vector2d& p) {
  const double r2 = p.squaredNorm();
  return 1.0 + d[0] * r2 + d[1] * r2 * r2;
}

Eigen::Vector2d tangentialShift(const std::array<double, 4>& d, const Eigen::Vector2d& p) {
  const double x = p.x(), y = p.y(), r2 = x * x + y * y;
  return {2 * d[2] * x * y + d[3] * (r2 + 2 * x * x), d[2] * (r2 + 2 * y * y) + 2 * d[3] * x * y};
}

// Where the lens images the normalised point p.
Eigen::Vector2d lensImage(const std::array<double, 4>& d, const Eigen::Vector2d& p) {
  return radialFactor(d, p) * p + tangentialShift(d, p);
}

Eigen::Vector2d normalised(const CalibratedCamera& c, const Eigen::Vector2d& px) {
  return {(px.x() - c.cxPx) / c.fxPx, (px.y() - c.cyPx) / c.fyPx};
}

Eigen::Vector2d pixel(const CalibratedCamera& c, const Eigen::Vector2d& p) {
  return {c.fxPx * p.x() + c.cxPx, c.fyPx * p.y() + c.cyPx};
}

}  // namespace

bool hasDistortion(const CalibratedCamera& c) {
  for (double d : c.distortions)
    if (d != 0.0) return true;
  return false;
}

Eigen::Vector2d distortPixel(const CalibratedCamera& c, const Eigen::Vector2d& undistorted) {
  return pixel(c, lensImage(c.distortions, normalised(c, undistorted)));
}

bool undistortPixel(const CalibratedCamera& c, const Eigen::Vector2d& distorted, Eigen::Vector2d& undistorted) {
  const Eigen::Vector2d target = normalised(c, distorted);
  Eigen::Vector2d p = target;
  for (int i = 0; i < kMaxIterations; ++i) {
    // OpenCV's iteration: undo the tangential shift, divide out the radial factor, both
    // evaluated at the current estimate.
    p = (target - tangentialShift(c.distortions, p)) / radialFactor(c.distortions, p);
    if (!p.allFinite()) return false;
    if ((lensImage(c.distortions, p) - target).norm() < kConvergedNormalised) {
      undistorted = pixel(c, p);
      return true;
    }
  }
  return false;
}

int undistortPixels(const CalibratedCamera& c, Eigen::MatrixXd& px) {
  if (!hasDistortion(c)) return 0;
  int lost = 0;
  for (Eigen::Index f = 0; f < px.rows(); ++f) {
    for (Eigen::Index j = 0; j + 1 < px.cols(); j += 2) {
      const Eigen::Vector2d d(px(f, j), px(f, j + 1));
      if (!d.allFinite()) continue;
      Eigen::Vector2d u;
      if (!undistortPixel(c, d, u)) {
        u.setConstant(std::numeric_limits<double>::quiet_NaN());
        ++lost;
      }
      px(f, j) = u.x();
      px(f, j + 1) = u.y();
    }
  }
  return lost;
}

int undistortTrial(const CalibratedCamera& c, KeypointTrial& trial) {
  int lost = undistortPixels(c, trial.jointsPx);
  // The heels and toes are lifted through the same pinhole (lifted_feet.h); a foot point
  // outside the calibrated field is dropped, not counted: the joints decide the fit.
  undistortPixels(c, trial.feetPx);
  for (PersonTrack& person : trial.people) {
    Eigen::MatrixXd& px = person.jointsPx;
    // The walker's own rows were counted once already.
    const int personLost = undistortPixels(c, px);
    if (&person != &trial.people[static_cast<std::size_t>(trial.chosen)]) lost += personLost;
  }
  // The cleaning's promise (pelvis, knees and ankles seen) held before the points moved; a
  // calibration not of this camera can push every one outside its field.
  countSeenJoints(trial);
  requireWalkJoints(trial, "once the calibration's lens distortion is taken out (" + std::to_string(lost) +
                               " points fell outside its calibrated field: is it this camera's?)");
  return lost;
}

}  // namespace ew
