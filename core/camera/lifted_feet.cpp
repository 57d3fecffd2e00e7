#include "core/camera/lifted_feet.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/common/skeleton.h"
#include "core/common/trial.h"
#include "core/eigenwalker/projection.h"
#include "core/gait/gait_events.h"

namespace ew {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The camera's axes and centre in the look-at point's frame (canonical axes; walk_camera.h's
// equations read backwards): X_c = P·ex, Y_c = P·ey, Z_c = D + P·ez.
struct CameraAxes {
  Eigen::Vector3d ex, ey, ez, centre;
};

CameraAxes axesOf(const WalkCamera& c) {
  const double ca = std::cos(degToRad(c.alphaDeg)), sa = std::sin(degToRad(c.alphaDeg));
  const double ce = std::cos(degToRad(c.elevationDeg)), se = std::sin(degToRad(c.elevationDeg));
  CameraAxes a;
  a.ex = {ca, sa, 0.0};
  a.ey = {se * sa, -se * ca, -ce};
  a.ez = {-ce * sa, ce * ca, -se};
  a.centre = -c.distanceMm * a.ez;
  return a;
}

// A pixel's ray, P(s) = origin + s·direction, in the look-at point's frame.
struct Ray {
  Eigen::Vector3d origin, direction;
};

Ray rayOf(const WalkCamera& c, const CameraAxes& axes, double uPx, double vPx) {
  if (c.model == CameraModel::Pinhole) {
    const double a = (uPx - c.cxPx) / c.focalPx, b = (vPx - c.cyPx) / c.focalPx;
    return {axes.centre, a * axes.ex + b * axes.ey + axes.ez};
  }
  const double xc = (uPx - c.cxPx) / c.pxPerMm, yc = (vPx - c.cyPx) / c.pxPerMm;
  return {xc * axes.ex + yc * axes.ey, axes.ez};
}

// Where the walker's canonical origin stands at time t relative to the look-at point (as
// walkInCameraFrame puts it).
Eigen::Vector3d originAt(const WalkCamera& c, double timeS) {
  const bool pinhole = c.model == CameraModel::Pinhole;
  return {0.0, (pinhole ? c.startOffsetMm : 0.0) + c.speedMmS * timeS, pinhole ? -c.lookAtHeightMm : 0.0};
}

Side sideOf(FootPoint p) { return p == FootPoint::LHeel || p == FootPoint::LToe ? Side::Left : Side::Right; }

std::string noteOf(const LiftedFeet& f) {
  std::ostringstream s;
  if (f.pointsSeen == 0) return "the image has no heel or toe points";
  s << f.pointsLifted << " of " << f.pointsSeen
    << " heel and toe samples lifted onto their ankles' sagittal planes (no foot progression)";
  if (f.pointsEndOn > 0)
    s << "; " << f.pointsEndOn << " seen within " << kMinRayToPlaneDeg << " deg of end-on left out";
  if (f.pointsFarFromAnkle > 0)
    s << "; " << f.pointsFarFromAnkle << " more than " << kMaxFootPointFromAnkleMm / 10.0
      << " cm from their ankle left out";
  return s.str();
}

}  // namespace

LiftedFeet liftFeetOntoSagittalPlanes(const Eigen::MatrixXd& feetPx, const Eigen::MatrixXd& framesMm,
                                      const Eigen::VectorXd& timesS, const WalkCamera& camera) {
  LiftedFeet out;
  const Eigen::Index T = framesMm.rows();
  if (feetPx.rows() != T || feetPx.cols() != 2 * kFootPointCount || timesS.size() != T) {
    out.note = noteOf(out);
    return out;
  }
  const CameraAxes axes = axesOf(camera);
  const double minSine = std::sin(degToRad(kMinRayToPlaneDeg));
  out.feetMm = Eigen::MatrixXd::Constant(T, kFootDims3, kNaN);
  for (Eigen::Index t = 0; t < T; ++t) {
    for (int p = 0; p < kFootPointCount; ++p) {
      const double u = feetPx(t, 2 * p), v = feetPx(t, 2 * p + 1);
      if (!std::isfinite(u) || !std::isfinite(v)) continue;
      ++out.pointsSeen;
      const Eigen::Vector3d ankle = framesMm.row(t).segment<3>(3 * index(ankleOf(sideOf(FootPoint(p))))).transpose();
      if (!ankle.allFinite()) continue;
      const Ray ray = rayOf(camera, axes, u, v);
      // The ray's sine against the plane x = const is its direction's x share.
      if (std::abs(ray.direction.x()) < minSine * ray.direction.norm()) {
        ++out.pointsEndOn;
        continue;
      }
      const Eigen::Vector3d origin = originAt(camera, timesS[t]);
      const double s = (ankle.x() + origin.x() - ray.origin.x()) / ray.direction.x();
      const Eigen::Vector3d point = ray.origin + s * ray.direction - origin;
      // A point not finite (a pixel far outside any picture) is no nearer its ankle than that.
      if (!point.allFinite() || !((point - ankle).norm() <= kMaxFootPointFromAnkleMm)) {
        ++out.pointsFarFromAnkle;
        continue;
      }
      out.feetMm.row(t).segment<3>(3 * p) = point.transpose();
      ++out.pointsLifted;
    }
  }
  if (out.pointsLifted == 0) out.feetMm.resize(0, 0);
  out.note = noteOf(out);
  return out;
}

Eigen::MatrixXd projectFootPoints(const Eigen::MatrixXd& feetMm, const Eigen::VectorXd& timesS,
                                  const WalkCamera& camera) {
  // The four points in the first four joints' places of a 15-joint walk: projectWalk's
  // equations, one place.
  Eigen::MatrixXd asJoints = Eigen::MatrixXd::Zero(feetMm.rows(), 3 * kJointCount);
  asJoints.leftCols(kFootDims3) = feetMm;
  return projectWalk(asJoints, timesS, camera).leftCols(2 * kFootPointCount);
}

}  // namespace ew
