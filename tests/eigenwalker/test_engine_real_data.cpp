// The engine on the shared real walkers (METHOD §8 experiments 3–4, reduced): leave-one-
// subject-out reconstruction at 0°, 30°, 90° (MAP vs LSQ) and unknown-view recovery.
#include <gtest/gtest.h>

#include <cstdio>
#include <map>

#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/eigenwalker/walker_set.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

constexpr double kSigma2Mm2 = 200.0;

const std::vector<Walker>& realWalkers() {
  static const std::vector<Walker> walkers = [] {
    const Dataset dataset = loadDataset({test::sharedDataDir() / "walkers.csv"});
    std::vector<std::string> warnings;
    auto w = makeWalkers(dataset, &warnings);
    for (const auto& line : warnings) std::printf("warning: %s\n", line.c_str());
    return w;
  }();
  return walkers;
}

std::vector<std::string> distinctSubjects(const std::vector<Walker>& walkers) {
  std::vector<std::string> out;
  for (const auto& w : walkers) {
    if (std::find(out.begin(), out.end(), w.subject) == out.end()) out.push_back(w.subject);
  }
  return out;
}

TEST(EngineRealData, WalkersFromTheManifest) {
  EW_REQUIRE_SHARED_DATA();
  const auto& walkers = realWalkers();
  EXPECT_GE(walkers.size(), 20u);
  double h1 = 0, h2 = 0;
  for (const auto& w : walkers) {
    EXPECT_EQ(w.id, w.subject + "/" + w.condition);
    EXPECT_EQ(w.fit.w.size(), kFourierDims3);
    EXPECT_GT(w.fit.cycles, 0.99);
    h1 += w.fit.h1Share / static_cast<double>(walkers.size());
    h2 += w.fit.h2Share / static_cast<double>(walkers.size());
  }
  std::printf("walkers %zu, mean harmonic shares h1 %.3f h2 %.3f\n", walkers.size(), h1, h2);
  EXPECT_GT(h1, 0.7);  // the paper: 91.9 % and 6.0 %
  EXPECT_GT(h1 + h2, 0.85);
  const auto model = buildModel(walkers);
  std::printf("full model: R %d, N %d (%.1f %% of the variance)\n", model.walkerCount(),
              model.componentCount(), 100 * model.explainedVariance());
}

TEST(EngineRealData, LeaveOneSubjectOutMapBeatsLsqAndFindsTheView) {
  EW_REQUIRE_SHARED_DATA();
  const auto& walkers = realWalkers();
  ASSERT_GE(walkers.size(), 10u);
  const std::vector<double> knownAngles = {0.0, 30.0, 90.0};
  const std::vector<double> searchAngles = {-60.0, -30.0, 0.0, 30.0, 60.0};
  std::map<double, double> lsqEa, mapEa, lsqEr, mapEr;
  std::map<double, int> hitsLsq, hitsMap;
  std::map<double, double> errLsq, errMap;
  int count = 0;
  for (const auto& subject : distinctSubjects(walkers)) {
    const ModelGram gram = precomputeModelGram(buildModelWithoutSubject(walkers, subject));
    for (const auto& w : walkers) {
      if (w.subject != subject) continue;
      ++count;
      for (double a : knownAngles) {
        const Eigen::VectorXd obs = projectToView(w.fit.w, a);
        const auto lsq = depthErrors(w.fit.w, reconstructLsq(gram, obs, a).w, a);
        const auto map = depthErrors(w.fit.w, reconstructMap(gram, obs, a, kSigma2Mm2).w, a);
        lsqEa[a] += lsq.absMean; mapEa[a] += map.absMean;
        lsqEr[a] += lsq.relMean; mapEr[a] += map.relMean;
      }
      for (double a : searchAngles) {
        const Eigen::VectorXd obs = projectToView(w.fit.w, a);
        const double eL = viewAngleErrorDeg(searchViewAngle(gram, obs).best.alphaDeg, a);
        const double eM = viewAngleErrorDeg(
            searchViewAngle(gram, obs, {Estimator::Map, kSigma2Mm2}).best.alphaDeg, a);
        hitsLsq[a] += eL <= 10.0;
        hitsMap[a] += eM <= 10.0;
        errLsq[a] += eL;
        errMap[a] += eM;
      }
    }
  }
  for (double a : knownAngles) {
    std::printf("alpha %5.1f: E_a LSQ %8.1f mm2, MAP(s2=%g) %8.1f mm2 (%.0f %% lower); "
                "E_r LSQ %.3f MAP %.3f\n", a, lsqEa[a] / count, kSigma2Mm2, mapEa[a] / count,
                100 * (1 - mapEa[a] / lsqEa[a]), lsqEr[a] / count, mapEr[a] / count);
    EXPECT_LT(mapEa[a], lsqEa[a]) << "alpha " << a;
  }
  for (double a : searchAngles) {
    std::printf("unknown view %5.1f: within 10 deg LSQ %d/%d MAP %d/%d; mean |error| LSQ %.1f MAP %.1f deg\n",
                a, hitsLsq[a], count, hitsMap[a], count, errLsq[a] / count, errMap[a] / count);
    EXPECT_GT(2 * hitsLsq[a], count) << "alpha " << a;  // most walkers
  }
}

}  // namespace
}  // namespace ew
