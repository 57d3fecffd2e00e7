// Gait events and measures (core/gait/gait_events.h, gait_measures.h): synthetic walkers
// against the parameters that generated them, hand-placed events against hand-computed
// measures, bad input, and the shared walkers' kinematic events against their C3D's own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numbers>
#include <functional>
#include <numeric>

#include "core/common/errors.h"
#include "core/gait/dataset.h"
#include "core/gait/gait_measures.h"
#include "core/gait/joint_angles.h"
#include "core/gait/prepare.h"
#include "core/synth/population.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

std::vector<SynthWalker> walkers(int count) {
  PopulationOptions o;
  o.count = count;
  return generatePopulation(o);
}

template <class F>
std::string errorOf(F&& f, ErrorKind kind) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error thrown";
  return "";
}

// Where each foot stands on the floor from its strike to its foot off (the walker advances
// 1.3 m a stride, 0.65 m a step, feet 120 mm apart), in the walker's frame: the pelvis at the
// origin, so a planted foot slides back at 1.3 m/s; swing is linear on the floor.
struct Stance {
  double strikeS, offS, forwardMm;
};
constexpr double kSpeedMps = 1.3;
const std::vector<Stance> kRightStances = {
    {-0.9, -0.28, -1300}, {0.1, 0.72, 0}, {1.1, 1.74, 1300}, {2.1, 2.72, 2600}, {3.1, 3.72, 3900}};
const std::vector<Stance> kLeftStances = {
    {-0.4, 0.2, -650}, {0.6, 1.22, 650}, {1.6, 2.22, 1950}, {2.6, 3.2, 3250}};

double floorPosition(const std::vector<Stance>& stances, double t) {
  for (size_t k = 0; k < stances.size(); ++k) {
    if (t >= stances[k].strikeS && t <= stances[k].offS) return stances[k].forwardMm;
    if (k + 1 < stances.size() && t > stances[k].offS && t < stances[k + 1].strikeS) {
      const double w = (t - stances[k].offS) / (stances[k + 1].strikeS - stances[k].offS);
      return (1 - w) * stances[k].forwardMm + w * stances[k + 1].forwardMm;
    }
  }
  return NAN;
}

Eigen::MatrixXd walkerOnStances(int frames) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(frames, kDims3);
  for (int i = 0; i < frames; ++i) {
    const double t = i / 100.0, back = kSpeedMps * 1000.0 * t;
    m.block<1, 3>(i, 3 * index(Joint::Pelvis)) << 0, 0, 950;
    m.block<1, 3>(i, 3 * index(Joint::RAnkle)) << 60, floorPosition(kRightStances, t) - back, 80;
    m.block<1, 3>(i, 3 * index(Joint::LAnkle)) << -60, floorPosition(kLeftStances, t) - back, 80;
  }
  return m;
}

GaitEventSet handEvents() {
  GaitEventSet e;
  e.method = "file events";
  e.right = {{0.10, 1.10, 2.10}, {0.72, 1.74}};
  e.left = {{0.60, 1.60}, {0.20, 1.22}};
  return e;
}

