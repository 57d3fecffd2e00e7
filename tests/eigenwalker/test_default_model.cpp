// The default model of real walkers (assets/models/real-walkers.ewm, compiled into
// ew_core): it loads and is sane, and it is not stale: rebuilt from ../shared/data the way
// assets/README.md says, it gives the same model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <thread>

#include "core/eigenwalker/default_model.h"
#include "core/experiments/model_build.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

constexpr const char* kRebuild =
    "rebuild it from the repository root with ../shared beside it:\n"
    "  build/bin/eigenwalker-cli build --data ../shared/data/walkers.csv --out "
    "assets/models/real-walkers.ewm\n"
    "(assets/README.md), then rebuild the programs";

TEST(DefaultRealModel, LoadsOnceAndIsTheModelOfThe24SharedWalkers) {
  const EigenwalkerModel& m = defaultRealModel();
  EXPECT_EQ(&m, &defaultRealModel());  // parsed once, the same object every time
  EXPECT_EQ(m.walkerCount(), 24);
  EXPECT_EQ(std::set<std::string>(m.subjects.begin(), m.subjects.end()).size(), 24u);
  EXPECT_EQ(m.mean.size(), 225);
  EXPECT_GE(m.componentCount(), 2);
  EXPECT_LT(m.componentCount(), m.walkerCount());
  EXPECT_GE(m.explainedVariance(), 0.95);  // built with METHOD §4's 95 % default
  EXPECT_TRUE(m.mean.allFinite() && m.eigenwalkers.allFinite());
  EXPECT_EQ(defaultRealModelName(), "24 real walkers (default)");
  // Stride frequencies of adults walking at their own pace: 0.6–1.4 Hz (slowest here 0.66).
  EXPECT_GT(m.omegasRadS.minCoeff(), 2 * M_PI * 0.6);
  EXPECT_LT(m.omegasRadS.maxCoeff(), 2 * M_PI * 1.4);
  // Every walker of the shared data walked overground: a speed each, of adults walking at
  // their own pace (0.7–1.6 m/s; the shared walkers' range is 0.73–1.55).
  ASSERT_EQ(m.speedsMps.size(), 24u);
  for (const auto& v : m.speedsMps) {
    ASSERT_TRUE(v.has_value());
    EXPECT_GT(*v, 0.7);
    EXPECT_LT(*v, 1.6);
  }
}

TEST(DefaultRealModel, StoresItsSigma2OptimumAndUsesIt) {
  const EigenwalkerModel& m = defaultRealModel();
  ASSERT_TRUE(m.sigma2Optimum.has_value());
  const Sigma2Optimum& s = *m.sigma2Optimum;
  EXPECT_NE(std::find(s.gridMm2.begin(), s.gridMm2.end(), s.sigma2Mm2), s.gridMm2.end());
  EXPECT_EQ(s.gridMm2, defaultBuildSigma2Plan().gridMm2);
  EXPECT_EQ(s.anglesDeg, defaultBuildSigma2Plan().anglesDeg);
  EXPECT_GT(s.meanAbsErrorMm2, 0.0);
  EXPECT_EQ(defaultSigma2Mm2(m), s.sigma2Mm2);
}

TEST(DefaultRealModel, RecordsNoPathOfTheMachineItWasBuiltOn) {
  for (const auto& line : defaultRealModel().provenance) {
    EXPECT_EQ(line.find(" /"), std::string::npos) << line;
    EXPECT_EQ(line.find("../"), std::string::npos) << line;
    EXPECT_NE(line.rfind("/", 0), 0u) << line;
  }
}

// Bit-exact in the build that wrote the asset; the tolerance (1e-9 of each array's largest
// magnitude) only absorbs last-digit differences another compiler or libm may give the
// trigonometry of the Fourier fits. A stale model differs by far more: one walker more or
// less, or any change to a loader or the fit, moves the mean by millimetres.
TEST(DefaultRealModel, IsNotStaleAgainstTheSharedData) {
  EW_REQUIRE_SHARED_DATA();
  ModelBuildOptions options;
  options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const ModelBuildResult rebuilt =
      buildModelFromData({test::sharedDataDir() / "walkers.csv"}, options);
  const EigenwalkerModel& shipped = defaultRealModel();
  const EigenwalkerModel& r = rebuilt.model;
  ASSERT_EQ(r.walkerIds, shipped.walkerIds) << "the default model is stale: " << kRebuild;
  ASSERT_EQ(r.subjects, shipped.subjects) << kRebuild;
  ASSERT_EQ(r.componentCount(), shipped.componentCount()) << kRebuild;
  ASSERT_EQ(r.spectrum.size(), shipped.spectrum.size()) << kRebuild;
  EXPECT_EQ(r.provenance, shipped.provenance) << kRebuild;
  const auto close = [](const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return (a - b).cwiseAbs().maxCoeff() <= 1e-9 * std::max(1.0, b.cwiseAbs().maxCoeff());
  };
  EXPECT_TRUE(close(r.mean, shipped.mean)) << "mean differs: " << kRebuild;
  EXPECT_TRUE(close(r.eigenwalkers, shipped.eigenwalkers)) << "eigenwalkers differ: " << kRebuild;
  EXPECT_TRUE(close(r.eigenvalues, shipped.eigenvalues)) << "eigenvalues differ: " << kRebuild;
  EXPECT_TRUE(close(r.spectrum, shipped.spectrum)) << "spectrum differs: " << kRebuild;
  EXPECT_TRUE(close(r.coefficients, shipped.coefficients)) << "coefficients differ: " << kRebuild;
  EXPECT_TRUE(close(r.omegasRadS, shipped.omegasRadS)) << "frequencies differ: " << kRebuild;
  ASSERT_EQ(r.speedsMps.size(), shipped.speedsMps.size()) << kRebuild;
  for (size_t k = 0; k < r.speedsMps.size(); ++k)
    EXPECT_NEAR(r.speedsMps[k].value_or(-1.0), shipped.speedsMps[k].value_or(-1.0), 1e-9) << "speeds differ: " << kRebuild;
  ASSERT_TRUE(r.sigma2Optimum && shipped.sigma2Optimum) << kRebuild;
  EXPECT_EQ(r.sigma2Optimum->sigma2Mm2, shipped.sigma2Optimum->sigma2Mm2) << kRebuild;
  EXPECT_NEAR(r.sigma2Optimum->meanAbsErrorMm2, shipped.sigma2Optimum->meanAbsErrorMm2,
              1e-9 * shipped.sigma2Optimum->meanAbsErrorMm2)
      << kRebuild;
  EXPECT_EQ(r.sigma2Optimum->criterion, shipped.sigma2Optimum->criterion) << kRebuild;
}

}  // namespace
}  // namespace ew
