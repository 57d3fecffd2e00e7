// The gait of a two-harmonic walker walking in place (core/gait/fourier_walker_gait.h): its
// stance feet slide faster than it walks, by kTwoHarmonicStanceSpeedRatio, measured here on
// the shared walkers against their progression.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>
#include <numeric>
#include <string>
#include <vector>

#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/gait/dataset.h"
#include "core/gait/fourier_walker_gait.h"
#include "core/gait/gait_events.h"
#include "core/gait/gait_measures.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

// One shared trial fitted with two harmonics, measured in place.
struct FittedTrial {
  std::string subject;
  double progressionMps = 0.0;      // the trial's own (WalkingTrial::speedMps)
  double strideLengthM = 0.0;       // the trial's, its footprints put down at that progression
  double stanceFeetMps = 0.0;       // the two-harmonic walker's stance feet, as they slide
  FourierWalkerGait walker;         // measured by measureFourierWalker (calibrated)
};

std::vector<FittedTrial> fittedSharedTrials() {
  const Dataset d = loadDataset({test::sharedDataDir() / "walkers.csv"});
  std::vector<FittedTrial> out;
  for (const auto& t : d.trials) {
    const WalkingTrial& trial = t.trial;
    const auto& frames = trial.joints.positionsMm;
    const double rate = trial.joints.rateHz;
    FourierFitOptions options;
    options.omegaHintRadS = 2.0 * std::numbers::pi * trial.cycles.strideHz;
    const FourierFit fit = fitFourier(frames, rate, options);
    const double strideHz = fit.omegaRadS / (2.0 * std::numbers::pi);
    FittedTrial f{t.info.subject, trial.speedMps, 0.0, 0.0,
                  measureFourierWalker(fit.w, strideHz, std::nullopt, t.info.file)};
    f.strideLengthM =
        measureGait(frames, rate, gaitEventsFromKinematics(frames, rate), trial.speedMps, t.info.file).strideLengthM;
    f.stanceFeetMps = f.walker.measures ? f.walker.measures->stanceFootSpeedMps : NAN;
    out.push_back(std::move(f));
  }
  return out;
}

double meanRatio(const std::vector<FittedTrial>& trials, const std::string& leftOut = "") {
  std::vector<double> r;
  for (const auto& t : trials)
    if (t.subject != leftOut && std::isfinite(t.stanceFeetMps)) r.push_back(t.stanceFeetMps / t.progressionMps);
  return std::accumulate(r.begin(), r.end(), 0.0) / static_cast<double>(r.size());
}

// The ratio is the one these trials measure; leaving each subject out, the others' ratio puts
// that subject's speed within 10 % of its progression (3.3 SDs of the ratio's spread, 0.030: a
// walker's own stance pattern, which no one ratio removes; measured: at most 9.0 %, SM2015015).
TEST(FourierWalkerGaitOnSharedWalkers, TheStanceFeetRatioHoldsForASubjectItWasNotMeasuredOn) {
  EW_REQUIRE_SHARED_DATA();
  const std::vector<FittedTrial> trials = fittedSharedTrials();
  ASSERT_EQ(trials.size(), 30u);
  for (const auto& t : trials) ASSERT_TRUE(t.walker.measures) << t.subject << ": " << t.walker.error;
  EXPECT_NEAR(meanRatio(trials), kTwoHarmonicStanceSpeedRatio, 0.0005);
  for (const auto& t : trials) {
    const double speed = t.stanceFeetMps / meanRatio(trials, t.subject);
    std::cout << t.subject << ": " << t.progressionMps << " m/s, its two-harmonic walker's stance feet "
              << t.stanceFeetMps << ", corrected by the others' ratio " << speed << "\n";
    EXPECT_LE(std::abs(speed / t.progressionMps - 1.0), 0.10) << t.subject;
  }
}

// Corrected, the walker's strides are on average the trial's own (measured −1.0 cm over the 30
// trials; +7.3 cm as the feet slide): bias within 2 cm. The spread is the walkers' own, SD 3.6 %.
TEST(FourierWalkerGaitOnSharedWalkers, StridesAreTheTrialsOwnOnAverage) {
  EW_REQUIRE_SHARED_DATA();
  std::vector<double> calibrated, asTheFeetSlide;
  for (const auto& t : fittedSharedTrials()) {
    ASSERT_TRUE(t.walker.measures) << t.subject;
    const GaitMeasures& g = *t.walker.measures;
    EXPECT_EQ(g.speedSource, "stance feet of a two-harmonic walker");
    EXPECT_NEAR(g.speedMps, g.stanceFootSpeedMps / kTwoHarmonicStanceSpeedRatio, 1e-9);
    calibrated.push_back(g.strideLengthM - t.strideLengthM);
    const GaitMeasures uncorrected = measureGait(t.walker.framesMm, kWalkerGaitRateHz,
                                                 gaitEventsFromKinematics(t.walker.framesMm, kWalkerGaitRateHz),
                                                 std::nullopt, t.subject);
    asTheFeetSlide.push_back(uncorrected.strideLengthM - t.strideLengthM);
  }
  const auto mean = [](const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  };
  std::cout << "stride length − the trial's: " << mean(asTheFeetSlide) << " m as the feet slide, "
            << mean(calibrated) << " m corrected\n";
  EXPECT_GT(mean(asTheFeetSlide), 0.05);
  EXPECT_LE(std::abs(mean(calibrated)), 0.02);
}