TEST(GaitMeasures, HandPlacedEventsGiveTheMeasuresComputedByHand) {
  const GaitMeasures g = measureGait(walkerOnStances(250), 100.0, handEvents(), kSpeedMps, "hand");
  ASSERT_EQ(g.strides.size(), 3u);  // right 0.1→1.1, left 0.6→1.6, right 1.1→2.1
  EXPECT_NEAR(g.strideTimeS, 1.0, 1e-12);
  EXPECT_NEAR(g.cadenceSpm, 120.0, 1e-9);
  // With the off-to-off intervals too: right 0.72 → 1.74, left 0.20 → 1.22.
  EXPECT_NEAR(g.strideTimeAllEventsS, (3 * 1.0 + 2 * 1.02) / 5, 1e-12);
  EXPECT_NEAR(g.stanceRightPct, 0.5 * (62.0 + 64.0), 1e-9);
  EXPECT_NEAR(g.stanceLeftPct, 62.0, 1e-9);  // 0.6 → off 1.22 → 1.6
  EXPECT_NEAR(g.doubleSupportPct, 63.0 + 62.0 - 100.0, 1e-9);
  EXPECT_NEAR(g.swingPct, 100.0 - 62.5, 1e-9);
  // Footprint to footprint: every step 0.65 m, 120 mm wide.
  EXPECT_NEAR(g.stepLengthRightM, 0.65, 1e-9);
  EXPECT_NEAR(g.stepLengthLeftM, 0.65, 1e-9);
  EXPECT_NEAR(g.strideLengthM, 1.3, 1e-9);
  EXPECT_NEAR(g.stepWidthM, 0.12, 1e-12);
  EXPECT_NEAR(g.stanceFootSpeedMps, kSpeedMps, 1e-9);
  EXPECT_EQ(g.speedSource, "progression");  // given: it is what is reported
  EXPECT_DOUBLE_EQ(g.speedMps, kSpeedMps);
  // A progression given wrong puts the footprints wrong by its error × the time between them.
  const GaitMeasures slow = measureGait(walkerOnStances(250), 100.0, handEvents(), 1.2, "hand");
  EXPECT_NEAR(slow.strideLengthM, 1.3 - 0.1 * 1.0, 1e-3);
}

TEST(GaitMeasures, WithoutProgressionTheSpeedComesFromTheStanceFeet) {
  const GaitMeasures g =
      measureGait(walkerOnStances(250), 100.0, handEvents(), std::nullopt, "hand");
  EXPECT_EQ(g.speedSource, "stance feet");
  EXPECT_NEAR(g.speedMps, kSpeedMps, 1e-9);
}

TEST(GaitMeasures, AProgressionFarBelowTheFeetsIsWalkingInPlace) {
  // A treadmill, or frames whose progression was removed before: the feet tell the speed.
  const GaitMeasures g = measureGait(walkerOnStances(250), 100.0, handEvents(), 0.003, "in place");
  EXPECT_EQ(g.speedSource, "stance feet");
  EXPECT_NEAR(g.speedMps, kSpeedMps, 1e-9);
  EXPECT_NEAR(g.strideLengthM, 1.3, 1e-9);
  ASSERT_FALSE(g.notes.empty());
  EXPECT_NE(g.notes.front().find("walking in place"), std::string::npos);
}

TEST(GaitMeasures, AStrideWithoutItsFootOffCountsForTimeButNotStance) {
  GaitEventSet e = handEvents();
  e.left.offsS.clear();
  const GaitMeasures g = measureGait(walkerOnStances(250), 100.0, e, std::nullopt, "hand");
  EXPECT_NEAR(g.strideTimeS, 1.0, 1e-12);
  EXPECT_TRUE(std::isnan(g.stanceLeftPct));
  EXPECT_NEAR(g.stancePct, 63.0, 1e-9);
  ASSERT_FALSE(g.notes.empty());
  EXPECT_NE(g.notes.front().find("symmetric"), std::string::npos);
}

TEST(GaitMeasures, BadInputIsAnErrorNamingTheTrial) {
  EXPECT_NE(
      errorOf([] { measureGait(Eigen::MatrixXd::Zero(10, 44), 100, handEvents(), {}, "t.c3d"); },
              ErrorKind::BadArgument)
          .find("t.c3d"),
      std::string::npos);
  EXPECT_NE(errorOf([] { measureGait(walkerOnStances(250), 0.0, handEvents(), {}, "t.c3d"); },
                    ErrorKind::BadArgument)
                .find("rate"),
            std::string::npos);
  Eigen::MatrixXd gap = walkerOnStances(250);
  gap(40, 3 * index(Joint::LAnkle) + 1) = NAN;
  EXPECT_NE(errorOf([&] { measureGait(gap, 100, handEvents(), {}, "t.c3d"); }, ErrorKind::BadData)
                .find(std::string(jointName(Joint::LAnkle))),
            std::string::npos);
  GaitEventSet one;
  one.method = "kinematics";
  one.right.strikesS = {0.3};
  one.left.strikesS = {0.8};
  const std::string msg = errorOf([&] { measureGait(walkerOnStances(250), 100, one, {}, "t.c3d"); },
                                  ErrorKind::BadData);
  EXPECT_NE(msg.find("t.c3d"), std::string::npos);
  EXPECT_NE(msg.find("no complete stride"), std::string::npos);
}

