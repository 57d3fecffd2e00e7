// calibrationOf (core/camera/walk_camera.h): a pinhole WalkCamera written as a calibration
// images every joint of a walk where projectWalk does, at any azimuth and elevation — the
// bridge that lets the skeleton engine see the camera experiment's clips.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "core/camera/walk_camera.h"
#include "tests/camera/filmed_walk.h"
#include "core/common/errors.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/skeleton/skeleton_camera.h"
#include "tests/common/error_matchers.h"

namespace ew {
namespace {

// x_cam = R W + t, then the pinhole; W is the canonical frame plus the progression.
Eigen::Vector2d imageThroughCalibration(const CalibratedCamera& c, const Eigen::Vector3d& world) {
  const Eigen::Vector3d x = rotationFromRodrigues(c.rotation) * world +
                            Eigen::Vector3d(c.translationMm[0], c.translationMm[1], c.translationMm[2]);
  return {c.cxPx + c.fxPx * x.x() / x.z(), c.cyPx + c.fyPx * x.y() / x.z()};
}

TEST(WalkCameraCalibration, ImagesEveryJointWhereProjectWalkDoes) {
  const EigenwalkerModel& model = defaultRealModel();
  const Eigen::VectorXd times = frameTimes(40, 30.0);
  const Eigen::MatrixXd frames = synthesizeFrames(model.mean, 2 * std::numbers::pi * 0.95, 0.0, times);
  for (double alpha : {-150.0, -40.0, 0.0, 65.0, 180.0})
    for (double elevation : {0.0, 12.0, 30.0}) {
      SCOPED_TRACE(std::to_string(alpha) + "° " + std::to_string(elevation) + "°");
      WalkCamera c = test::crossingPinhole(1400, 1.3);
      c.alphaDeg = alpha;
      c.elevationDeg = elevation;
      const Eigen::MatrixXd px = projectWalk(frames, times, c);
      const CalibratedCamera cal = calibrationOf(c, 1920, 1080);
      EXPECT_EQ(cal.widthPx, 1920);
      EXPECT_TRUE(cal.hasExtrinsics);
      double worst = 0;
      for (Eigen::Index f = 0; f < frames.rows(); ++f)
        for (int j = 0; j < kJointCount; ++j) {
          Eigen::Vector3d w = frames.block<1, 3>(f, 3 * j).transpose();
          w.y() += c.startOffsetMm + c.speedMmS * times[f];
          const Eigen::Vector2d uv = imageThroughCalibration(cal, w);
          worst = std::max(worst, (uv - Eigen::Vector2d(px(f, 2 * j), px(f, 2 * j + 1))).norm());
        }
      EXPECT_LT(worst, 1e-6);  // px: the same equations, rounding only
    }
}

TEST(WalkCameraCalibration, AnOrthographicCameraHasNone) {
  WalkCamera c;
  c.model = CameraModel::ScaledOrthographic;
  EXPECT_TRUE(test::throwsError([&] { calibrationOf(c, 100, 100); }, ErrorKind::BadArgument, {"orthographic"}));
}

}  // namespace
}  // namespace ew
