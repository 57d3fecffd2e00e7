// Which joints a walker's own body hides from the camera (core/camera/self_occlusion.h): the
// default model's mean walker through a pinhole, in profile from either side and from behind.

#include <gtest/gtest.h>

#include "core/camera/self_occlusion.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"

namespace ew {
namespace {

Eigen::MatrixXd hiddenAt(double alphaDeg) {
  const EigenwalkerModel& model = defaultRealModel();
  const double omega = model.omegasRadS.mean();
  const Eigen::VectorXd t = frameTimes(60, 30.0);
  WalkCamera camera;
  camera.model = CameraModel::Pinhole;
  camera.alphaDeg = alphaDeg;
  camera.distanceMm = 6000.0;
  camera.lookAtHeightMm = 1000.0;
  camera.speedMmS = 1200.0;
  camera.startOffsetMm = -1200.0;
  return hiddenJoints(synthesizeFrames(model.mean, omega, 0.0, t), t, camera);
}

double shareHidden(const Eigen::MatrixXd& hidden, Joint j) { return hidden.col(index(j)).mean(); }

// In profile the far shoulder is behind the trunk all along and the near one never is; which is
// far flips with the side. From behind, the trunk hides neither shoulder nor the head.
TEST(SelfOcclusion, TheFarShoulderIsBehindTheTrunkInProfileAndNeitherFromBehind) {
  const Eigen::MatrixXd one = hiddenAt(90.0), other = hiddenAt(-90.0), behind = hiddenAt(0.0);
  const double oneRight = shareHidden(one, Joint::RShoulder), oneLeft = shareHidden(one, Joint::LShoulder);
  EXPECT_EQ(std::max(oneRight, oneLeft), 1.0);
  EXPECT_EQ(std::min(oneRight, oneLeft), 0.0);
  EXPECT_EQ(shareHidden(other, Joint::RShoulder), oneLeft);
  EXPECT_EQ(shareHidden(other, Joint::LShoulder), oneRight);
  for (Joint j : {Joint::RShoulder, Joint::LShoulder, Joint::Head, Joint::Sternum})
    EXPECT_EQ(shareHidden(behind, j), 0.0) << jointName(j);
  // The head is never behind anything, in any view.
  EXPECT_EQ(shareHidden(one, Joint::Head) + shareHidden(other, Joint::Head), 0.0);
}

// A walker who has walked past a pinhole (NaN pixels behind it) has no hidden joints there,
// rather than an answer computed from NaNs.
TEST(SelfOcclusion, FramesBehindThePinholeHideNothing) {
  const EigenwalkerModel& model = defaultRealModel();
  const Eigen::VectorXd t = frameTimes(10, 30.0);
  WalkCamera camera;
  camera.model = CameraModel::Pinhole;
  camera.alphaDeg = 180.0;  // walking straight at the camera
  camera.distanceMm = 500.0;
  camera.speedMmS = 30000.0;  // past the pinhole within the clip
  const Eigen::MatrixXd frames = synthesizeFrames(model.mean, model.omegasRadS.mean(), 0.0, t);
  ASSERT_TRUE(projectWalk(frames, t, camera).row(9).array().isNaN().all());
  const Eigen::MatrixXd hidden = hiddenJoints(frames, t, camera);
  EXPECT_TRUE(hidden.allFinite());
  EXPECT_EQ(hidden.row(9).sum(), 0.0);
}

}  // namespace
}  // namespace ew