TEST(GaitMeasures, StrikesTooFarApartForWalkingMakeNoStride) {
  GaitEventSet e;
  e.right.strikesS = {0.0, 4.0};  // 0.25 Hz: below walking's stride frequencies
  EXPECT_TRUE(
      errorOf([&] { measureGait(walkerOnStances(500), 100, e, {}, "slow"); }, ErrorKind::BadData)
          .size() > 0);
}

TEST(GaitEvents, FileEventsAreSortedPerSideAndKeptInsideTheTrial) {
  std::vector<GaitEvent> file = {{Side::Left, GaitEventType::FootStrike, 1.5, "Foot Strike2"},
                                 {Side::Left, GaitEventType::FootStrike, 0.5, "Foot Strike1"},
                                 {Side::Right, GaitEventType::FootOff, 0.7, "Foot Off"},
                                 {Side::Right, GaitEventType::FootStrike, 9.0, "late"},
                                 {Side::Right, GaitEventType::Other, 0.2, "Event"}};
  const GaitEventSet e = gaitEventsFromFile(file, 2.0);
  EXPECT_EQ(e.method, "file events");
  EXPECT_EQ(e.left.strikesS, (std::vector<double>{0.5, 1.5}));
  EXPECT_TRUE(e.right.strikesS.empty());
  EXPECT_EQ(e.right.offsS, (std::vector<double>{0.7}));
}

TEST(GaitEvents, ExtremesAreLocatedBetweenFrames) {
  Eigen::VectorXd s(5);
  const double peak = 2.3;  // a parabola's top between rows 2 and 3
  for (int i = 0; i < 5; ++i) s[i] = -(i - peak) * (i - peak);
  EXPECT_NEAR(refinedExtreme(s, 2), peak, 1e-12);
  EXPECT_EQ(refinedExtreme(s, 0), 0.0);
}

// Synthetic walkers: stride time, stride length and speed as generated; step width as the
// feet were placed on the floor (the trial before its progression was removed).
TEST(GaitMeasures, SyntheticWalkersMeasureAsTheyWereGenerated) {
  for (const auto& w : walkers(8)) {
    const WalkingTrial t = prepareWalkingTrial(w.trial);
    const auto& m = t.joints.positionsMm;
    const double rate = t.joints.rateHz;
    const GaitEventSet events = gaitEventsFromKinematics(m, rate);
    const GaitMeasures g = measureGait(m, rate, events, t.speedMps, w.id);
    const GaitMeasures feet = measureGait(m, rate, events, std::nullopt, w.id);
    const auto& floor = w.trial.positionsMm;  // overground: the feet stand still in these axes
    const GaitMeasures onFloor =
        measureGait(floor, rate, gaitEventsFromKinematics(floor, rate), std::nullopt, w.id);
    const double cadence = w.attributes.at("cadence_spm"),
                 stride = w.attributes.at("stride_length_m");
    const double speed = w.attributes.at("speed_mps");
    std::cout << w.id << ": cadence " << g.cadenceSpm << " (" << cadence << "), stride "
              << g.strideLengthM << " m / from the feet " << feet.strideLengthM << " (" << stride
              << "), width " << g.stepWidthM * 1000 << " mm / on the floor "
              << onFloor.stepWidthM * 1000 << ", speed from the feet " << feet.speedMps << " ("
              << speed << "), stance " << g.stancePct << " %, strides " << g.strides.size() << "\n";
    EXPECT_NEAR(g.cadenceSpm, cadence, 0.02 * cadence) << w.id;
    EXPECT_NEAR(120.0 / g.strideTimeAllEventsS, cadence, 0.02 * cadence) << w.id;
    EXPECT_NEAR(g.strideLengthM, stride, 0.01 * stride) << w.id;
    EXPECT_NEAR(g.stepWidthM, onFloor.stepWidthM, 0.005) << w.id;
    // Without the progression: the stance feet's slide, measured up to 7 % slow here.
    EXPECT_EQ(feet.speedSource, "stance feet");
    EXPECT_NEAR(feet.speedMps, speed, 0.08 * speed) << w.id;
    EXPECT_NEAR(feet.strideLengthM, stride, 0.08 * stride) << w.id;
    // Walking adults' stance: the shared walkers' C3D events give 61–69 %, and these walkers
    // are drawn from a model of such walkers (measured here: 57–68 %).
    EXPECT_GT(g.stancePct, 55.0) << w.id;
    EXPECT_LT(g.stancePct, 70.0) << w.id;
    EXPECT_GE(g.strides.size(), 4u) << w.id;
  }
}

