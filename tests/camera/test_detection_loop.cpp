// The model loop on a detector's keypoints (core/camera/detection_loop.h): joints the detector is
// unsure of, and wrong, are pulled towards the fitted walker and the refit meets the rest better.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/camera/detection_loop.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "tests/camera/filmed_walk.h"

namespace ew {
namespace {

using Eigen::MatrixXd;


struct Scene {
  MatrixXd truthPx, detectedPx, confidence;
};

// The mean walker crossing 6 m from a 1500 px pinhole, 5 s at 30 fps. The far leg's knee and
// ankle are found 45 px off (behind the near leg) on two frames in five, where the detector
// says it is unsure (0.4); everything else is found where it is, and sure (0.95).
Scene unsureFarLeg() {
  const WalkCamera camera = test::crossingPinhole(1500, 5.0);
  const Eigen::VectorXd t = frameTimes(150, 30.0);
  const MatrixXd walk =
      synthesizeFrames(defaultRealModel().mean, 2 * std::numbers::pi * test::kFilmedStrideHz, 0.2, t);
  Scene s;
  s.truthPx = projectWalk(walk, t, camera);
  s.detectedPx = s.truthPx;
  s.confidence = MatrixXd::Constant(150, kJointCount, 0.95);
  for (Eigen::Index f = 0; f < 150; ++f) {
    if (f % 5 >= 2) continue;
    for (Joint j : {Joint::LKnee, Joint::LAnkle}) {
      s.detectedPx(f, 2 * index(j)) += 45.0;
      s.confidence(f, index(j)) = 0.4;
    }
  }
  return s;
}

double meanErrorPx(const MatrixXd& a, const MatrixXd& b, Joint j) {
  double sum = 0.0;
  for (Eigen::Index f = 0; f < a.rows(); ++f) sum += (a.row(f).segment<2>(2 * index(j)) - b.row(f).segment<2>(2 * index(j))).norm();
  return sum / static_cast<double>(a.rows());
}

TEST(DetectionLoop, UnsureJointsGiveWayToTheWalkerAndTheRefitMeetsWhatIsSure) {
  const Scene s = unsureFarLeg();
  KeypointOptions k;
  k.fps = 30.0;
  KeypointTrial trial = trialFromJoints(s.detectedPx, s.confidence, "walk.mp4", "detected", k);
  trial.jointConfidence = s.confidence;
  CameraFitOptions o;
  o.focalPx = 1500;
  DetectionLoopOptions lo;
  lo.rounds = 2;
  const DetectionLoop loop = reconstructWithDetectionLoop(defaultRealModel(), trial, o, lo);
  EXPECT_EQ(loop.unsureJointFrames, 2 * 60);
  EXPECT_LT(loop.lastRmsOnSurePx, loop.firstRmsOnSurePx);
  // The fitted far leg comes nearer its true place in the image.
  EXPECT_LT(meanErrorPx(loop.last.reprojectedPx, s.truthPx, Joint::LAnkle),
            meanErrorPx(loop.first.reprojectedPx, s.truthPx, Joint::LAnkle));
  EXPECT_NEAR(loop.last.fit.camera.alphaDeg, 40.0, 2.0);
}

TEST(DetectionLoop, WithoutConfidencesOrDoubtsItIsOneFit) {
  Scene s = unsureFarLeg();
  KeypointOptions k;
  k.fps = 30.0;
  const KeypointTrial tracked = trialFromJoints(s.truthPx, MatrixXd::Constant(150, kJointCount, 0.9), "t.mp4", "tracked", k);
  const DetectionLoop a = reconstructWithDetectionLoop(defaultRealModel(), tracked, {});
  EXPECT_EQ(a.unsureJointFrames, 0);
  EXPECT_EQ(a.last.fit.reprojectionRmsPx, a.first.fit.reprojectionRmsPx);
  KeypointTrial sure = tracked;
  sure.jointConfidence = MatrixXd::Constant(150, kJointCount, 0.99);
  const DetectionLoop b = reconstructWithDetectionLoop(defaultRealModel(), sure, {});
  EXPECT_EQ(b.unsureJointFrames, 0);
  EXPECT_EQ(b.last.fit.reprojectionRmsPx, b.first.fit.reprojectionRmsPx);
  EXPECT_EQ(b.lastRmsOnSurePx, b.firstRmsOnSurePx);
}

}  // namespace
}  // namespace ew
