// A calibration's lens distortion (core/camera/lens_distortion.h): undistortion inverts
// OpenCV's model over the whole image of a wide lens, a point the iteration cannot bring back
// becomes missing rather than wrong, and `reconstruct --unknown-camera --camera FILE` takes
// the distortion out of the keypoints before the fit.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/camera/lens_distortion.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/keypoints/openpose_writer.h"
#include "tests/camera/filmed_walk.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A wide lens's barrel distortion on a 1920 × 1080 camera of 1400 px.
CalibratedCamera wideLens() {
  CalibratedCamera c;
  c.name = c.table = "wide";
  c.widthPx = 1920, c.heightPx = 1080;
  c.fxPx = c.fyPx = 1400;
  c.cxPx = 960, c.cyPx = 540;
  c.distortions = {-0.25, 0.08, 0.001, -0.0005};
  return c;
}

TEST(LensDistortion, UndistortionInvertsTheModelOverTheImage) {
  const CalibratedCamera c = wideLens();
  double largestShift = 0.0;
  for (double u = 0; u <= 1920; u += 160) {
    for (double v = 0; v <= 1080; v += 120) {
      const Eigen::Vector2d ideal(u, v), distorted = distortPixel(c, ideal);
      largestShift = std::max(largestShift, (distorted - ideal).norm());
      Eigen::Vector2d back;
      ASSERT_TRUE(undistortPixel(c, distorted, back)) << u << ", " << v;
      EXPECT_LT((back - ideal).norm(), 1e-4) << u << ", " << v;
    }
  }
  EXPECT_GT(largestShift, 100.0);  // the corners move by more than 100 px: a real test
}

TEST(LensDistortion, PointsTheIterationCannotBringBackAreDropped) {
  const CalibratedCamera c = wideLens();
  Eigen::MatrixXd px(1, 6);
  px << 1000, 500, std::nan(""), std::nan(""), 960 + 1400 * 6.0, 540 + 1400 * 6.0;  // 6 focal lengths off-axis
  EXPECT_EQ(undistortPixels(c, px), 1);
  EXPECT_TRUE(std::isfinite(px(0, 0)) && std::isfinite(px(0, 1)));
  EXPECT_TRUE(std::isnan(px(0, 2)));  // missing stays missing
  EXPECT_TRUE(std::isnan(px(0, 4)) && std::isnan(px(0, 5)));
  // Without distortion nothing moves.
  CalibratedCamera plain = c;
  plain.distortions = {};
  Eigen::MatrixXd same(1, 2);
  same << 1234.5, 67.25;
  EXPECT_EQ(undistortPixels(plain, same), 0);
  EXPECT_EQ(same(0, 0), 1234.5);
}

// Issue 53: a calibration not of this camera (here a lens 1000 times the wide one's, as a
// tiny focal length made) pushes every point outside its calibrated field. The walk's joints
// are then gone: an error naming the clip, not a trial whose pelvis is nowhere (which crashed the
// gait cycles).
TEST(LensDistortion, ACalibrationThatLosesTheWalksJointsIsAnError) {
  KeypointTrial trial;
  trial.file = "cam01_json";
  trial.chosenReason = "person 1 of 1: in 2 of 2 frames";
  trial.frameCount = 2;
  trial.jointsPx = Eigen::MatrixXd::Constant(2, kDims2, 900.0);
  trial.people.push_back(PersonTrack{{0, 1}, {0, 0}, 0.0, 500.0, trial.jointsPx});
  CalibratedCamera c = wideLens();
  c.distortions = {-250.0, 80.0, 0.0, 0.0};
  c.cxPx = c.cyPx = 0.0;  // every point 900 px off-axis in both directions
  KeypointTrial lost = trial;
  EXPECT_TRUE(test::throwsError([&] { undistortTrial(c, lost); }, ErrorKind::BadData,
                                {"cam01_json", "pelvis of person 1 of 1 is never seen once the calibration's lens",
                                 "30 points fell outside its calibrated field: is it this camera's?"}));
  // The wide lens itself keeps them, and counts them seen.
  KeypointTrial kept = trial;
  EXPECT_EQ(undistortTrial(wideLens(), kept), 0);
  EXPECT_FALSE(kept.missing[static_cast<std::size_t>(index(Joint::Pelvis))]);
  EXPECT_EQ(kept.seenShare[static_cast<std::size_t>(index(Joint::Pelvis))], 1.0);
}