TEST(GaitCurves, EachStrideIsResampledFromStrikeToStrike) {
  const double rate = 100.0;
  const int frames = 300;
  const std::vector<std::string> names = {"knee_angle_r", "other", "knee_angle_l"};
  Eigen::MatrixXd angles(frames, 3);
  for (int i = 0; i < frames; ++i) {
    const double t = i / rate;
    angles(i, 0) =
        30.0 + 25.0 * std::sin(2.0 * std::numbers::pi * (t - 0.1));  // period 1 s from 0.1 s
    angles(i, 1) = 0.0;
    angles(i, 2) = NAN;  // never measured: no curve
  }
  const GaitMeasures g = measureGait(walkerOnStances(frames), rate, handEvents(), {}, "curves");
  const auto curves = flexionCycleCurves(angles, names, rate, g, 11);
  ASSERT_EQ(curves.size(), 1u);
  EXPECT_EQ(curves[0].name, "knee_angle_r");
  EXPECT_EQ(curves[0].strides, 2);
  for (int k = 0; k < 11; ++k) {
    EXPECT_NEAR(curves[0].meanDeg[k], 30.0 + 25.0 * std::sin(2.0 * std::numbers::pi * k / 10.0),
                0.05);
    EXPECT_NEAR(curves[0].sdDeg[k], 0.0, 0.05);
  }
}

// Issue 17's bar: on the Schreiber-Moissenet walkers, events from the kinematics give cadence
// and stride time within 2 % and stance within 3 points of the C3D's EVENT group. Met on
// average (measured: stride time +1.1 %, stance -2.1 points); not in every trial, where a
// trial holds one stride per foot and each event scatters ±15 ms about the C3D's (the
// per-trial counts are in docs/RESULTS.md, "Gait measures"). The per-trial guard is the
// worst measured plus a frame.
// The Schreiber-Moissenet walkers, whole trials (each about 1.5 strides, with its C3D events).
struct SharedC3dTrial {
  std::string subject, path;
  Eigen::MatrixXd framesMm;
  double rateHz = 0, speedMps = 0;
  GaitEventSet file;
  Eigen::MatrixXd feetMm;  // heel and toe (JointTrial::feetMm), canonical frame
};

std::vector<SharedC3dTrial> sharedC3dTrials() {
  std::vector<std::string> warnings;
  PrepareOptions whole;
  whole.cropToSteadyWindow = false;
  std::vector<SharedC3dTrial> trials;
  for (const auto& f : collectTrialFiles({test::sharedDataDir() / "walkers.csv"}, warnings)) {
    if (f.path.extension() != ".c3d") continue;
    const WalkingTrial t = loadWalkingTrial(f.path, {}, whole);
    const double duration = static_cast<double>(t.joints.positionsMm.rows() - 1) / t.joints.rateHz;
    trials.push_back({f.info.subject, f.path.string(), t.joints.positionsMm, t.joints.rateHz,
                      t.speedMps, gaitEventsFromFile(t.joints.events, duration), t.joints.feetMm});
  }
  return trials;
}

