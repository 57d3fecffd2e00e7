// The still background of a fixed camera (video/static_background.h): found and flattened on
// footage of a walker crossing the picture; refused, with the reason, when the camera pans or
// the walker stays in place (a treadmill: the person is part of every frame's median); never more
// frames sampled than the tracker's frame buffer holds.
#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/common/skeleton.h"
#include "core/synth/population.h"
#include "tests/common/test_support.h"
#include "tests/video/walking_footage.h"
#include "video/static_background.h"
#include "video/synthetic_footage.h"

namespace ew {
namespace {

Keyframe keyOn(const Eigen::MatrixXd& truthPx, int frame) {
  Keyframe k;
  k.frame = frame;
  k.jointsPx = truthPx.row(frame).transpose();
  return k;
}

// Pixels of `mask` (non-zero: kept) along the bones of `jointsPx` and far from every joint.
struct Kept {
  double onBones = 0, farAway = 0;
};

Kept keptShares(const cv::Mat& flattened, unsigned char fill, const Eigen::RowVectorXd& jointsPx) {
  cv::Mat near = cv::Mat::zeros(flattened.size(), CV_8U);
  int onBones = 0, keptOnBones = 0;
  for (const auto& [from, to] : kBones) {
    const cv::Point2d a(jointsPx(2 * index(from)), jointsPx(2 * index(from) + 1));
    const cv::Point2d b(jointsPx(2 * index(to)), jointsPx(2 * index(to) + 1));
    cv::line(near, a, b, cv::Scalar(255), 80);  // a limb is about 10 px wide here: 40 px clear
    for (int k = 1; k < 8; ++k) {
      const cv::Point2d p = a + (b - a) * (k / 8.0);
      ++onBones;
      keptOnBones += flattened.at<unsigned char>(cv::Point(p)) != fill;
    }
  }
  const cv::Mat far = near == 0;
  const cv::Mat keptFar = far & (flattened != fill);
  return {static_cast<double>(keptOnBones) / onBones,
          static_cast<double>(cv::countNonZero(keptFar)) / cv::countNonZero(far)};
}

TEST(StaticBackground, AWalkerCrossingTheFixedCamerasPictureLeavesTheBackgroundFlattened) {
  const test::WalkingFootage& footage = test::walkingFootage();
  VideoSource video(footage.file);
  const int last = video.info().frameCount - 1;
  const BackgroundCheck check = estimateStaticBackground(video, 0, last, keyOn(footage.truthPx, 0));
  ASSERT_TRUE(check.background) << check.why;
  EXPECT_GE(check.background->thresholdGrey, 10.0);
  for (int frame : {0, last / 2, last}) {
    const cv::Mat flattened = withoutBackground(toGrey(video.frame(frame)), *check.background);
    const Kept kept = keptShares(flattened, check.background->fillGrey, footage.truthPx.row(frame));
    EXPECT_GT(kept.onBones, 0.9) << "frame " << frame;    // the walker stays
    EXPECT_LT(kept.farAway, 0.001) << "frame " << frame;  // the background goes
  }
}

TEST(StaticBackground, AWalkerOnATreadmillIsPartOfTheMedianAndIsNotFlattened) {
  PopulationOptions o;
  o.count = 1;
  o.simulation.rateHz = 30.0;
  o.simulation.cycles = 2.0;
  Eigen::MatrixXd frames = generatePopulation(o).front().trial.positionsMm;
  const Eigen::VectorXd forward = frames.col(3 * index(Joint::Pelvis) + 1);
  for (int j = 0; j < kJointCount; ++j) frames.col(3 * j + 1) -= forward;  // walking in place
  const std::filesystem::path file = test::makeTempDir("static_background") / "treadmill.avi";
  const Eigen::MatrixXd truthPx =
      writeFootage(file, frames, cameraBeside(frames, 30.0, 6000.0), 30.0);
  VideoSource video(file);
  const BackgroundCheck check =
      estimateStaticBackground(video, 0, video.info().frameCount - 1, keyOn(truthPx, 0));
  EXPECT_FALSE(check.background);
  EXPECT_NE(check.why.find("stays in place"), std::string::npos) << check.why;
}

TEST(StaticBackground, APanningCameraHasNone) {
  cv::Mat texture(400, 900, CV_8UC3);
  cv::randu(texture, cv::Scalar::all(0), cv::Scalar::all(255));
  cv::GaussianBlur(texture, texture, cv::Size(5, 5), 1.5);
  const std::filesystem::path file = test::makeTempDir("static_background") / "pan.avi";
  {
    cv::VideoWriter out(file.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30.0,
                        cv::Size(320, 240));
    ASSERT_TRUE(out.isOpened());
    for (int f = 0; f < 30; ++f) out.write(texture(cv::Rect(10 * f, 20, 320, 240)));
  }
  VideoSource video(file);
  Keyframe key;
  key.frame = 0;
  key.jointsPx = Eigen::VectorXd::Constant(kDims2, 120.0);
  const BackgroundCheck check = estimateStaticBackground(video, 0, 29, key);
  EXPECT_FALSE(check.background);
  EXPECT_NE(check.why.find("camera moves"), std::string::npos) << check.why;
}

TEST(StaticBackground, NoMoreFramesAreSampledThanFitTheFrameBuffer) {
  const test::WalkingFootage& footage = test::walkingFootage();
  VideoSource video(footage.file);
  const std::size_t frameBytes =
      static_cast<std::size_t>(video.info().widthPx) * video.info().heightPx;
  const BackgroundCheck check = estimateStaticBackground(video, 0, video.info().frameCount - 1,
                                                         keyOn(footage.truthPx, 0), 2 * frameBytes);
  EXPECT_FALSE(check.background);
  EXPECT_NE(check.why.find("too large"), std::string::npos) << check.why;
  EXPECT_TRUE(estimateStaticBackground(video, 0, video.info().frameCount - 1,
                                       keyOn(footage.truthPx, 0), 3 * frameBytes)
                  .background);
}

}  // namespace
}  // namespace ew
