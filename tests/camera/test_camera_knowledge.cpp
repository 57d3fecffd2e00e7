// Camera knowledge resolved once (core/camera/camera_knowledge.h): what the user gave — a
// focal length, a calibration file, the image's size, held angles — to the fit's options and
// the source of each value, with one rule for every program.

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/camera/camera_knowledge.h"
#include "core/common/errors.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

constexpr const char* kCalibration = R"([cam_side]
name = "cam_side"
size = [ 1920, 1080]
matrix = [ [ 1500.0, 0.0, 950.0], [ 0.0, 1502.0, 545.0], [ 0.0, 0.0, 1.0]]
distortions = [ -0.1, 0.01, 0.0, 0.0]
)";

std::filesystem::path writeCalibration(const std::string& text) {
  const auto file = test::makeTempDir("camera_knowledge") / "Calib.toml";
  std::ofstream(file) << text;
  return file;
}

TEST(CameraKnowledge, NothingGivenEstimatesEverything) {
  const CameraKnowledge k = resolveCameraKnowledge({});
  EXPECT_FALSE(k.focalPx);
  EXPECT_TRUE(k.estimateFocal);
  EXPECT_EQ(k.focalSource, "estimated");
  EXPECT_EQ(k.alphaSource, "estimated");
  EXPECT_FALSE(k.imageSize);
  const CameraFitOptions o = cameraFitOptions(k, {Estimator::Map, 80.0}, "clip.json");
  EXPECT_FALSE(o.focalPx);
  EXPECT_TRUE(o.estimateFocal);
  EXPECT_EQ(o.estimator.sigma2Mm2, 80.0);
  EXPECT_EQ(o.file, "clip.json");
  EXPECT_FALSE(o.principalPointPx);
}

TEST(CameraKnowledge, ACalibrationGivesFocalImageAndPrincipalPoint) {
  CameraGivens g;
  g.calibrationFile = writeCalibration(kCalibration);
  const CameraKnowledge k = resolveCameraKnowledge(g);
  ASSERT_TRUE(k.calibration);
  EXPECT_EQ(*k.focalPx, 1501.0);
  EXPECT_EQ(k.focalSource, "calibration file (cam_side)");
  ASSERT_TRUE(k.imageSize);
  EXPECT_EQ(k.imageSize->width, 1920);
  EXPECT_TRUE(k.imageSizeFromCalibration);
  EXPECT_NE(k.imageSizeSource.find("Calib.toml"), std::string::npos);
  const CameraFitOptions o = cameraFitOptions(k);
  ASSERT_TRUE(o.principalPointPx && o.imageSizePx);
  EXPECT_EQ(o.principalPointPx->x(), 950.0);
  EXPECT_EQ(o.imageSizePx->y(), 1080.0);
  EXPECT_EQ(*o.focalPx, 1501.0);
}

TEST(CameraKnowledge, AGivenImageSizeWinsOverTheCalibrations) {
  CameraGivens g;
  g.calibrationFile = writeCalibration(kCalibration);
  g.imageSize = KeypointImageSize{960, 540};
  const CameraKnowledge k = resolveCameraKnowledge(g);
  EXPECT_EQ(k.imageSize->width, 960);
  EXPECT_FALSE(k.imageSizeFromCalibration);
  EXPECT_EQ(k.imageSizeSource, "given (--image-size)");
}

TEST(CameraKnowledge, HeldValuesAndOrthographyAreSaid) {
  CameraGivens g;
  g.focalPx = 2000.0;
  g.alphaDeg = -90.0;
  g.elevationDeg = 10.0;
  g.names.alpha = "azimuth field";
  const CameraKnowledge k = resolveCameraKnowledge(g);
  EXPECT_EQ(k.focalSource, "given (--focal-px)");
  EXPECT_EQ(k.alphaSource, "given (azimuth field)");
  EXPECT_EQ(k.elevationSource, "given (--elevation)");
  const CameraFitOptions o = cameraFitOptions(k);
  EXPECT_EQ(*o.alphaDeg, -90.0);
  EXPECT_EQ(*o.elevationDeg, 10.0);
  CameraGivens ortho;
  ortho.orthographic = true;
  EXPECT_FALSE(cameraFitOptions(resolveCameraKnowledge(ortho)).estimateFocal);
}

// One rule for a focal length wherever it is typed, the message naming where.
TEST(CameraKnowledge, RefusesAFocalNoCameraHasAndTwoFocalSources) {
  CameraGivens g;
  g.focalPx = 3.5;  // mm typed for px
  g.names.focal = "the focal field";
  try {
    resolveCameraKnowledge(g);
    FAIL() << "a 3.5 px focal length was taken";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadArgument);
    EXPECT_NE(std::string(e.what()).find("the focal field"), std::string::npos) << e.what();
  }
  g.focalPx = 1500.0;
  g.calibrationFile = writeCalibration(kCalibration);
  EXPECT_THROW(resolveCameraKnowledge(g), Error);
}

TEST(CameraKnowledge, OnlyACalibratedLensIsUndone) {
  KeypointTrial t;
  EXPECT_FALSE(undistortKeypoints(resolveCameraKnowledge({}), t));
  CameraGivens g;
  g.calibrationFile = writeCalibration(std::string(kCalibration).replace(
      std::string(kCalibration).find("-0.1, 0.01"), 10, "0.0, 0.00"));
  EXPECT_FALSE(undistortKeypoints(resolveCameraKnowledge(g), t));
}

}  // namespace
}  // namespace ew