// A known progression (motion capture) is used as it is: no correction.
TEST(FourierWalkerGait, AGivenSpeedIsKept) {
  EW_REQUIRE_SHARED_DATA();
  const Dataset d = loadDataset({test::sharedDataDir() / "walkers.csv"});
  const WalkingTrial& trial = d.trials.front().trial;
  const FourierFit fit = fitFourier(trial.joints.positionsMm, trial.joints.rateHz);
  const FourierWalkerGait g =
      measureFourierWalker(fit.w, fit.omegaRadS / (2.0 * std::numbers::pi), trial.speedMps, "given");
  ASSERT_TRUE(g.measures) << g.error;
  EXPECT_EQ(g.measures->speedSource, "progression");
  EXPECT_DOUBLE_EQ(g.measures->speedMps, trial.speedMps);
}

}  // namespace
}  // namespace ew

namespace ew {
namespace {

// Events of a periodic walk (gaitEventsOfPeriodicWalk): on walkers of the default model seen
// for a stride and a third at 30 fps, one strike and one foot off per stride, exactly a
// stride apart, at the phase where the kinematics' peaks fall on eight strides at 100 Hz
// (within 10 ms: the kinematic peaks' own smoothing and sampling); their cadence is the
// walker's 120 f on a stride and a half.
TEST(PeriodicWalkEvents, OneOfEachPerStrideWhereTheKinematicsPutThem) {
  const EigenwalkerModel& model = defaultRealModel();
  for (int k = 0; k < 4; ++k) {
    Eigen::VectorXd w = model.mean;
    if (k > 0) w += model.eigenwalkers.col(k - 1) * std::sqrt(model.eigenvalues(k - 1));
    const double f = model.omegasRadS.mean() / (2.0 * std::numbers::pi) * (0.9 + 0.1 * k);
    const auto framesAt = [&](double rate, double seconds) {
      const int n = static_cast<int>(std::floor(seconds * rate)) + 1;
      Eigen::VectorXd t(n);
      for (int i = 0; i < n; ++i) t(i) = i / rate;
      return synthesizeFrames(w, 2.0 * std::numbers::pi * f, 0.7, t);
    };
    const Eigen::MatrixXd shortClip = framesAt(30.0, 1.35 / f), longWalk = framesAt(100.0, 8.0 / f);
    const GaitEventSet periodic = gaitEventsOfPeriodicWalk(shortClip, 30.0, f);
    const GaitEventSet kinematic = gaitEventsFromKinematics(longWalk, 100.0);
    const auto phaseOf = [&](double t) { return std::fmod(t * f, 1.0); };
    const auto cyclicGapS = [&](double a, double b) {
      const double d = std::abs(phaseOf(a) - phaseOf(b));
      return std::min(d, 1.0 - d) / f;
    };
    for (Side side : {Side::Right, Side::Left}) {
      const FootEvents& p = periodic.of(side);
      const FootEvents& q = kinematic.of(side);
      ASSERT_GE(p.strikesS.size(), 1u);
      ASSERT_LE(p.strikesS.size(), 2u) << "a stride and a third holds one or two strikes of a foot";
      ASSERT_GE(p.offsS.size(), 1u);
      for (std::size_t i = 1; i < p.strikesS.size(); ++i) EXPECT_NEAR(p.strikesS[i] - p.strikesS[i - 1], 1.0 / f, 1e-9);
      ASSERT_FALSE(q.strikesS.empty());
      EXPECT_LT(cyclicGapS(p.strikesS.front(), q.strikesS[q.strikesS.size() / 2]), 0.010) << "walker " << k;
      EXPECT_LT(cyclicGapS(p.offsS.front(), q.offsS[q.offsS.size() / 2]), 0.010) << "walker " << k;
    }
    // A stride and a half: one foot strikes twice (the feet strike half a stride apart).
    const Eigen::MatrixXd strideAndAHalf = framesAt(30.0, 1.5 / f);
    const GaitMeasures g =
        measureGait(strideAndAHalf, 30.0, gaitEventsOfPeriodicWalk(strideAndAHalf, 30.0, f), 1.3, "periodic");
    EXPECT_NEAR(g.cadenceSpm, 120.0 * f, 1e-6);
    EXPECT_TRUE(gaitEventsOfPeriodicWalk(shortClip, 30.0, 9.0).right.strikesS.empty()) << "a stride past 2.5 Hz";
  }
}

}  // namespace
}  // namespace ew
