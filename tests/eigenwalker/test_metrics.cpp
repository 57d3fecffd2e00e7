// METHOD §7: depth errors (closed form over one cycle and against frames), MPJPE, view error.
#include <gtest/gtest.h>

#include <numbers>

#include "core/common/errors.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/synthetic_walkers.h"

namespace ew {
namespace {

constexpr double kOmega = 2.0 * std::numbers::pi;  // 1 Hz
constexpr double kRateHz = 100.0;                  // 100 frames = exactly one cycle

Eigen::VectorXd oneCycle() { return frameTimes(100, kRateHz); }

TEST(Metrics, ClosedFormEqualsTheAverageOverOneCycle) {
  const Eigen::VectorXd wTrue = syntheticWalkerSet(2, 8).col(0);
  const Eigen::VectorXd wRec = syntheticWalkerSet(2, 8).col(1);
  for (double a : {-90.0, 0.0, 37.0}) {
    const DepthErrors e = depthErrors(wTrue, wRec, a);
    // Uniform samples of one period average a degree-4 trigonometric polynomial exactly.
    const Eigen::MatrixXd dTrue = depthFramesAtView(synthesizeFrames(wTrue, kOmega, 0.3, oneCycle()), a);
    const Eigen::MatrixXd dRec = depthFramesAtView(synthesizeFrames(wRec, kOmega, 0.3, oneCycle()), a);
    const Eigen::VectorXd numeric = (dTrue - dRec).array().square().colwise().mean().transpose();
    EXPECT_LT((e.absPerJoint - numeric).cwiseAbs().maxCoeff(), 1e-9 * numeric.maxCoeff());
    EXPECT_NEAR(e.absMean, numeric.mean(), 1e-9 * numeric.mean());
    const Eigen::RowVectorXd mean = dTrue.colwise().mean();
    const double sigmaM2 = (dTrue.rowwise() - mean).array().square().colwise().mean().mean();
    EXPECT_NEAR(e.sigmaM2Mm2, sigmaM2, 1e-9 * sigmaM2);
    EXPECT_NEAR(depthVarianceMm2(wTrue, a), sigmaM2, 1e-9 * sigmaM2);
    EXPECT_NEAR(e.relMean, e.absMean / e.sigmaM2Mm2, 1e-12);
    // The frame version on exactly one cycle agrees with the closed form.
    const DepthErrors f = depthErrorsFrames(synthesizeFrames(wTrue, kOmega, 0.3, oneCycle()),
                                            kRateHz, wRec, kOmega, 0.3, a);
    EXPECT_NEAR(f.absMean, e.absMean, 1e-9 * e.absMean);
    EXPECT_NEAR(f.sigmaM2Mm2, e.sigmaM2Mm2, 1e-9 * e.sigmaM2Mm2);
  }
}

TEST(Metrics, IdenticalWalkersHaveZeroError) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const DepthErrors e = depthErrors(w, w, 20.0);
  EXPECT_EQ(e.absMean, 0.0);
  EXPECT_EQ(e.relMean, 0.0);
  EXPECT_GT(e.sigmaM2Mm2, 0.0);
  EXPECT_EQ(mpjpe(w, w), 0.0);
}

TEST(Metrics, OnlyTheDepthAxisCounts) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  Eigen::VectorXd shifted = w;
  for (int j = 0; j < 15; ++j) shifted(3 * j) += 10.0;  // every joint's mean x + 10 mm
  EXPECT_NEAR(depthErrors(w, shifted, 0.0).absMean, 0.0, 1e-20);    // depth = y at 0°
  EXPECT_NEAR(depthErrors(w, shifted, 90.0).absMean, 100.0, 1e-9);  // depth = −x at 90°
  EXPECT_NEAR(depthErrors(w, shifted, 30.0).absMean, 25.0, 1e-9);   // (10 sin 30°)²
  EXPECT_NEAR(mpjpe(w, shifted), 10.0, 1e-9);
}

TEST(Metrics, MpjpeAgainstFramesSkipsNaN) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  Eigen::MatrixXd frames = synthesizeFrames(w, kOmega, 0.1, oneCycle());
  frames.col(2).array() += 5.0;  // head 5 mm higher in the data
  frames(10, 0) = std::nan("");
  EXPECT_NEAR(mpjpeFrames(frames, kRateHz, w, kOmega, 0.1), 5.0 / 15.0, 1e-9);
  frames.col(3).setConstant(std::nan(""));
  EXPECT_THROW(mpjpeFrames(frames, kRateHz, w, kOmega, 0.1), Error);
}

TEST(Metrics, ViewAngleErrorWrapsToHalfCircle) {
  EXPECT_DOUBLE_EQ(viewAngleErrorDeg(10.0, 10.0), 0.0);
  EXPECT_DOUBLE_EQ(viewAngleErrorDeg(170.0, -170.0), 20.0);
  EXPECT_DOUBLE_EQ(viewAngleErrorDeg(-90.0, 90.0), 180.0);
  EXPECT_DOUBLE_EQ(viewAngleErrorDeg(-30.0, 45.0), 75.0);
  EXPECT_DOUBLE_EQ(viewAngleErrorDeg(359.0, 0.0), 1.0);
}

TEST(Metrics, WrongSizesAreErrors) {
  EXPECT_THROW(depthErrors(Eigen::VectorXd::Zero(150), syntheticBaseWalker(), 0.0), Error);
  EXPECT_THROW(mpjpe(syntheticBaseWalker(), syntheticBaseWalker(), 0), Error);
}

}  // namespace
}  // namespace ew
