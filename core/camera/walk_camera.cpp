#include "core/camera/walk_camera.h"

#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/projection.h"

namespace ew {

Eigen::MatrixXd walkInCameraFrame(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                  const Eigen::Ref<const Eigen::VectorXd>& timesS, const WalkCamera& c) {
  const double ca = std::cos(degToRad(c.alphaDeg)), sa = std::sin(degToRad(c.alphaDeg));
  const double ce = std::cos(degToRad(c.elevationDeg)), se = std::sin(degToRad(c.elevationDeg));
  const bool pinhole = c.model == CameraModel::Pinhole;
  const double y0 = pinhole ? c.startOffsetMm : 0.0, h = pinhole ? c.lookAtHeightMm : 0.0;
  Eigen::MatrixXd out(frames.rows(), 3 * kJointCount);
  for (Eigen::Index f = 0; f < frames.rows(); ++f) {
    const double forward = y0 + c.speedMmS * timesS[f];
    for (int j = 0; j < kJointCount; ++j) {
      const double x = frames(f, 3 * j), y = frames(f, 3 * j + 1) + forward, z = frames(f, 3 * j + 2) - h;
      const double u = x * ca + y * sa, d = -x * sa + y * ca;
      out(f, 3 * j) = u;
      out(f, 3 * j + 1) = -(d * se + z * ce);
      out(f, 3 * j + 2) = c.distanceMm + d * ce - z * se;
    }
  }
  return out;
}

Eigen::MatrixXd projectWalk(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                            const Eigen::Ref<const Eigen::VectorXd>& timesS, const WalkCamera& c) {
  const Eigen::MatrixXd cam = walkInCameraFrame(frames, timesS, c);
  const bool pinhole = c.model == CameraModel::Pinhole;
  Eigen::MatrixXd out(frames.rows(), 2 * kJointCount);
  for (Eigen::Index f = 0; f < frames.rows(); ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const double xc = cam(f, 3 * j), yc = cam(f, 3 * j + 1), zc = cam(f, 3 * j + 2);
      if (pinhole) {
        const bool visible = zc > 1.0;
        out(f, 2 * j) = visible ? c.cxPx + c.focalPx * xc / zc : std::numeric_limits<double>::quiet_NaN();
        out(f, 2 * j + 1) = visible ? c.cyPx + c.focalPx * yc / zc : std::numeric_limits<double>::quiet_NaN();
      } else {
        out(f, 2 * j) = c.cxPx + c.pxPerMm * xc;
        out(f, 2 * j + 1) = c.cyPx + c.pxPerMm * yc;
      }
    }
  }
  return out;
}

WalkImageGradient projectWalkGradient(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                      const Eigen::Ref<const Eigen::VectorXd>& timesS, const WalkCamera& c) {
  const double ca = std::cos(degToRad(c.alphaDeg)), sa = std::sin(degToRad(c.alphaDeg));
  const double ce = std::cos(degToRad(c.elevationDeg)), se = std::sin(degToRad(c.elevationDeg));
  // Rows of walkInCameraFrame's rotation: ∂(X_c, Y_c, Z_c) / ∂(x, y, z).
  const Eigen::Vector3d dXc(ca, sa, 0.0), dYc(sa * se, -ca * se, -ce), dZc(-sa * ce, ca * ce, -se);
  WalkImageGradient g{Eigen::MatrixXd(frames.rows(), frames.cols()), Eigen::MatrixXd(frames.rows(), frames.cols())};
  if (c.model != CameraModel::Pinhole) {
    for (Eigen::Index f = 0; f < frames.rows(); ++f)
      for (int j = 0; j < kJointCount; ++j) {
        g.du.row(f).segment<3>(3 * j) = c.pxPerMm * dXc.transpose();
        g.dv.row(f).segment<3>(3 * j) = c.pxPerMm * dYc.transpose();
      }
    return g;
  }
  const Eigen::MatrixXd cam = walkInCameraFrame(frames, timesS, c);
  for (Eigen::Index f = 0; f < frames.rows(); ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const double xc = cam(f, 3 * j), yc = cam(f, 3 * j + 1), zc = cam(f, 3 * j + 2);
      // u = c_x + f X_c / Z_c: ∂u = f (∂X_c Z_c − X_c ∂Z_c) / Z_c², v likewise; none where
      // projectWalk gives NaN, nor where the camera is so far that the point sits at infinity.
      const bool imaged = zc > 1.0 && std::isfinite(zc) && std::isfinite(xc) && std::isfinite(yc);
      if (!imaged) {
        g.du.row(f).segment<3>(3 * j).setZero();
        g.dv.row(f).segment<3>(3 * j).setZero();
        continue;
      }
      const double k = c.focalPx / (zc * zc);
      g.du.row(f).segment<3>(3 * j) = k * (zc * dXc - xc * dZc).transpose();
      g.dv.row(f).segment<3>(3 * j) = k * (zc * dYc - yc * dZc).transpose();
    }
  }
  return g;
}

