// METHOD §3: the Fourier fit recovers ω, φ and w from synthetic 2-harmonic walkers.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/common/errors.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/synthetic_walkers.h"

namespace ew {
namespace {

constexpr double kRateHz = 120.0;
constexpr double kStrideHz = 1.05;
constexpr double kOmega = 2.0 * std::numbers::pi * kStrideHz;
constexpr double kPhase = 0.7;

Eigen::MatrixXd walkerFrames(const Eigen::VectorXd& w, double cycles) {
  const int count = static_cast<int>(std::lround(cycles * kRateHz / kStrideHz));
  return synthesizeFrames(w, kOmega, kPhase, frameTimes(count, kRateHz));
}

double relativeError(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).norm() / b.norm();
}

class FourierCycles : public ::testing::TestWithParam<double> {};

TEST_P(FourierCycles, RecoversOmegaPhaseAndCoefficients) {
  const Eigen::VectorXd w = syntheticWalkerSet(1, 7).col(0);
  const FourierFit fit = fitFourier(walkerFrames(w, GetParam()), kRateHz);
  EXPECT_NEAR(fit.omegaRadS / kOmega, 1.0, 1e-3);
  EXPECT_NEAR(fit.omegaRadS / kOmega, 1.0, 1e-7) << "noise-free data: the peak is exact";
  EXPECT_NEAR(std::remainder(fit.phaseRad - kPhase, 2 * std::numbers::pi), 0.0, 1e-6);
  EXPECT_LT(relativeError(fit.w, w), 1e-6);
  EXPECT_LT(fit.residualShare, 1e-10);
  EXPECT_NEAR(fit.cycles, GetParam(), 0.01);
  EXPECT_EQ(fit.omegaSource, "scan");
}

INSTANTIATE_TEST_SUITE_P(OneToFourCycles, FourierCycles, ::testing::Values(1.0, 1.3, 4.0));

TEST(Fourier, HintNearTheTruthAgreesWithTheScan) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  FourierFitOptions options;
  options.omegaHintRadS = kOmega * 1.03;  // gait events are a few % off
  const FourierFit fit = fitFourier(walkerFrames(w, 2.5), kRateHz, options);
  EXPECT_EQ(fit.omegaSource, "scan, agrees with hint");
  EXPECT_TRUE(fit.warnings.empty());
  EXPECT_NEAR(fit.omegaRadS / kOmega, 1.0, 1e-7);
}

TEST(Fourier, WildHintIsOverruledWithAWarning) {
  FourierFitOptions options;
  options.omegaHintRadS = kOmega * 1.9;
  const FourierFit fit = fitFourier(walkerFrames(syntheticBaseWalker(), 4.0), kRateHz, options);
  EXPECT_NEAR(fit.omegaRadS / kOmega, 1.0, 1e-6);
  ASSERT_EQ(fit.warnings.size(), 1u);
  EXPECT_NE(fit.warnings[0].find("spectral"), std::string::npos) << fit.warnings[0];
}

TEST(Fourier, FixedOmegaSkipsTheScan) {
  FourierFitOptions options;
  options.omegaFixedRadS = kOmega;
  const Eigen::VectorXd w = syntheticBaseWalker();
  const FourierFit fit = fitFourier(walkerFrames(w, 1.3), kRateHz, options);
  EXPECT_EQ(fit.omegaSource, "fixed");
  EXPECT_EQ(fit.omegaRadS, kOmega);
  EXPECT_LT(relativeError(fit.w, w), 1e-10);
}

// Gaussian noise σ = 5 mm on every coordinate, 4 cycles (457 frames). Least squares
// gives each harmonic coefficient a standard error σ·√(2/T) ≈ 0.33 mm (p0: 0.23 mm), so
// 2 mm is 6 standard errors; ω's relative error is of order σ/(A·√(T·channels)·ωT) ≈ 1e-5,
// far inside 0.1 %.
TEST(Fourier, NoisyFramesStayClose) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  Eigen::MatrixXd frames = walkerFrames(w, 4.0);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 5.0);
  for (Eigen::Index i = 0; i < frames.size(); ++i) frames.data()[i] += noise(rng);
  const FourierFit fit = fitFourier(frames, kRateHz);
  EXPECT_NEAR(fit.omegaRadS / kOmega, 1.0, 1e-3);
  EXPECT_LT((fit.w - w).cwiseAbs().maxCoeff(), 2.0);
  EXPECT_NEAR(std::remainder(fit.phaseRad - kPhase, 2 * std::numbers::pi), 0.0, 0.01);
  EXPECT_GT(fit.residualShare, 0.0);
}

TEST(Fourier, HarmonicSharesOfTheBaseWalker) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const FourierFit fit = fitFourier(walkerFrames(w, 4.0), kRateHz);
  // Whole cycles: the shares are the harmonics' variances over the total.
  double v1 = 0, v2 = 0;
  for (int b = 1; b <= 4; ++b) (b <= 2 ? v1 : v2) += 0.5 * w.segment(b * 45, 45).squaredNorm();
  EXPECT_NEAR(fit.h1Share, v1 / (v1 + v2), 2e-3);
  EXPECT_NEAR(fit.h2Share, v2 / (v1 + v2), 2e-3);
  EXPECT_GT(fit.h1Share, 0.8);
}

