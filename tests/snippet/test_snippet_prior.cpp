// The snippet prior and single-snippet inference (core/snippet): a known Gaussian mixture
// fitted back, the per-cluster MAP against a dense solve, and EM never lowering L.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "core/common/errors.h"
#include "core/snippet/snippet_fit.h"
#include "core/snippet/snippet_prior.h"
#include "core/synth/random.h"

namespace ew {
namespace {

// Samples of one PPCA cluster: mean + √λ u a + √σ² (I − uuᵀ) b, a, b standard normal.
void sampleCluster(Eigen::MatrixXd& out, int& col, int n, const Eigen::Vector3d& mean,
                   const Eigen::Vector3d& u, double lambda, double sigma2, Rng& rng) {
  const Eigen::Matrix3d rest = Eigen::Matrix3d::Identity() - u * u.transpose();
  for (int i = 0; i < n; ++i, ++col) {
    const Eigen::Vector3d b(rng.normal(), rng.normal(), rng.normal());
    out.col(col) = mean + std::sqrt(lambda) * rng.normal() * u + std::sqrt(sigma2) * rest * b;
  }
}

TEST(SnippetPrior, KnownTwoComponentMixtureIsFittedBack) {
  Rng rng(7);
  const int n = 20000, nA = 6000;
  Eigen::MatrixXd x(3, n);
  int col = 0;
  const Eigen::Vector3d uA(0, 0, 1), uB = Eigen::Vector3d(1, 1, 0).normalized();
  sampleCluster(x, col, nA, Eigen::Vector3d(0, 0, 0), uA, 4.0, 0.25, rng);
  sampleCluster(x, col, n - nA, Eigen::Vector3d(20, 0, 5), uB, 9.0, 0.5, rng);
  SnippetPriorOptions o;
  o.clusters = 2;
  o.components = 1;
  o.minNoiseVarianceMm2 = 1e-6;
  const SnippetPrior prior = fitSnippetMixture(x, o);
  ASSERT_EQ(prior.components.size(), 2u);
  const bool aFirst = prior.components[0].mean.norm() < prior.components[1].mean.norm();
  const PpcaComponent& a = prior.components[aFirst ? 0 : 1];
  const PpcaComponent& b = prior.components[aFirst ? 1 : 0];
  // Standard errors: weight √(0.21/20000) = 0.003, a mean ≤ √(9/14000) = 0.025, a variance
  // λ√(2/n) ≤ 2 %: the tolerances are about 3 to 4 standard errors.
  EXPECT_NEAR(a.weight, 0.3, 0.01);
  EXPECT_NEAR(b.weight, 0.7, 0.01);
  EXPECT_LT((a.mean - Eigen::Vector3d(0, 0, 0)).norm(), 0.1);
  EXPECT_LT((b.mean - Eigen::Vector3d(20, 0, 5)).norm(), 0.1);
  EXPECT_NEAR(a.variances(0), 4.0, 0.2);
  EXPECT_NEAR(b.variances(0), 9.0, 0.45);
  EXPECT_NEAR(a.noiseVariance, 0.25, 0.0125);
  EXPECT_NEAR(b.noiseVariance, 0.5, 0.025);
  EXPECT_NEAR(std::abs(a.basis.col(0).dot(uA)), 1.0, 1e-3);
  EXPECT_NEAR(std::abs(b.basis.col(0).dot(uB)), 1.0, 1e-3);
}

// 200 samples of a cluster at the origin and 200 of one at `secondMean`, and the options
// that fit two one-component clusters to them.
struct TwoClusters {
  Eigen::MatrixXd x = Eigen::MatrixXd(3, 400);
  SnippetPriorOptions options;
};
TwoClusters twoClusters(std::uint64_t seed, const Eigen::Vector3d& secondMean) {
  Rng rng(seed);
  TwoClusters t;
  int col = 0;
  sampleCluster(t.x, col, 200, Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1, 0), 3.0, 0.4, rng);
  sampleCluster(t.x, col, 200, secondMean, Eigen::Vector3d(1, 0, 0), 2.0, 0.3, rng);
  t.options.clusters = 2;
  t.options.components = 1;
  t.options.minNoiseVarianceMm2 = 1e-6;
  return t;
}

TEST(SnippetPrior, DensityIsTheDenseGaussianMixture) {
  const TwoClusters t = twoClusters(3, Eigen::Vector3d(8, 8, 0));
  const SnippetPrior prior = fitSnippetMixture(t.x, t.options);
  const Eigen::Vector3d p(1.0, -0.5, 0.3);
  double dense = 0.0;
  for (const auto& c : prior.components) {
    const Eigen::MatrixXd cov = c.basis * (c.variances.array() - c.noiseVariance).matrix().asDiagonal() *
                                    c.basis.transpose() + c.noiseVariance * Eigen::Matrix3d::Identity();
    const Eigen::Vector3d e = p - c.mean;
    dense += c.weight * std::exp(-0.5 * e.dot(cov.ldlt().solve(e))) /
             std::sqrt(std::pow(2 * M_PI, 3) * cov.determinant());
  }
  EXPECT_NEAR(logDensity(prior, p), std::log(dense), 1e-9);
}

// Two clusters so far apart that each point's responsibility for the other one lies in
// the denormal range (log ratio ≈ −720): EM must leave such tail points out of the
// weighted PCA (on the real walkers they made the SVD return NaN, m = 32) and give back
// the clusters of the k-means fit.
TEST(SnippetPrior, EmLeavesTheFarTailOut) {
  TwoClusters t = twoClusters(11, Eigen::Vector3d(24, 0, 0));
  const SnippetPrior kmeansOnly = fitSnippetMixture(t.x, t.options);
  t.options.emIterations = 3;
  const SnippetPrior refined = fitSnippetMixture(t.x, t.options);
  ASSERT_NO_THROW(checkSnippetPrior(refined));
  ASSERT_EQ(refined.components.size(), 2u);
  for (size_t j = 0; j < 2; ++j) {
    // Tail weights below 1e-12 of the mean move the moments by less than 1e-9 relative.
    EXPECT_LT((refined.components[j].mean - kmeansOnly.components[j].mean).norm(), 1e-9);
    EXPECT_NEAR(refined.components[j].variances(0), kmeansOnly.components[j].variances(0),
                1e-9 * kmeansOnly.components[j].variances(0));
    EXPECT_NEAR(refined.components[j].weight, 0.5, 1e-12);
  }
}

// A random PPCA cluster over one frame of 15 joints (D = 45).
PpcaComponent randomComponent(Rng& rng, int q) {
  PpcaComponent c;
  c.weight = 1.0;
  c.members = 100;
  c.mean = Eigen::VectorXd::NullaryExpr(45, [&] { return rng.normal(0.0, 300.0); });
  Eigen::MatrixXd g = Eigen::MatrixXd::NullaryExpr(45, q, [&] { return rng.normal(); });
  c.basis = g.householderQr().householderQ() * Eigen::MatrixXd::Identity(45, q);
  c.variances = Eigen::VectorXd::LinSpaced(q, 4000.0, 500.0);
  c.noiseVariance = 30.0;
  return c;
}

TEST(SnippetFit, ClusterMapMatchesTheDenseClosedForm) {
  Rng rng(11);
  const PpcaComponent c = randomComponent(rng, 6);
  SnippetCamera cam;
  cam.alphaDeg = 33.0;
  cam.scale = 1.7;
  cam.shift = Eigen::Vector2d(40.0, -12.0);
  const Eigen::VectorXd truth = c.mean + c.basis * Eigen::VectorXd::Constant(6, 20.0);
  Eigen::MatrixXd y = renderSnippet(truth, 1, cam);
  for (Eigen::Index i = 0; i < y.size(); ++i) y.data()[i] += rng.normal(0.0, 3.0);
  y(0, 2 * 4) = y(0, 2 * 4 + 1) = NAN;  // r_elbow not seen
  const double nu = 25.0;
  const ClusterMap fast = clusterMap(c, y, cam, nu);
  // Dense, unknowns [x; t]: (HᵀH/ν + diag(C⁻¹, 0)) [x; t] = Hᵀy/ν + [C⁻¹ μ; 0], H = [A E]
  // with E putting t_u on the u rows and t_v on the v rows (a flat prior on t).
  const double a = cam.alphaDeg * M_PI / 180.0;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(30, 47);
  Eigen::VectorXd yv = Eigen::VectorXd::Zero(30);
  for (int j = 0; j < 15; ++j) {
    if (j == 4) continue;
    H(2 * j, 3 * j) = cam.scale * std::cos(a);
    H(2 * j, 3 * j + 1) = cam.scale * std::sin(a);
    H(2 * j + 1, 3 * j + 2) = cam.scale;
    H(2 * j, 45) = 1.0;
    H(2 * j + 1, 46) = 1.0;
    yv(2 * j) = y(0, 2 * j);
    yv(2 * j + 1) = y(0, 2 * j + 1);
  }
  const Eigen::MatrixXd cov = c.basis * (c.variances.array() - c.noiseVariance).matrix().asDiagonal() *
                                  c.basis.transpose() + c.noiseVariance * Eigen::MatrixXd::Identity(45, 45);
  const Eigen::MatrixXd covInv = cov.inverse();
  Eigen::MatrixXd lhs = H.transpose() * H / nu;
  lhs.topLeftCorner(45, 45) += covInv;
  Eigen::VectorXd rhs = H.transpose() * yv / nu;
  rhs.head(45) += covInv * c.mean;
  const Eigen::VectorXd dense = lhs.ldlt().solve(rhs);
  EXPECT_LT((fast.snippet - dense.head(45)).cwiseAbs().maxCoeff(), 1e-7 * dense.head(45).cwiseAbs().maxCoeff());
  EXPECT_LT((fast.shift - dense.tail(2)).cwiseAbs().maxCoeff(), 1e-6);
}

SnippetPrior randomMixture(Rng& rng, int clusters) {
  SnippetPrior prior;
  prior.frames = 1;
  for (int j = 0; j < clusters; ++j) {
    prior.components.push_back(randomComponent(rng, 5));
    prior.components.back().weight = 1.0 / clusters;
  }
  return prior;
}

TEST(SnippetFit, EmNeverLowersThePosterior) {
  Rng rng(5);
  const PreparedSnippetPrior prep = prepareSnippetPrior(randomMixture(rng, 4));
  for (int trial = 0; trial < 6; ++trial) {
    // A point between two clusters, so several share the responsibility early on.
    const Eigen::VectorXd x = 0.5 * (prep.prior.components[0].mean + prep.prior.components[1].mean);
    SnippetCamera cam;
    cam.alphaDeg = -70.0 + 30.0 * trial;
    Eigen::MatrixXd y = renderSnippet(x, 1, cam);
    for (Eigen::Index i = 0; i < y.size(); ++i) y.data()[i] += rng.normal(0.0, 10.0);
    SnippetFitOptions o;
    o.rejectOutliers = false;
    o.scale = 1.0;
    const SnippetFit fit = fitSnippet(prep, y, o);
    ASSERT_GE(fit.trace.size(), 1u);
    for (size_t i = 1; i < fit.trace.size(); ++i)
      EXPECT_GE(fit.trace[i], fit.trace[i - 1] - 1e-9 * std::abs(fit.trace[i - 1])) << "iteration " << i;
    EXPECT_NEAR(snippetLogPosterior(prep.prior, y, fit.snippet, fit.camera, 25.0), fit.logPosterior,
                1e-9 * std::abs(fit.logPosterior));
  }
}

TEST(SnippetFit, KnownViewRecoversASnippetOfTheModel) {
  Rng rng(9);
  const PreparedSnippetPrior prep = prepareSnippetPrior(randomMixture(rng, 3));
  const PpcaComponent& c = prep.prior.components[2];
  const Eigen::VectorXd truth = c.mean + c.basis * Eigen::VectorXd::Constant(5, 15.0);
  SnippetCamera cam;
  cam.alphaDeg = 40.0;
  const Eigen::MatrixXd y = renderSnippet(truth, 1, cam);
  SnippetFitOptions o;
  o.alphaDeg = 40.0;
  o.scale = 1.0;
  const SnippetFit fit = fitSnippet(prep, y, o);
  EXPECT_EQ(fit.cluster, 2);
  EXPECT_LT(fit.reprojectionRms, 2.0);
  EXPECT_NEAR(fit.camera.alphaDeg, 40.0, 1e-12);
}

TEST(SnippetFit, BadInputIsRefused) {
  Rng rng(1);
  const PreparedSnippetPrior prep = prepareSnippetPrior(randomMixture(rng, 2));
  EXPECT_THROW(fitSnippet(prep, Eigen::MatrixXd::Zero(2, 30)), Error);
  Eigen::MatrixXd y = Eigen::MatrixXd::Constant(1, 30, NAN);
  y(0, 0) = y(0, 1) = 0.0;
  EXPECT_THROW(fitSnippet(prep, y), Error);  // one point seen
  SnippetFitOptions o;
  o.noiseSdMm = -1.0;
  EXPECT_THROW(fitSnippet(prep, Eigen::MatrixXd::Zero(1, 30), o), Error);
  SnippetPrior broken = prep.prior;
  broken.components[0].noiseVariance = 0.0;
  EXPECT_THROW(prepareSnippetPrior(broken), Error);
}

}  // namespace
}  // namespace ew