double horizonRowPx(const WalkCamera& c) {
  if (c.model != CameraModel::Pinhole) return std::numeric_limits<double>::quiet_NaN();
  return c.cyPx - c.focalPx * std::tan(degToRad(c.elevationDeg));
}

double horizonOffDeg(const WalkCamera& c, double sceneRowPx) {
  if (c.model != CameraModel::Pinhole) return std::numeric_limits<double>::quiet_NaN();
  return std::atan((c.cyPx - sceneRowPx) / c.focalPx) * 180.0 / std::numbers::pi - c.elevationDeg;
}

CalibratedCamera calibrationOf(const WalkCamera& c, double widthPx, double heightPx) {
  if (c.model != CameraModel::Pinhole)
    throw Error(ErrorKind::BadArgument, "", "", "a scaled orthographic camera has no pinhole calibration");
  const double ca = std::cos(degToRad(c.alphaDeg)), sa = std::sin(degToRad(c.alphaDeg));
  const double ce = std::cos(degToRad(c.elevationDeg)), se = std::sin(degToRad(c.elevationDeg));
  Eigen::Matrix3d r;
  r << ca, sa, 0.0,            //
      se * sa, -se * ca, -ce,  //
      -ce * sa, ce * ca, -se;
  const Eigen::Vector3d t = Eigen::Vector3d(0.0, 0.0, c.distanceMm) - r * Eigen::Vector3d(0.0, 0.0, c.lookAtHeightMm);
  const Eigen::AngleAxisd axisAngle(r);
  const Eigen::Vector3d rodrigues = axisAngle.angle() * axisAngle.axis();
  CalibratedCamera out;
  out.name = out.table = "walk camera";
  out.widthPx = widthPx;
  out.heightPx = heightPx;
  out.fxPx = out.fyPx = c.focalPx;
  out.cxPx = c.cxPx;
  out.cyPx = c.cyPx;
  out.hasExtrinsics = true;
  out.rotation = {rodrigues.x(), rodrigues.y(), rodrigues.z()};
  out.translationMm = {t.x(), t.y(), t.z()};
  return out;
}

double viewElevationDeg(const Eigen::Ref<const Eigen::MatrixXd>& inCamera, double elevationDeg) {
  // The camera frame is x right, y down, z forward; turned up by the tilt it is level.
  const double c = std::cos(degToRad(elevationDeg)), s = std::sin(degToRad(elevationDeg));
  double sum = 0.0;
  for (Eigen::Index f = 0; f < inCamera.rows(); ++f) {
    const Eigen::Vector3d p = inCamera.row(f).segment<3>(3 * index(Joint::Pelvis));
    const double down = p.y() * c + p.z() * s, ahead = p.z() * c - p.y() * s;
    sum += std::atan2(down, std::hypot(p.x(), ahead));
  }
  return sum / static_cast<double>(inCamera.rows()) * 180.0 / std::numbers::pi;
}

}  // namespace ew
