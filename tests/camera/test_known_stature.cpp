// A known stature scales a camera fit (core/camera/known_stature.h): the image is the same,
// every length and speed is s times its own; and a stature no person has is refused.
#include <gtest/gtest.h>

#include <numbers>

#include "core/camera/camera_knowledge.h"
#include "core/camera/known_stature.h"
#include "core/common/errors.h"
#include "tests/camera/filmed_walk.h"

namespace ew {
namespace {

ClipReconstruction filmedClip() {
  ClipReconstruction clip;
  clip.trial.file = "filmed";
  clip.fit.camera = test::crossingPinhole(1400, 5.0);
  clip.fit.w = defaultRealModel().mean;
  clip.fit.omegaRadS = 2 * std::numbers::pi * test::kFilmedStrideHz;
  clip.timesS = frameTimes(60, 30.0);
  clip.framesMm = synthesizeFrames(clip.fit.w, clip.fit.omegaRadS, 0.2, clip.timesS);
  clip.fit.statureMm = 1700.0;
  clip.fit.headHeightMm = 1450.0;
  clip.fit.speedMps = 1.3;
  clip.fit.strideLengthM = 1.3 / test::kFilmedStrideHz;
  return clip;
}

TEST(KnownStature, TheScaledWalkProjectsToTheSameImage) {
  const ClipReconstruction before = filmedClip();
  ClipReconstruction after = before;
  scaleToStature(after, 1870.0);
  const double s = 1.1;
  EXPECT_DOUBLE_EQ(after.fit.statureMm, 1870.0);
  EXPECT_NEAR(after.fit.headHeightMm, s * 1450.0, 1e-9);
  EXPECT_NEAR(after.fit.speedMps, s * 1.3, 1e-12);
  EXPECT_NEAR(after.fit.strideLengthM, s * before.fit.strideLengthM, 1e-12);
  EXPECT_NEAR(after.fit.camera.distanceMm, s * 6000.0, 1e-9);
  EXPECT_LT((after.framesMm - s * before.framesMm).cwiseAbs().maxCoeff(), 1e-9);
  const Eigen::MatrixXd imageBefore = projectWalk(before.framesMm, before.timesS, before.fit.camera);
  const Eigen::MatrixXd imageAfter = projectWalk(after.framesMm, after.timesS, after.fit.camera);
  EXPECT_LT((imageAfter - imageBefore).cwiseAbs().maxCoeff(), 1e-6) << "px";
}

TEST(KnownStature, AStatureNoPersonHasIsRefused) {
  ClipReconstruction clip = filmedClip();
  EXPECT_THROW(scaleToStature(clip, 175000.0), Error);  // 175 m: centimetres read as metres
  EXPECT_THROW(scaleToStature(clip, NAN), Error);
  clip.fit.statureMm = 0.0;
  EXPECT_THROW(scaleToStature(clip, 1700.0), Error);
  CameraGivens g;
  g.statureMm = 3000.0;
  try {
    resolveCameraKnowledge(g);
    FAIL() << "3 m accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--stature"), std::string::npos) << e.what();
  }
  g.statureMm = 1720.0;
  const CameraKnowledge k = resolveCameraKnowledge(g);
  EXPECT_EQ(k.statureSource, "given (--stature)");
  EXPECT_DOUBLE_EQ(*k.statureMm, 1720.0);
}

}  // namespace
}  // namespace ew
