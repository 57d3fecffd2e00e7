// METHOD §6: LSQ and MAP reconstruction at a known view, and the unknown-view search.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <random>

#include "core/common/errors.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/eigenwalker/synthetic_walkers.h"

namespace ew {
namespace {

constexpr int kWalkers = 24;

EigenwalkerModel syntheticModel(std::optional<int> components) {
  const Eigen::MatrixXd w = syntheticWalkerSet(kWalkers, 42);
  std::vector<std::string> ids;
  for (int i = 0; i < kWalkers; ++i) ids.push_back("S" + std::to_string(i));
  ModelOptions options;
  options.components = components;
  return buildModel(w, ids, ids, Eigen::VectorXd::Constant(kWalkers, 6.3), options);
}

// A new walker inside the model's span: w̄ + E k with k drawn from the prior.
Eigen::VectorXd walkerInSpan(const EigenwalkerModel& m, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  Eigen::VectorXd k(m.componentCount());
  for (int n = 0; n < k.size(); ++n) k(n) = std::sqrt(m.eigenvalues(n)) * unit(rng);
  return synthesizeWalker(m, k);
}

// A walker outside the span: a fresh synthetic walker from another seed.
Eigen::VectorXd walkerOutsideSpan() { return syntheticWalkerSet(1, 99).col(0); }

TEST(Reconstruction, WalkerInSpanIsExactAtEveryViewByLsq) {
  const auto model = syntheticModel(18);
  const ModelGram gram = precomputeModelGram(model);
  const Eigen::VectorXd w = walkerInSpan(model, 1);
  double worst = 0.0;
  for (int a = -90; a <= 90; ++a) {
    const Reconstruction rec = reconstructLsq(gram, projectToView(w, a), a);
    worst = std::max(worst, (rec.w - w).cwiseAbs().maxCoeff());
    EXPECT_NEAR(rec.objective, 0.0, 1e-6);
  }
  EXPECT_LT(worst, 1e-6) << "mm";
}

TEST(Reconstruction, GramSolutionEqualsDenseLeastSquares) {
  const auto model = syntheticModel(std::nullopt);
  const ModelGram gram = precomputeModelGram(model);
  const Eigen::VectorXd w = walkerOutsideSpan();
  for (double a : {-70.0, 0.0, 25.0, 90.0}) {
    const Eigen::VectorXd obs = projectToView(w, a);
    const Eigen::MatrixXd e = projectionMatrix(a) * model.eigenwalkers;
    const Eigen::VectorXd rhs = obs - projectionMatrix(a) * model.mean;
    const Eigen::VectorXd kQr = e.colPivHouseholderQr().solve(rhs);
    const Reconstruction rec = reconstructLsq(gram, obs, a);
    EXPECT_LT((rec.k - kQr).norm(), 1e-8 * kQr.norm());
    const double residual = (rhs - e * kQr).squaredNorm();
    EXPECT_NEAR(rec.residualSq, residual, 1e-9 * rhs.squaredNorm());
    EXPECT_NEAR(rec.objective, residual, 1e-9 * rhs.squaredNorm());
    // MAP against the dense normal equations of eq. 3.15.
    const double sigma2 = 70.0;
    Eigen::MatrixXd h = e.transpose() * e;
    h.diagonal() += sigma2 * model.eigenvalues.cwiseInverse();
    const Eigen::VectorXd kMap = h.ldlt().solve(e.transpose() * rhs);
    const Reconstruction map = reconstructMap(gram, obs, a, sigma2);
    EXPECT_LT((map.k - kMap).norm(), 1e-8 * kMap.norm());
    const double prior = sigma2 * (kMap.array().square() / model.eigenvalues.array()).sum();
    EXPECT_NEAR(map.objective, (rhs - e * kMap).squaredNorm() + prior, 1e-9 * rhs.squaredNorm());
  }
}

TEST(Reconstruction, MapTendsToLsqAndToTheMean) {
  const auto model = syntheticModel(std::nullopt);
  const ModelGram gram = precomputeModelGram(model);
  const Eigen::VectorXd obs = projectToView(walkerOutsideSpan(), 30.0);
  const Reconstruction lsq = reconstructLsq(gram, obs, 30.0);
  const Reconstruction tiny = reconstructMap(gram, obs, 30.0, 1e-9);
  EXPECT_LT((tiny.k - lsq.k).norm(), 1e-6 * lsq.k.norm());
  const Reconstruction huge = reconstructMap(gram, obs, 30.0, 1e14);
  EXPECT_LT(huge.k.norm(), 1e-6 * lsq.k.norm());
  EXPECT_LT((huge.w - model.mean).cwiseAbs().maxCoeff(), 1e-3);
  // In between, the prior shrinks the coefficients monotonically.
  double previous = lsq.k.norm();
  for (double s2 : {1.0, 70.0, 1000.0, 1e5}) {
    const double norm = reconstructMap(gram, obs, 30.0, s2).k.norm();
    EXPECT_LT(norm, previous) << "sigma2 " << s2;
    previous = norm;
  }
}

TEST(Reconstruction, DataPreservingOutputKeepsTheObservedImage) {
  const auto model = syntheticModel(std::nullopt);
  const ModelGram gram = precomputeModelGram(model);
  const Eigen::VectorXd w = walkerOutsideSpan();
  for (double a : {-45.0, 0.0, 60.0}) {
    const Eigen::VectorXd obs = projectToView(w, a);
    const Reconstruction rec = reconstructMap(gram, obs, a, 70.0);
    EXPECT_GT((projectToView(rec.w, a) - obs).norm(), 1.0) << "model synthesis differs";
    EXPECT_LT((projectToView(rec.wDataPreserving, a) - obs).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT((depthAtView(rec.wDataPreserving, a) - depthAtView(rec.w, a)).cwiseAbs().maxCoeff(), 1e-9);
  }
}

TEST(Reconstruction, MissingJointsDropTheirRows) {
  const auto model = syntheticModel(18);
  const std::vector<int> missing = {5, 8, 0};  // wrists and head
  const ModelGram gram = precomputeModelGram(model, missing);
  EXPECT_EQ(gram.observedPoints.size(), 5u * 12u);
  const Eigen::VectorXd w = walkerInSpan(model, 2);
  Eigen::VectorXd obs = projectToView(w, 40.0);
  for (int b = 0; b < 5; ++b) {
    for (int j : missing) obs.segment<2>(2 * (15 * b + j)).setConstant(std::nan(""));
  }
  const Reconstruction rec = reconstructLsq(gram, obs, 40.0);
  EXPECT_LT((rec.w - w).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_TRUE(rec.wDataPreserving.allFinite());
  EXPECT_LT((rec.wDataPreserving - w).cwiseAbs().maxCoeff(), 1e-6);
  const ViewSearch search = searchViewAngle(gram, obs);
  EXPECT_LT(std::abs(search.best.alphaDeg - 40.0), 0.01);
}

TEST(Reconstruction, BadObservationsAreErrors) {
  const auto model = syntheticModel(10);
  const ModelGram gram = precomputeModelGram(model);
  EXPECT_THROW(reconstructLsq(gram, Eigen::VectorXd::Zero(149), 0.0), Error);
  Eigen::VectorXd obs = projectToView(walkerOutsideSpan(), 0.0);
  obs(7) = std::nan("");
  EXPECT_THROW(reconstructLsq(gram, obs, 0.0), Error);
  EXPECT_THROW(precomputeModelGram(model, {15}), Error);
  EXPECT_THROW(reconstructMap(gram, projectToView(walkerOutsideSpan(), 0.0), 0.0, -1.0), Error);
}

// [SECTION] Unknown view

class UnknownView : public ::testing::TestWithParam<double> {};

TEST_P(UnknownView, TrueAngleIsTheGlobalMinimum) {
  const double alpha = GetParam();
  const auto model = syntheticModel(18);
  const ModelGram gram = precomputeModelGram(model);
  const Eigen::VectorXd w = walkerInSpan(model, 3);
  const Eigen::VectorXd obs = projectToView(w, alpha);
  const ViewSearch s = searchViewAngle(gram, obs);
  EXPECT_LT(std::abs(wrapDeg(s.best.alphaDeg - alpha)), 0.01) << "alpha " << alpha;
  EXPECT_LT((s.best.w - w).cwiseAbs().maxCoeff(), 1e-3) << "mm";
  EXPECT_NEAR(s.best.objective, 0.0, 1e-3);
  ASSERT_FALSE(s.minima.empty());
  EXPECT_EQ(s.minima.front().alphaDeg, s.best.alphaDeg);
  EXPECT_EQ(s.scanObjective.size(), 360);
  EXPECT_LT(s.scanAlphaDeg.minCoeff(), -178.9);
  EXPECT_EQ(s.scanAlphaDeg.maxCoeff(), 180.0);
  for (size_t i = 1; i < s.minima.size(); ++i) {
    const auto& m = s.minima[i];
    EXPECT_GT(m.objective, s.minima.front().objective);
    EXPECT_EQ(m.depthReversedOfBest, isDepthReversedView(m.alphaDeg, s.best.alphaDeg, 20.0));
    EXPECT_EQ(m.mirrorOfBest, isMirrorView(m.alphaDeg, s.best.alphaDeg, 20.0));
    EXPECT_EQ(m.facingOfBest, isFacingView(m.alphaDeg, s.best.alphaDeg, 20.0));
  }
  // MAP trades the fit against the prior, so even a noise-free walker's α̂ moves a little.
  const ViewSearch map = searchViewAngle(gram, obs, {Estimator::Map, 70.0});
  EXPECT_LT(std::abs(wrapDeg(map.best.alphaDeg - alpha)), 1.0);
}

INSTANTIATE_TEST_SUITE_P(Angles, UnknownView, ::testing::Values(-90.0, -60.0, -25.0, 0.0, 30.0, 75.0, 90.0, 180.0));

TEST(UnknownViewSearch, ReportsTheDepthReversedMinimum) {
  // The synthetic walkers are nearly front-back symmetric, so the Necker reading at −α
  // fits well at oblique views; it must be listed, flagged, and worse than the truth.
  const auto model = syntheticModel(18);
  const ModelGram gram = precomputeModelGram(model);
  for (double alpha : {-60.0, 70.0}) {
    const ViewSearch s = searchViewAngle(gram, projectToView(walkerOutsideSpan(), alpha));
    EXPECT_LT(std::abs(s.best.alphaDeg - alpha), 1.5);
    const auto reversed = std::find_if(s.minima.begin(), s.minima.end(),
                                       [](const ViewMinimum& m) { return m.depthReversedOfBest; });
    ASSERT_NE(reversed, s.minima.end()) << "no minimum near " << -alpha;
    EXPECT_GT(reversed->objective, 5.0 * s.minima.front().objective);
    EXPECT_FALSE(reversed->mirrorOfBest);
  }
}

TEST(UnknownViewSearch, RelationsOfAngles) {
  EXPECT_TRUE(isDepthReversedView(-30.0, 30.0, 1.0));
  EXPECT_TRUE(isDepthReversedView(-90.0, 90.0, 1.0));
  EXPECT_FALSE(isDepthReversedView(150.0, 30.0, 1.0));
  EXPECT_TRUE(isMirrorView(150.0, 30.0, 1.0));
  EXPECT_TRUE(isMirrorView(-100.0, -80.0, 1.0));
  EXPECT_TRUE(isMirrorView(185.0, 0.0, 10.0));
  EXPECT_FALSE(isMirrorView(-30.0, 30.0, 10.0));
  EXPECT_TRUE(isFacingView(-150.0, 30.0, 1.0));
  EXPECT_TRUE(isFacingView(180.0, 0.0, 1.0));
  EXPECT_FALSE(isFacingView(150.0, 30.0, 1.0));
}

TEST(UnknownViewSearch, ObjectiveProfileMatchesKnownViewObjective) {
  const auto model = syntheticModel(std::nullopt);
  const ModelGram gram = precomputeModelGram(model);
  const Eigen::VectorXd obs = projectToView(walkerOutsideSpan(), -20.0);
  const Eigen::VectorXd alphas = Eigen::VectorXd::LinSpaced(5, -40.0, 40.0);
  const EstimatorOptions map{Estimator::Map, 200.0};
  const Eigen::VectorXd j = viewObjective(gram, obs, alphas, map);
  for (int i = 0; i < 5; ++i)
    EXPECT_DOUBLE_EQ(j(i), reconstructKnownView(gram, obs, alphas(i), map).objective);
}

}  // namespace
}  // namespace ew
