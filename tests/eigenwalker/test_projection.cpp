// METHOD §5: orthographic projection at a horizontal view angle, and depth.
#include <gtest/gtest.h>

#include "core/common/errors.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/synthetic_walkers.h"

namespace ew {
namespace {

TEST(Projection, MatrixFreeEqualsDenseMatrix) {
  const Eigen::MatrixXd w = syntheticWalkerSet(3, 11);
  for (double a : {-180.0, -90.0, -33.3, 0.0, 17.0, 90.0, 135.0}) {
    const Eigen::MatrixXd dense = projectionMatrix(a) * w;
    EXPECT_LT((projectToView(w, a) - dense).cwiseAbs().maxCoeff(), 1e-9) << "alpha " << a;
  }
}

TEST(Projection, FrontalAndProfileViews) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const Eigen::VectorXd front = projectToView(w, 0.0), side = projectToView(w, 90.0);
  const Eigen::VectorXd dFront = depthAtView(w, 0.0), dSide = depthAtView(w, 90.0);
  for (int p = 0; p < kPointsPerWalker; ++p) {
    EXPECT_DOUBLE_EQ(front(2 * p), w(3 * p));         // u = x
    EXPECT_DOUBLE_EQ(front(2 * p + 1), w(3 * p + 2));  // v = z
    EXPECT_NEAR(side(2 * p), w(3 * p + 1), 1e-9);      // u = y
    EXPECT_DOUBLE_EQ(dFront(p), w(3 * p + 1));         // d = y
    EXPECT_NEAR(dSide(p), -w(3 * p), 1e-9);            // d = −x
  }
}

TEST(Projection, ImageAndDepthRecomposeTheWalker) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  for (double a : {-120.0, -45.0, 10.0, 60.0}) {
    const Eigen::MatrixXd back = composeFromView(projectToView(w, a), depthAtView(w, a), a);
    EXPECT_LT((back - w).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(Projection, FramesCommuteWithFourierSynthesis) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const Eigen::VectorXd t = frameTimes(40, 100.0);
  const Eigen::MatrixXd frames = synthesizeFrames(w, 6.0, 0.4, t);
  const Eigen::MatrixXd viaFrames = projectFramesToView(frames, 35.0);
  const Eigen::MatrixXd viaFourier = synthesizeFrames(projectToView(w, 35.0), 6.0, 0.4, t);
  EXPECT_LT((viaFrames - viaFourier).cwiseAbs().maxCoeff(), 1e-9);
  const Eigen::MatrixXd depthFrames = depthFramesAtView(frames, 35.0);
  ASSERT_EQ(depthFrames.cols(), 15);
  const Eigen::VectorXd d = depthAtView(w, 35.0);
  // Depth frames are the 1-D "walker" with coefficients d.
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    const double th = 6.0 * t(i) + 0.4;
    const double expected = d(4) + d(15 + 4) * std::sin(th) + d(30 + 4) * std::cos(th) +
                            d(45 + 4) * std::sin(2 * th) + d(60 + 4) * std::cos(2 * th);
    EXPECT_NEAR(depthFrames(i, 4), expected, 1e-9);
  }
}

TEST(Projection, WrapDeg) {
  EXPECT_DOUBLE_EQ(wrapDeg(180.0), 180.0);
  EXPECT_DOUBLE_EQ(wrapDeg(-180.0), 180.0);
  EXPECT_DOUBLE_EQ(wrapDeg(190.0), -170.0);
  EXPECT_DOUBLE_EQ(wrapDeg(-725.0), -5.0);
}

TEST(Projection, WrongShapesAreBadArgument) {
  EXPECT_THROW(projectToView(Eigen::VectorXd::Zero(150), 0.0), Error);
  EXPECT_THROW(projectFramesToView(Eigen::MatrixXd::Zero(3, 30), 0.0), Error);
}

}  // namespace
}  // namespace ew