TEST(Fourier, TwoDimensionalFramesFitTheProjectedWalker) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const Eigen::MatrixXd frames2d = projectFramesToView(walkerFrames(w, 1.5), 30.0);
  const FourierFit fit = fitFourier(frames2d, kRateHz);
  ASSERT_EQ(fit.w.size(), kFourierDims2);
  // v = z, so the 2D phase reference equals the 3D one and ŵ = C(α) w.
  EXPECT_LT(relativeError(fit.w, projectToView(w, 30.0)), 1e-6);
  EXPECT_NEAR(std::remainder(fit.phaseRad - kPhase, 2 * std::numbers::pi), 0.0, 1e-6);
}

TEST(Fourier, LessThanOneCycleIsBadData) {
  FourierFitOptions options;
  options.file = "short.c3d";
  try {
    fitFourier(walkerFrames(syntheticBaseWalker(), 0.8), kRateHz, options);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadData);
    EXPECT_NE(std::string(e.what()).find("short.c3d"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("less than one"), std::string::npos) << e.what();
  }
}

TEST(Fourier, FixedOmegaBelowOneCycleIsBadData) {
  FourierFitOptions options;
  options.omegaFixedRadS = kOmega * 0.5;  // 1.3 cycles at kOmega = 0.65 at half of it
  EXPECT_THROW(fitFourier(walkerFrames(syntheticBaseWalker(), 1.3), kRateHz, options), Error);
}

TEST(Fourier, DropsFramesWithNaN) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  Eigen::MatrixXd frames = walkerFrames(w, 2.0);
  for (Eigen::Index i = 5; i < frames.rows(); i += 12) frames(i, 7) = std::nan("");
  const FourierFit fit = fitFourier(frames, kRateHz);
  EXPECT_GT(fit.framesDropped, 0);
  EXPECT_EQ(fit.framesUsed + fit.framesDropped, frames.rows());
  EXPECT_LT(relativeError(fit.w, w), 1e-6);
  EXPECT_NEAR(fit.omegaRadS / kOmega, 1.0, 1e-7);
}

TEST(Fourier, TooManyMissingFramesIsBadData) {
  Eigen::MatrixXd frames = walkerFrames(syntheticBaseWalker(), 2.0);
  for (Eigen::Index i = 0; i < frames.rows(); i += 4) frames(i, 0) = std::nan("");  // 25 %
  try {
    fitFourier(frames, kRateHz);
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadData);
    EXPECT_NE(std::string(e.what()).find("missing"), std::string::npos) << e.what();
  }
}

TEST(Fourier, WrongColumnCountIsBadArgument) {
  const Eigen::MatrixXd frames = Eigen::MatrixXd::Zero(200, 44);
  try {
    fitFourier(frames, kRateHz);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadArgument);
  }
}

TEST(Fourier, RephaseDescribesTheSameMotion) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const Eigen::VectorXd t = frameTimes(50, kRateHz);
  const Eigen::VectorXd shifted = rephase(w, 0.3, -1.1);
  EXPECT_LT((synthesizeFrames(w, kOmega, 0.3, t) - synthesizeFrames(shifted, kOmega, -1.1, t))
                .cwiseAbs()
                .maxCoeff(),
            1e-9);
  EXPECT_GT((shifted - w).norm(), 1.0);
}

TEST(Fourier, SynthesisMatchesTheFormula) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const double t = 0.37, th = kOmega * t + kPhase;
  const Eigen::VectorXd times = Eigen::VectorXd::Constant(1, t);
  const Eigen::RowVectorXd p = synthesizeFrames(w, kOmega, kPhase, times).row(0);
  for (int c : {0, 17, 44}) {
    const double expected = w(c) + w(45 + c) * std::sin(th) + w(90 + c) * std::cos(th) +
                            w(135 + c) * std::sin(2 * th) + w(180 + c) * std::cos(2 * th);
    EXPECT_NEAR(p(c), expected, 1e-9);
  }
}

// The camera fit's Jacobian takes its ω and φ columns from fourierBasisPhaseDerivative by the
// chain rule: it must be the synthesis's derivative, checked against central differences.
TEST(Fourier, ThePhaseDerivativeIsTheSynthesisDerivative) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const Eigen::VectorXd t = frameTimes(40, 30.0);
  const Eigen::Map<const Eigen::MatrixXd> blocks(w.data(), 45, kFourierBlocks);
  EXPECT_LT((fourierBasis(kOmega, kPhase, t) * blocks.transpose() - synthesizeFrames(w, kOmega, kPhase, t))
                .cwiseAbs()
                .maxCoeff(),
            1e-9);
  const Eigen::MatrixXd analytic = fourierBasisPhaseDerivative(kOmega, kPhase, t) * blocks.transpose();
  const double h = 1e-6;  // rad: central differences err by ~h² |w|, far below the tolerance
  const Eigen::MatrixXd numeric =
      (synthesizeFrames(w, kOmega, kPhase + h, t) - synthesizeFrames(w, kOmega, kPhase - h, t)) / (2 * h);
  EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(), 1e-5 * numeric.cwiseAbs().maxCoeff());
  EXPECT_GT(numeric.cwiseAbs().maxCoeff(), 10.0) << "mm per rad: a walk that moves";
}

}  // namespace
}  // namespace ew