// Kinematic − file stance (points) of one trial, with the given foot-off lag (of the stride).
double stanceDifference(const SharedC3dTrial& t, double footOffLag) {
  const GaitMeasures a = measureGait(t.framesMm, t.rateHz, t.file, t.speedMps, t.path);
  const GaitMeasures b =
      measureGait(t.framesMm, t.rateHz, gaitEventsFromKinematics(t.framesMm, t.rateHz, footOffLag),
                  t.speedMps, t.path);
  return b.stancePct - a.stancePct;
}

// Each kinematic event's time less the file's nearest event of the same kind and foot (within
// 0.15 s: the same event), as a fraction of the stride, appended to `out`.
void eventErrors(const std::vector<double>& kinematic, const std::vector<double>& file,
                 double strideS, std::vector<double>& out) {
  for (double f : file) {
    double nearest = std::numeric_limits<double>::infinity();
    for (double k : kinematic)
      if (std::abs(k - f) < std::abs(nearest)) nearest = k - f;
    if (std::abs(nearest) < 0.15) out.push_back(nearest / strideS);
  }
}

// How much earlier Zeni's foot off from the ankle comes than his strike, against the files'
// events, over the given trials (a fraction of the stride).
double footOffLagOf(const std::vector<const SharedC3dTrial*>& trials) {
  std::vector<double> strikes, offs;
  for (const auto* t : trials) {
    const GaitEventSet zeni = gaitEventsFromKinematics(t->framesMm, t->rateHz, 0.0);
    const double strideS = medianStrideS(zeni);
    for (Side side : {Side::Right, Side::Left}) {
      eventErrors(zeni.of(side).strikesS, t->file.of(side).strikesS, strideS, strikes);
      eventErrors(zeni.of(side).offsS, t->file.of(side).offsS, strideS, offs);
    }
  }
  const auto mean = [](const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  };
  return mean(strikes) - mean(offs);
}

TEST(GaitMeasuresOnSharedWalkers, KinematicEventsAgreeWithTheC3dEvents) {
  EW_REQUIRE_SHARED_DATA();
  std::vector<double> strideDiffs, cadenceDiffs, stanceDiffs, allEventDiffs;
  for (const auto& t : sharedC3dTrials()) {
    const GaitMeasures a = measureGait(t.framesMm, t.rateHz, t.file, t.speedMps, t.path);
    const GaitMeasures b = measureGait(
        t.framesMm, t.rateHz, gaitEventsFromKinematics(t.framesMm, t.rateHz), t.speedMps, t.path);
    strideDiffs.push_back(100.0 * (b.strideTimeS - a.strideTimeS) / a.strideTimeS);
    cadenceDiffs.push_back(100.0 * (b.cadenceSpm - a.cadenceSpm) / a.cadenceSpm);
    stanceDiffs.push_back(b.stancePct - a.stancePct);
    allEventDiffs.push_back(100.0 * (b.strideTimeAllEventsS - a.strideTimeAllEventsS) / a.strideTimeAllEventsS);
    std::cout << t.subject << ": stride " << a.strideTimeS << " / " << b.strideTimeS << " s ("
              << strideDiffs.back() << " %), stance " << a.stancePct << " / " << b.stancePct
              << " % (" << stanceDiffs.back() << ")\n";
    EXPECT_LE(std::abs(strideDiffs.back()), 3.5) << t.path;
    EXPECT_LE(std::abs(stanceDiffs.back()), 3.0) << t.path;  // issue 17's bar, every trial
  }
  ASSERT_EQ(strideDiffs.size(), 18u);
  const auto mean = [](const std::vector<double>& v) {
    return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  };
  EXPECT_LE(std::abs(mean(strideDiffs)), 2.0);
  EXPECT_LE(std::abs(mean(cadenceDiffs)), 2.0);
  EXPECT_LE(std::abs(mean(stanceDiffs)), 1.0);
  const auto within = [](const std::vector<double>& v, double bar) {
    return std::count_if(v.begin(), v.end(), [&](double d) { return std::abs(d) <= bar; });
  };
  std::cout << "within the bar: stride time " << within(strideDiffs, 2.0) << ", cadence "
            << within(cadenceDiffs, 2.0) << ", stance " << within(stanceDiffs, 3.0) << " of 18\n";
  // A single stride per foot: each strike scatters ±15 ms, ±2 % of the stride (docs/GAIT.md).
  EXPECT_GE(within(strideDiffs, 2.0), 14);
  EXPECT_GE(within(cadenceDiffs, 2.0), 14);
  // The cycle's period from every event, the file's and the kinematics' alike: twice the
  // intervals, and the kinematic events keep the file's period (measured: 17 of 18 within 2 %,
  // the 18th at 2.02 %; mean +0.45 %).
  std::cout << "from every event: " << within(allEventDiffs, 2.0) << " of 18 within 2 %, mean "
            << mean(allEventDiffs) << " %\n";
  EXPECT_GE(within(allEventDiffs, 2.0), 17);
  EXPECT_EQ(within(allEventDiffs, 2.1), 18);
  EXPECT_LE(std::abs(mean(allEventDiffs)), 1.0);
}