// The mean walker filmed through the wide lens, as OpenPose JSON.
fs::path distortedClip(const std::string& stem) {
  const fs::path dir = test::makeTempDir(stem);
  const Eigen::VectorXd t = frameTimes(150, 30.0);
  const Eigen::MatrixXd walk = synthesizeFrames(defaultRealModel().mean, 2 * std::numbers::pi * test::kFilmedStrideHz, 0.2, t);
  Eigen::MatrixXd px = projectWalk(walk, t, test::crossingPinhole(1400, 5.0));
  for (Eigen::Index f = 0; f < px.rows(); ++f)
    for (Eigen::Index j = 0; j < px.cols(); j += 2) {
      const Eigen::Vector2d d = distortPixel(wideLens(), Eigen::Vector2d(px(f, j), px(f, j + 1)));
      px(f, j) = d.x(), px(f, j + 1) = d.y();
    }
  writeOpenPoseBody25(dir, {{px, Eigen::MatrixXd()}});
  return dir;
}

json reconstructJson(const fs::path& clip, std::vector<std::string> cameraArgs, const std::string& stem) {
  std::vector<std::string> args{"reconstruct", "--input", clip.string(), "--unknown-camera", "--fps", "30",
                                "--out", (test::makeTempDir("out") / (stem + ".csv")).string(), "--json"};
  args.insert(args.end(), cameraArgs.begin(), cameraArgs.end());
  const auto run = test::runProgram(EW_CLI_PATH, args, test::makeTempDir(stem));
  EXPECT_EQ(run.exitCode, 0) << run.output;
  const auto begin = run.output.find("{\n");
  if (begin == std::string::npos) return json::object();
  return json::parse(run.output.substr(begin));
}

// Through the calibration the keypoints are undistorted and the fit is the pinhole's again
// (measured: azimuth 39.5°, elevation 12.5°, 6.17 m, 1.31 m/s, 3.2 px: the detector-placed
// sternum's miss); given only the focal length, the barrel bends the walk: elevation 15.9°,
// 1.26 m/s, 4.4 px.
TEST(LensDistortion, CalibratedReconstructionUndistortsTheKeypoints) {
  const fs::path clip = distortedClip("lens_cli");
  const fs::path calib = test::makeTempDir("out") / "Calib_wide.toml";
  std::ofstream(calib) << "[wide]\nname = \"wide\"\nsize = [1920, 1080]\n"
                          "matrix = [[1400, 0, 960], [0, 1400, 540], [0, 0, 1]]\n"
                          "distortions = [-0.25, 0.08, 0.001, -0.0005]\n";
  const json calibrated = reconstructJson(clip, {"--camera", calib.string()}, "lens_cli_calibrated");
  ASSERT_TRUE(calibrated["lens_undistorted"].is_object()) << calibrated.dump(1);
  EXPECT_EQ(calibrated["lens_undistorted"]["points_dropped"], 0);
  EXPECT_NEAR(calibrated["alpha_deg"].get<double>(), 40, 2.0);
  EXPECT_NEAR(calibrated["elevation_deg"].get<double>(), 12, 1.0);
  EXPECT_NEAR(calibrated["speed_mps"].get<double>(), 1.3, 0.02 * 1.3);
  EXPECT_NEAR(calibrated["distance_m"].get<double>(), 6.0, 0.05 * 6.0);
  EXPECT_LT(calibrated["reprojection_rms_px"].get<double>(), 6.0);
  const json focalOnly = reconstructJson(clip, {"--focal-px", "1400"}, "lens_cli_focal");
  EXPECT_TRUE(focalOnly["lens_undistorted"].is_null());
  EXPECT_GT(std::abs(focalOnly["elevation_deg"].get<double>() - 12), 2.5);
  EXPECT_GT(focalOnly["reprojection_rms_px"].get<double>(), calibrated["reprojection_rms_px"].get<double>() + 1.0);
}

}  // namespace
}  // namespace ew
