// The horizon read from a scene's own lines (video/scene_horizon.h): drawn lines running to a
// known point vote for it; the walking video's window rows meet on the row its buildings put the
// horizon at; four calibrated cameras' vanishing points lie on the horizons their calibrations
// give; footage with no lines has none, and says why.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/camera/calibration_file.h"
#include "core/skeleton/skeleton_camera.h"
#include "tests/common/test_support.h"
#include "video/scene_horizon.h"

namespace ew {
namespace {

// A grey picture with `count` dark line segments, each lying on a line through `point`, at
// slopes spread over 5–25° either side; plus a few level and upright distractors.
cv::Mat linesRunningTo(const cv::Point2d& point, int count) {
  cv::Mat image(720, 1280, CV_8U, cv::Scalar(200));
  std::mt19937 random(7);
  std::uniform_real_distribution<double> slope(5.0, 25.0), along(0.0, 1.0);
  for (int i = 0; i < count; ++i) {
    const double deg = slope(random) * (i % 2 == 0 ? 1.0 : -1.0), rad = deg * std::numbers::pi / 180.0;
    const cv::Point2d dir(-std::cos(rad), std::sin(rad));  // from the point, to its left
    const cv::Point2d a = point + dir * (300.0 + 500.0 * along(random)), b = a + dir * 120.0;
    cv::line(image, a, b, cv::Scalar(30), 3, cv::LINE_AA);
  }
  for (int i = 0; i < 6; ++i) {
    cv::line(image, {100 + 150 * i, 650}, {200 + 150 * i, 650}, cv::Scalar(30), 3, cv::LINE_AA);
    cv::line(image, {80 + 180 * i, 80}, {80 + 180 * i, 220}, cv::Scalar(30), 3, cv::LINE_AA);
  }
  return image;
}

TEST(SceneHorizon, DrawnLinesVoteForThePointTheyRunTo) {
  const cv::Point2d point(1100, 300);
  const std::optional<VanishingVote> vote = vanishingVoteOf(linesRunningTo(point, 16));
  ASSERT_TRUE(vote);
  EXPECT_NEAR(vote->pointPx.x(), point.x, 15.0);
  EXPECT_NEAR(vote->pointPx.y(), point.y, 5.0);
  EXPECT_GE(vote->segments, 12) << "most of the 16 sloped segments, none of the level or upright ones";
  EXPECT_LE(vote->segments, 16 * 3) << "a thick line's two edges, one of them split: no more";
}

TEST(SceneHorizon, APictureWithoutLinesHasNoVote) {
  cv::Mat noise(720, 1280, CV_8U);
  cv::randu(noise, 0, 255);
  cv::GaussianBlur(noise, noise, {0, 0}, 3.0);
  EXPECT_FALSE(vanishingVoteOf(noise));
  EXPECT_FALSE(vanishingVoteOf(linesRunningTo({1100, 300}, 4))) << "four segments are no family of lines";
}

TEST(SceneHorizon, FootageWithoutLinesHasNoneAndSaysWhy) {
  const auto file = std::filesystem::temp_directory_path() / "eigenwalker_scene_horizon_noise.avi";
  {
    cv::VideoWriter writer(file.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, {320, 240});
    ASSERT_TRUE(writer.isOpened());
    cv::Mat frame(240, 320, CV_8UC3);
    for (int i = 0; i < 12; ++i) {
      cv::randu(frame, 0, 255);
      cv::GaussianBlur(frame, frame, {0, 0}, 2.0);
      writer.write(frame);
    }
  }
  std::string why;
  EXPECT_FALSE(sceneHorizonOf(file, 6, why));
  EXPECT_NE(why.find("0 of 6 frames"), std::string::npos) << why;
  std::filesystem::remove(file);
}

// The walking video's buildings: six window rows of the left facade pass within 563–570 px at
// x = 761 px, and the right facade's rows turn level at about 570 px (docs/CAMERA.md, "The
// scene's horizon": measured by hand, on single segments, apart from this code).
TEST(SceneHorizon, TheWalkingVideosWindowRowsMeetOnItsHorizon) {
  EW_REQUIRE_SHARED_DATA();
  std::string why;
  const auto h = sceneHorizonOf(test::sharedDataDir() / "video/sports2d-demo/demo.mp4", 12, why);
  ASSERT_TRUE(h) << why;
  EXPECT_NEAR(h->rowPx, 566.0, 10.0);
  EXPECT_NEAR(h->vanishingPointPx.x(), 760.0, 60.0);
  EXPECT_GE(h->framesAgreeing, 10);
  EXPECT_LT(h->rowSpreadPx, 8.0);
}

// The four Pose2Sim cameras are calibrated (world z up): each one's horizon is the line of image
// points whose rays are level, K⁻ᵀ R e_z. Their vanishing points must lie on it, though the
// cameras look down about 22° and one is rolled 26° (where the row alone would not do).
TEST(SceneHorizon, CalibratedCamerasVanishingPointsLieOnTheirHorizons) {
  EW_REQUIRE_SHARED_DATA();
  const auto dir = test::sharedDataDir() / "pose2sim-balancing";
  for (int c = 1; c <= 4; ++c) {
    SCOPED_TRACE("cam0" + std::to_string(c));
    const CalibratedCamera cam = readCalibratedCamera(dir / "Calib_qualisys.toml", "cam_0" + std::to_string(c));
    const Eigen::Vector3d up = rotationFromRodrigues(cam.rotation).col(2);  // world z in the camera
    // (u, v) on the horizon: ((u − cx)/fx, (v − cy)/fy, 1) · up = 0.
    const Eigen::Vector3d line(up.x() / cam.fxPx, up.y() / cam.fyPx,
                               up.z() - up.x() * cam.cxPx / cam.fxPx - up.y() * cam.cyPx / cam.fyPx);
    std::string why;
    const auto h = sceneHorizonOf(dir / "videos" / ("cam0" + std::to_string(c) + ".mp4"), 4, why);
    ASSERT_TRUE(h) << why;
    const double off = std::abs(line.dot(Eigen::Vector3d(h->vanishingPointPx.x(), h->vanishingPointPx.y(), 1.0))) /
                       line.head<2>().norm();
    // A point far outside the picture (1.7–7.8 k px from its centre here) is fixed by segments
    // whose directions differ little: held to its direction from the picture's centre.
    const double away = (h->vanishingPointPx - Eigen::Vector2d(0.5 * cam.widthPx, 0.5 * cam.heightPx)).norm();
    EXPECT_LT(std::atan2(off, away) * 180.0 / std::numbers::pi, 1.5)
        << off << " px from the calibrated horizon, the point at (" << h->vanishingPointPx.transpose() << ")";
  }
}

}  // namespace
}  // namespace ew