// kAnkleFootOffLagOfStride is the lag these trials measure; leaving each trial out of the
// measuring, the lag of the other 17 still puts that trial's stance within 3 points of its C3D's.
TEST(GaitMeasuresOnSharedWalkers, TheFootOffLagHoldsForATrialItWasNotMeasuredOn) {
  EW_REQUIRE_SHARED_DATA();
  const std::vector<SharedC3dTrial> trials = sharedC3dTrials();
  ASSERT_EQ(trials.size(), 18u);
  std::vector<const SharedC3dTrial*> all;
  for (const auto& t : trials) all.push_back(&t);
  EXPECT_NEAR(footOffLagOf(all), kAnkleFootOffLagOfStride, 0.0005);
  for (const auto& t : trials) {
    std::vector<const SharedC3dTrial*> others;
    for (const auto* o : all)
      if (o != &t) others.push_back(o);
    const double lag = footOffLagOf(others);
    const double zeni = stanceDifference(t, 0.0), heldOut = stanceDifference(t, lag);
    std::cout << t.subject << ": lag of the others " << lag * 100
              << " % of the stride; stance − C3D's " << zeni << " → " << heldOut << " points\n";
    EXPECT_LE(std::abs(heldOut), 3.0) << t.path;
  }
}

// [SECTION] Events from the feet (the C3Ds' heel and toe markers, FCC and FM2)

