// A detector's track corrected by hand (core/tracking/corrected_track.h): the correction's
// offset carried to the frames around it, fading; interpolated between two near corrections;
// the detection elsewhere.
#include <gtest/gtest.h>

#include <cmath>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/tracking/corrected_track.h"

namespace ew {
namespace {

constexpr int kAnkle = static_cast<int>(Joint::LAnkle);

// 60 frames, every joint moving right 2 px a frame.
Eigen::MatrixXd track() {
  Eigen::MatrixXd px(60, kDims2);
  for (int f = 0; f < 60; ++f)
    for (int j = 0; j < kJointCount; ++j) px.row(f).segment<2>(2 * j) << 100.0 + 2.0 * f + 10 * j, 300.0 + 20 * j;
  return px;
}

Keyframe mark(int frame, const Eigen::MatrixXd& px, Eigen::Vector2d moveAnkleBy) {
  Keyframe k{frame, Eigen::RowVectorXd::Constant(kDims2, std::nan(""))};
  k.jointsPx.segment<2>(2 * kAnkle) = px.row(frame).segment<2>(2 * kAnkle) + moveAnkleBy.transpose();
  return k;
}

TEST(CorrectedTrack, ACorrectionFadesOverItsSpanAndLeavesTheRest) {
  const Eigen::MatrixXd px = track();
  const Keyframes corrections{"v.mp4", {mark(20, px, {30.0, -12.0})}};
  const Eigen::MatrixXd out = correctTrack(px, corrections, 5);
  EXPECT_TRUE(out.row(20).segment<2>(2 * kAnkle).isApprox(px.row(20).segment<2>(2 * kAnkle) + Eigen::RowVector2d(30, -12)));
  // Half-way through the span, half the offset; beyond it, none.
  EXPECT_NEAR(out(23, 2 * kAnkle) - px(23, 2 * kAnkle), 30.0 * (1.0 - 3.0 / 6.0), 1e-12);
  EXPECT_NEAR(out(17, 2 * kAnkle + 1) - px(17, 2 * kAnkle + 1), -12.0 * (1.0 - 3.0 / 6.0), 1e-12);
  EXPECT_EQ(out(26, 2 * kAnkle), px(26, 2 * kAnkle));
  EXPECT_EQ(out(14, 2 * kAnkle), px(14, 2 * kAnkle));
  // Other joints are the detection's.
  EXPECT_TRUE(out.leftCols(2 * kAnkle).isApprox(px.leftCols(2 * kAnkle)));
}

TEST(CorrectedTrack, TwoNearCorrectionsAreInterpolated) {
  const Eigen::MatrixXd px = track();
  const Keyframes corrections{"v.mp4", {mark(20, px, {10.0, 0.0}), mark(26, px, {40.0, 0.0})}};
  const Eigen::MatrixXd out = correctTrack(px, corrections, 5);
  EXPECT_NEAR(out(23, 2 * kAnkle) - px(23, 2 * kAnkle), 25.0, 1e-12);
  EXPECT_NEAR(out(26, 2 * kAnkle) - px(26, 2 * kAnkle), 40.0, 1e-12);
  EXPECT_NEAR(out(29, 2 * kAnkle) - px(29, 2 * kAnkle), 40.0 * (1.0 - 3.0 / 6.0), 1e-12);
}

TEST(CorrectedTrack, AJointTheDetectorMissedIsTheMarkOnItsFrameOnly) {
  Eigen::MatrixXd px = track();
  const Eigen::Vector2d truth = px.row(30).segment<2>(2 * kAnkle).transpose();
  px(30, 2 * kAnkle) = px(30, 2 * kAnkle + 1) = std::nan("");
  Keyframe k{30, Eigen::RowVectorXd::Constant(kDims2, std::nan(""))};
  k.jointsPx.segment<2>(2 * kAnkle) = truth.transpose();
  const Eigen::MatrixXd out = correctTrack(px, {"v.mp4", {k}}, 5);
  EXPECT_TRUE(out.row(30).segment<2>(2 * kAnkle).transpose().isApprox(truth));
  EXPECT_EQ(out(31, 2 * kAnkle), px(31, 2 * kAnkle));
  // A keyframe beyond the track is ignored; a negative span and a wrong shape are refused.
  EXPECT_TRUE(correctTrack(px.topRows(10), {"v.mp4", {k}}, 5).isApprox(px.topRows(10)));
  EXPECT_THROW(correctTrack(px, {"v.mp4", {k}}, -1), Error);
  EXPECT_THROW(correctTrack(px.leftCols(10), {"v.mp4", {k}}, 5), Error);
}

// A pose estimator's trial corrected (reconstruct --corrections, the viewer): a span of
// kCorrectionSpanS at its rate, the corrected joint sure there and only there.
TEST(CorrectedTrack, ATrialIsCorrectedOverAQuarterSecondAndMadeSureThere) {
  KeypointTrial t;
  t.rateHz = 30.0;
  t.jointsPx = track();
  t.frameCount = static_cast<int>(t.jointsPx.rows());
  t.jointConfidence = Eigen::MatrixXd::Constant(t.frameCount, kJointCount, 0.4);
  const Eigen::MatrixXd px = t.jointsPx;
  const Keyframes corrections{"v.mp4", {mark(20, px, {30.0, 0.0})}};
  EXPECT_EQ(correctTrial(t, corrections), 8);  // 0.25 s at 30 Hz
  EXPECT_TRUE(t.jointsPx.isApprox(correctTrack(px, corrections, 8)));
  EXPECT_EQ(t.jointConfidence(20, kAnkle), 1.0);
  EXPECT_EQ(t.jointConfidence(21, kAnkle), 0.4);
  EXPECT_EQ(t.jointConfidence(20, kAnkle - 1), 0.4);
}

}  // namespace
}  // namespace ew