double meanOf(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

double sdOf(const std::vector<double>& v) {
  const double m = meanOf(v);
  double sum = 0.0;
  for (double x : v) sum += (x - m) * (x - m);
  return std::sqrt(sum / (static_cast<double>(v.size()) - 1.0));
}

// Each event's lead on the file's (ms): strikes and offs of both feet over the given trials.
struct EventLeads {
  std::vector<double> strikesMs, offsMs;
};

EventLeads leadsOf(const std::vector<const SharedC3dTrial*>& trials,
                   const std::function<GaitEventSet(const SharedC3dTrial&)>& events, bool asFractionOfStride = false) {
  EventLeads out;
  for (const auto* t : trials) {
    const GaitEventSet e = events(*t);
    const double scale = asFractionOfStride ? medianStrideS(e) : 1e-3;
    for (Side side : {Side::Right, Side::Left}) {
      eventErrors(e.of(side).strikesS, t->file.of(side).strikesS, scale, out.strikesMs);
      eventErrors(e.of(side).offsS, t->file.of(side).offsS, scale, out.offsMs);
    }
  }
  return out;
}

std::vector<const SharedC3dTrial*> pointersTo(const std::vector<SharedC3dTrial>& trials) {
  std::vector<const SharedC3dTrial*> out;
  for (const auto& t : trials) out.push_back(&t);
  return out;
}

// The heel's foremost point and the toe's rearmost against the file's strikes and offs (18
// trials, one stride per foot), beside the ankle's: every event closer, the stride times and the
// stance as close. Measured (docs/GAIT.md, "Events from the feet"): strikes −12.2 ± 13.5 ms (the
// ankle −30.9 ± 14.7), offs −12.0 ± 11.6 ms (the ankle, with its lag, −31.5 ± 16.7).
TEST(FeetOnSharedWalkers, EventsFromTheFeetAgreeWithTheC3dEvents) {
  EW_REQUIRE_SHARED_DATA();
  const std::vector<SharedC3dTrial> trials = sharedC3dTrials();
  ASSERT_EQ(trials.size(), 18u);
  const auto feet = [](const SharedC3dTrial& t) { return gaitEventsFromFeet(t.framesMm, t.feetMm, t.rateHz); };
  const auto ankle = [](const SharedC3dTrial& t) { return gaitEventsFromKinematics(t.framesMm, t.rateHz); };
  std::vector<double> strideDiffs, stanceDiffs;
  for (const auto& t : trials) {
    ASSERT_EQ(t.feetMm.cols(), kFootDims3) << t.path;
    ASSERT_EQ(feet(t).method, "kinematics (heel and toe)") << t.path;
    const GaitMeasures a = measureGait(t.framesMm, t.rateHz, t.file, t.speedMps, t.path);
    const GaitMeasures b = measureGait(t.framesMm, t.rateHz, feet(t), t.speedMps, t.path);
    strideDiffs.push_back(100.0 * (b.strideTimeS - a.strideTimeS) / a.strideTimeS);
    stanceDiffs.push_back(b.stancePct - a.stancePct);
    std::cout << t.subject << ": from the feet, stride time " << strideDiffs.back() << " %, stance "
              << stanceDiffs.back() << " points\n";
    EXPECT_LE(std::abs(stanceDiffs.back()), 3.0) << t.path;
  }
  const EventLeads f = leadsOf(pointersTo(trials), feet), a = leadsOf(pointersTo(trials), ankle);
  std::cout << "strikes: feet " << meanOf(f.strikesMs) << " ± " << sdOf(f.strikesMs) << " ms (" << f.strikesMs.size()
            << "), ankle " << meanOf(a.strikesMs) << " ± " << sdOf(a.strikesMs) << " ms (" << a.strikesMs.size() << ")\n"
            << "offs: feet " << meanOf(f.offsMs) << " ± " << sdOf(f.offsMs) << " ms (" << f.offsMs.size() << "), ankle "
            << meanOf(a.offsMs) << " ± " << sdOf(a.offsMs) << " ms (" << a.offsMs.size() << ")\n";
  // Every file event found but each trial's first strike, at 0.05 s: the heel is foremost about
  // 30 ms before it, inside the smoothing window of the clip's start (gait_events.h). 18 × 3.
  EXPECT_EQ(f.strikesMs.size(), 54u);
  EXPECT_EQ(f.offsMs.size(), 54u);
  EXPECT_LT(std::abs(meanOf(f.strikesMs)), 0.5 * std::abs(meanOf(a.strikesMs)));
  EXPECT_LT(std::abs(meanOf(f.offsMs)), 0.5 * std::abs(meanOf(a.offsMs)));
  EXPECT_LT(sdOf(f.strikesMs), sdOf(a.strikesMs));
  EXPECT_LT(sdOf(f.offsMs), sdOf(a.offsMs));
  const auto within = [](const std::vector<double>& v, double bar) {
    return std::count_if(v.begin(), v.end(), [&](double d) { return std::abs(d) <= bar; });
  };
  std::cout << "stride time within 2 %: " << within(strideDiffs, 2.0) << " of 18 (the ankle's: 14), mean "
            << meanOf(strideDiffs) << " %; stance mean " << meanOf(stanceDiffs) << " points\n";
  EXPECT_GE(within(strideDiffs, 2.0), 16);
  EXPECT_LE(std::abs(meanOf(stanceDiffs)), 1.0);
}

// kHeelStrikeLagOfStride is the lag these trials measure (the toe's lead on the foot off less the
// heel's on the strike, as fractions of the stride); leaving each trial out, the lag of the other
// 17 still puts that trial's stance within 3 points of its C3D's.
TEST(FeetOnSharedWalkers, TheHeelStrikeLagHoldsForATrialItWasNotMeasuredOn) {
  EW_REQUIRE_SHARED_DATA();
  const std::vector<SharedC3dTrial> trials = sharedC3dTrials();
  ASSERT_EQ(trials.size(), 18u);
  const auto zeni = [](const SharedC3dTrial& t) { return gaitEventsFromFeet(t.framesMm, t.feetMm, t.rateHz, 0.0); };
  const auto lagOf = [&](const std::vector<const SharedC3dTrial*>& some) {
    const EventLeads l = leadsOf(some, zeni, true);
    return meanOf(l.offsMs) - meanOf(l.strikesMs);
  };
  const auto all = pointersTo(trials);
  std::cout << "heel strike lag " << 100 * lagOf(all) << " % of the stride\n";
  EXPECT_NEAR(lagOf(all), kHeelStrikeLagOfStride, 0.0005);
  for (const auto& t : trials) {
    std::vector<const SharedC3dTrial*> others;
    for (const auto* o : all)
      if (o != &t) others.push_back(o);
    const double lag = lagOf(others);
    const GaitMeasures a = measureGait(t.framesMm, t.rateHz, t.file, t.speedMps, t.path);
    const GaitMeasures b =
        measureGait(t.framesMm, t.rateHz, gaitEventsFromFeet(t.framesMm, t.feetMm, t.rateHz, lag), t.speedMps, t.path);
    std::cout << t.subject << ": lag of the others " << lag * 100 << " %; stance − C3D's " << b.stancePct - a.stancePct
              << " points\n";
    EXPECT_LE(std::abs(b.stancePct - a.stancePct), 3.0) << t.path;
  }
}

// The ankle's curve over the cycle as a gait lab draws it: its most plantarflexed point just after
// the foot off (Perry & Burnfield: about 62 % of the cycle), from the C3D's own events; the foot
// progression toe out on average (adults walk 5–10° toe out, Seber et al. 1981).
TEST(FeetOnSharedWalkers, AnkleCurvesPeakInPlantarflexionAtFootOff) {
  EW_REQUIRE_SHARED_DATA();
  std::vector<double> progression;
  for (const auto& t : sharedC3dTrials()) {
    const GaitMeasures g = measureGait(t.framesMm, t.rateHz, t.file, t.speedMps, t.path);
    const JointAngles angles = jointAnglesWithFeet(t.framesMm, t.feetMm, Eigen::Vector3d::UnitZ(), t.path);
    const auto curves = footCycleCurves(angles.degrees, angles.names, t.rateHz, g);
    ASSERT_EQ(curves.size(), 2u) << t.path;
    for (const auto& c : curves) {
      Eigen::Index lowest = 0;
      c.meanDeg.minCoeff(&lowest);
      const double range = c.meanDeg.maxCoeff() - c.meanDeg.minCoeff();
      std::cout << t.subject << " " << c.name << ": most plantarflexed at " << lowest << " % of the cycle, range "
                << range << "°\n";
      EXPECT_GE(lowest, 55) << t.path << " " << c.name;
      EXPECT_LE(lowest, 75) << t.path << " " << c.name;
      EXPECT_GT(range, 10.0) << t.path << " " << c.name;
    }
    const FootProgression p = footProgressionDeg(angles.degrees, angles.names, t.rateHz, g);
    progression.push_back(p.rightDeg);
    progression.push_back(p.leftDeg);
  }
  std::cout << "foot progression " << meanOf(progression) << " ± " << sdOf(progression) << "° (toe out)\n";
  EXPECT_GT(meanOf(progression), 2.0);
  EXPECT_LT(meanOf(progression), 15.0);
}

}  // namespace
}  // namespace ew
