// The feet beside the 15 joints: carried through prepare with the joints (core/gait/prepare.h),
// gait events from the heel and the toe (gaitEventsFromFeet, core/gait/gait_events.h), and the
// ankle and foot progression angles (jointAnglesWithFeet, core/gait/joint_angles.h). Synthetic
// walkers with known answers; the shared walkers' feet against their C3D events are in
// test_gait_measures.cpp.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/gait/gait_events.h"
#include "core/gait/joint_angles.h"
#include "core/gait/prepare.h"
#include "core/synth/population.h"
#include "tests/common/synthetic_gait.h"

namespace ew {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Eigen::Vector3d ankleAt(const Eigen::MatrixXd& m, Eigen::Index row, Side side) {
  return m.row(row).segment<3>(3 * index(side == Side::Left ? Joint::LAnkle : Joint::RAnkle)).transpose();
}

Eigen::Vector3d footAt(const Eigen::MatrixXd& feet, Eigen::Index row, FootPoint p) {
  return feet.row(row).segment<3>(3 * index(p)).transpose();
}

// [SECTION] Through prepare

// Heel and toe at fixed offsets from their ankle along the walker's own forward and up, in a lab
// frame with another up axis and heading: prepare must put them where the canonical frame says.
class FeetThroughPrepare : public ::testing::TestWithParam<std::tuple<int, double>> {};

TEST_P(FeetThroughPrepare, TheFeetKeepTheirPlaceOnTheJoints) {
  const auto [upAxis, headingDeg] = GetParam();
  test::AnalyticGait g;
  g.up = SignedAxis{upAxis, 1};
  g.headingDeg = headingDeg;
  JointTrial t = test::analyticWalkTrial(g);
  // The lab's forward and up (synthetic_gait.cpp's body → lab rotation).
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  up[upAxis] = 1.0;
  const Eigen::Matrix3d toLab =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), up).toRotationMatrix() *
      Eigen::AngleAxisd(headingDeg * std::numbers::pi / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Eigen::Vector3d forward = toLab * Eigen::Vector3d::UnitY(), labUp = toLab * Eigen::Vector3d::UnitZ();
  t.feetMm.resize(t.frameCount(), kFootDims3);
  for (Eigen::Index r = 0; r < t.frameCount(); ++r) {
    for (Side side : {Side::Right, Side::Left}) {
      const Eigen::Vector3d ankle = ankleAt(t.positionsMm, r, side);
      t.feetMm.row(r).segment<3>(3 * index(heelOf(side))) = (ankle - 50.0 * forward - 40.0 * labUp).transpose();
      t.feetMm.row(r).segment<3>(3 * index(toeOf(side))) = (ankle + 150.0 * forward - 40.0 * labUp).transpose();
    }
  }
  // A short gap and a one-frame glitch in the right toe are bridged; the left heel is never seen.
  t.feetMm.block(100, 3 * index(FootPoint::RToe), 4, 3).setConstant(kNaN);
  t.feetMm(150, 3 * index(FootPoint::RToe)) += 5000.0;
  t.feetMm.middleCols(3 * index(FootPoint::LHeel), 3).setConstant(kNaN);
  const WalkingTrial w = prepareWalkingTrial(t);
  const Eigen::MatrixXd& m = w.joints.positionsMm;
  ASSERT_TRUE(w.joints.hasFeet());
  EXPECT_TRUE(w.joints.feetMm.middleCols(3 * index(FootPoint::LHeel), 3).array().isNaN().all());
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    const Eigen::Vector3d rToe = footAt(w.joints.feetMm, r, FootPoint::RToe) - ankleAt(m, r, Side::Right);
    const Eigen::Vector3d rHeel = footAt(w.joints.feetMm, r, FootPoint::RHeel) - ankleAt(m, r, Side::Right);
    const Eigen::Vector3d lToe = footAt(w.joints.feetMm, r, FootPoint::LToe) - ankleAt(m, r, Side::Left);
    EXPECT_TRUE(rHeel.isApprox(Eigen::Vector3d(0, -50, -40), 1e-9)) << "row " << r << ": " << rHeel.transpose();
    EXPECT_TRUE(lToe.isApprox(Eigen::Vector3d(0, 150, -40), 1e-9)) << "row " << r << ": " << lToe.transpose();
    // The bridged samples lie on a line between their neighbours, a few mm off the ankle's arc.
    const int loadedRow = w.windowBegin + static_cast<int>(r);
    const bool bridged = (loadedRow >= 100 && loadedRow < 104) || loadedRow == 150;
    EXPECT_LT((rToe - Eigen::Vector3d(0, 150, -40)).norm(), bridged ? 30.0 : 1e-6) << "row " << r;
  }
}

INSTANTIATE_TEST_SUITE_P(LabFrames, FeetThroughPrepare,
                         ::testing::Values(std::tuple{2, 30.0}, std::tuple{1, -60.0}, std::tuple{0, 135.0}));

TEST(FeetThroughPrepare, FeetOfAnotherLengthAreLeftBehind) {
  JointTrial t = test::analyticWalkTrial({});
  t.feetMm = Eigen::MatrixXd::Zero(t.frameCount() - 1, kFootDims3);  // one row short: not the trial's
  EXPECT_FALSE(t.hasFeet());
  const WalkingTrial w = prepareWalkingTrial(t);
  EXPECT_FALSE(w.joints.hasFeet());
  EXPECT_EQ(w.joints.feetMm.size(), 0);
}

// [SECTION] Events from the heel and the toe

// A walker in its canonical frame at 100 Hz: the pelvis still, each ankle, heel and toe swinging
// fore and aft sinusoidally at 0.9 strides a second, the heel 30 ms behind the ankle and the toe
// 50 ms ahead of it; the left foot half a stride after the right.
constexpr double kStrideHz = 0.9, kRateHz = 100.0, kHeelDelayS = 0.03, kToeDelayS = -0.05;

double swing(double t, double delayS, double phase) {
  return 300.0 * std::sin(2.0 * std::numbers::pi * kStrideHz * (t - delayS) + phase);
}

struct CanonicalWalker {
  Eigen::MatrixXd frames, feet;
};

CanonicalWalker swingingFeet(int rows) {
  CanonicalWalker w{Eigen::MatrixXd::Zero(rows, kDims3), Eigen::MatrixXd::Zero(rows, kFootDims3)};
  for (int r = 0; r < rows; ++r) {
    const double t = r / kRateHz;
    for (Side side : {Side::Right, Side::Left}) {
      const double phase = side == Side::Right ? 0.0 : std::numbers::pi;
      const int ankle = 3 * index(side == Side::Left ? Joint::LAnkle : Joint::RAnkle);
      w.frames(r, ankle + 1) = swing(t, 0.0, phase);
      w.feet(r, 3 * index(heelOf(side)) + 1) = swing(t, kHeelDelayS, phase) - 50.0;
      w.feet(r, 3 * index(toeOf(side)) + 1) = swing(t, kToeDelayS, phase) + 150.0;
    }
  }
  return w;
}

// The times in [0, endS] where the swing of delay `delayS` and `phase` is foremost (rearmost:
// half a stride later).
std::vector<double> extremeTimes(double delayS, double phase, bool foremost, double endS) {
  std::vector<double> times;
  const double strideS = 1.0 / kStrideHz;
  double t = delayS + (0.25 - phase / (2.0 * std::numbers::pi)) * strideS + (foremost ? 0.0 : 0.5 * strideS);
  while (t > 0) t -= strideS;
  for (; t <= endS; t += strideS)
    if (t > 0.05 && t < endS - 0.05) times.push_back(t);
  return times;
}

void expectTimes(const std::vector<double>& got, const std::vector<double>& want, const char* what) {
  ASSERT_EQ(got.size(), want.size()) << what;
  for (size_t k = 0; k < got.size(); ++k) EXPECT_NEAR(got[k], want[k], 0.002) << what << " " << k;
}

TEST(FootEvents, StrikesFromTheHeelAndFootOffsFromTheToe) {
  const CanonicalWalker w = swingingFeet(400);
  const double endS = 399 / kRateHz, lagS = kHeelStrikeLagOfStride / kStrideHz;
  const GaitEventSet e = gaitEventsFromFeet(w.frames, w.feet, kRateHz);
  EXPECT_EQ(e.method, "kinematics (heel and toe)");
  for (Side side : {Side::Right, Side::Left}) {
    const double phase = side == Side::Right ? 0.0 : std::numbers::pi;
    std::vector<double> strikes = extremeTimes(kHeelDelayS, phase, true, endS);
    for (double& s : strikes) s += lagS;
    expectTimes(e.of(side).strikesS, strikes, side == Side::Right ? "right strikes" : "left strikes");
    expectTimes(e.of(side).offsS, extremeTimes(kToeDelayS, phase, false, endS),
                side == Side::Right ? "right offs" : "left offs");
  }
  // Without the lag the strike is the heel's foremost point itself.
  const GaitEventSet zeni = gaitEventsFromFeet(w.frames, w.feet, kRateHz, 0.0);
  expectTimes(zeni.right.strikesS, extremeTimes(kHeelDelayS, 0.0, true, endS), "Zeni's right strikes");
}

// A foot missing its heel or its toe somewhere (a gap prepare could not bridge, a point never
// seen) times both its events from the ankle: a foot's strike and foot off share one lead.
TEST(FootEvents, AFootWithoutBothPointsTimesItsEventsFromTheAnkle) {
  CanonicalWalker w = swingingFeet(400);
  const GaitEventSet ankle = gaitEventsFromKinematics(w.frames, kRateHz);
  const GaitEventSet both = gaitEventsFromFeet(w.frames, w.feet, kRateHz);
  w.feet.col(3 * index(FootPoint::LHeel) + 2).setConstant(kNaN);  // never seen (one coordinate is enough)
  GaitEventSet e = gaitEventsFromFeet(w.frames, w.feet, kRateHz);
  EXPECT_EQ(e.method, "kinematics (heel and toe of one foot, the other's ankle)");
  EXPECT_EQ(e.left.strikesS, ankle.left.strikesS);
  EXPECT_EQ(e.left.offsS, ankle.left.offsS);
  EXPECT_EQ(e.right.strikesS, both.right.strikesS);  // the right foot is whole
  EXPECT_EQ(e.right.offsS, both.right.offsS);
  EXPECT_NE(e.right.offsS, ankle.right.offsS);
  w.feet(200, 3 * index(FootPoint::RToe) + 1) = kNaN;  // and now the right toe has a gap
  e = gaitEventsFromFeet(w.frames, w.feet, kRateHz);
  EXPECT_EQ(e.method, "kinematics");
  for (Side side : {Side::Right, Side::Left}) {
    EXPECT_EQ(e.of(side).strikesS, ankle.of(side).strikesS);
    EXPECT_EQ(e.of(side).offsS, ankle.of(side).offsS);
  }
}

TEST(FootEvents, NoFeetGivesTheAnklesEventsUnchanged) {
  // A walker of the synthetic population, prepared as the gait command prepares it.
  PopulationOptions o;
  o.count = 1;
  const WalkingTrial t = prepareWalkingTrial(generatePopulation(o).front().trial);
  const Eigen::MatrixXd& m = t.joints.positionsMm;
  const double rate = t.joints.rateHz;
  const GaitEventSet ankle = gaitEventsFromKinematics(m, rate);
  ASSERT_FALSE(ankle.right.strikesS.empty());
  const auto same = [&](const GaitEventSet& e, const char* what) {
    EXPECT_EQ(e.method, "kinematics") << what;
    for (Side side : {Side::Right, Side::Left}) {
      EXPECT_EQ(e.of(side).strikesS, ankle.of(side).strikesS) << what;
      EXPECT_EQ(e.of(side).offsS, ankle.of(side).offsS) << what;
    }
  };
  same(gaitEventsFromFeet(m, Eigen::MatrixXd(), rate), "no feet");
  same(gaitEventsFromFeet(m, Eigen::MatrixXd::Constant(m.rows(), kFootDims3, kNaN), rate), "all NaN");
  same(gaitEventsFromFeet(m, Eigen::MatrixXd::Zero(m.rows() - 1, kFootDims3), rate), "a row short");
  same(gaitEventsFromFeet(m, Eigen::MatrixXd::Zero(m.rows(), 9), rate), "three points");
  const GaitEventSet none = gaitEventsFromFeet(m.topRows(2), Eigen::MatrixXd::Zero(2, kFootDims3), rate);
  EXPECT_TRUE(none.right.strikesS.empty() && none.left.offsS.empty());
}

// [SECTION] Ankle and foot progression angles

// A walker standing still (the analytic walker's first frame, z up, facing +y) whose right shank
// is vertical and whose feet are set by hand.
struct StandingFeet {
  Eigen::MatrixXd frames, feet;
};

StandingFeet standing() {
  test::AnalyticGait g;
  g.durationS = 0.02;
  StandingFeet s{test::analyticWalkFrames(g).topRows(1), Eigen::MatrixXd::Constant(1, kFootDims3, kNaN)};
  for (Side side : {Side::Right, Side::Left}) {
    const Eigen::Vector3d ankle = ankleAt(s.frames, 0, side);
    const int knee = 3 * index(side == Side::Left ? Joint::LKnee : Joint::RKnee);
    s.frames.row(0).segment<3>(knee) = (ankle + Eigen::Vector3d(0, 0, 400)).transpose();
  }
  return s;
}

void placeFoot(StandingFeet& s, Side side, double toeOutDeg, double toeUpDeg) {
  const double out = toeOutDeg * std::numbers::pi / 180.0, up = toeUpDeg * std::numbers::pi / 180.0;
  const double sideways = side == Side::Right ? 1.0 : -1.0;
  const Eigen::Vector3d along(sideways * std::sin(out) * std::cos(up), std::cos(out) * std::cos(up), std::sin(up));
  const Eigen::Vector3d heel = ankleAt(s.frames, 0, side) + Eigen::Vector3d(0, -50, -40);
  s.feet.row(0).segment<3>(3 * index(heelOf(side))) = heel.transpose();
  s.feet.row(0).segment<3>(3 * index(toeOf(side))) = (heel + 200.0 * along).transpose();
}

double angleNamed(const JointAngles& a, const std::string& name) {
  const auto it = std::find(a.names.begin(), a.names.end(), name);
  return it == a.names.end() ? -999.0 : a.degrees(0, it - a.names.begin());
}

TEST(FootAngles, AnkleFlexionAndFootProgressionFromHeelAndToe) {
  StandingFeet s = standing();
  placeFoot(s, Side::Right, 0.0, 0.0);
  placeFoot(s, Side::Left, 0.0, 0.0);
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  JointAngles a = jointAnglesWithFeet(s.frames, s.feet, up, "standing");
  EXPECT_EQ(a.names.size(), jointAngleNames().size() + footAngleNames().size());
  EXPECT_NEAR(angleNamed(a, "ankle_angle_r"), 0.0, 1e-9);  // shank square to the foot
  EXPECT_NEAR(angleNamed(a, "foot_progression_r"), 0.0, 1e-9);
  // Toes up 15° (dorsiflexion) and out 12° on both feet (the left foot's out is to the left).
  placeFoot(s, Side::Right, 12.0, 15.0);
  placeFoot(s, Side::Left, 12.0, -20.0);
  a = jointAnglesWithFeet(s.frames, s.feet, up, "standing");
  EXPECT_NEAR(angleNamed(a, "ankle_angle_r"), 15.0, 1e-9);
  EXPECT_NEAR(angleNamed(a, "foot_progression_r"), 12.0, 1e-9);
  EXPECT_NEAR(angleNamed(a, "ankle_angle_l"), -20.0, 1e-9);  // plantarflexion
  EXPECT_NEAR(angleNamed(a, "foot_progression_l"), 12.0, 1e-9);
  // The joints' own angles are jointAngles', column for column.
  const JointAngles joints = jointAngles(s.frames, up, "standing");
  EXPECT_TRUE(a.degrees.leftCols(joints.degrees.cols()).isApprox(joints.degrees) ||
              (a.degrees.leftCols(joints.degrees.cols()).array().isNaN() == joints.degrees.array().isNaN()).all());
}

TEST(FootAngles, MissingPointsAreNaNNeverAnError) {
  StandingFeet s = standing();
  placeFoot(s, Side::Right, 5.0, 5.0);  // the left foot stays NaN
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  JointAngles a = jointAnglesWithFeet(s.frames, s.feet, up, "half");
  EXPECT_TRUE(std::isfinite(angleNamed(a, "ankle_angle_r")));
  EXPECT_TRUE(std::isnan(angleNamed(a, "ankle_angle_l")));
  EXPECT_TRUE(std::isnan(angleNamed(a, "foot_progression_l")));
  // The toe on the heel: no foot axis. No knee: no ankle angle, the progression still.
  s.feet.row(0).segment<3>(3 * index(FootPoint::RToe)) = s.feet.row(0).segment<3>(3 * index(FootPoint::RHeel));
  s.frames.row(0).segment<3>(3 * index(Joint::LKnee)).setConstant(kNaN);
  placeFoot(s, Side::Left, 5.0, 5.0);
  a = jointAnglesWithFeet(s.frames, s.feet, up, "degenerate");
  EXPECT_TRUE(std::isnan(angleNamed(a, "ankle_angle_r")));
  EXPECT_TRUE(std::isnan(angleNamed(a, "foot_progression_r")));
  EXPECT_TRUE(std::isnan(angleNamed(a, "ankle_angle_l")));
  EXPECT_NEAR(angleNamed(a, "foot_progression_l"), 5.0, 1e-9);
  // No feet at all, or feet of another shape: the columns are there, NaN.
  a = jointAnglesWithFeet(s.frames, Eigen::MatrixXd(), up, "none");
  EXPECT_TRUE(std::isnan(angleNamed(a, "ankle_angle_r")));
  a = jointAnglesWithFeet(s.frames, Eigen::MatrixXd::Zero(1, 6), up, "short");
  EXPECT_TRUE(std::isnan(angleNamed(a, "foot_progression_r")));
}

}  // namespace
}  // namespace ew

namespace ew {
namespace {

// A detector's feet drop out where the walker enters or leaves the picture: the heel and the toe
// still give a foot's events over the frames they are seen in together (kMinFeetSeenShare),
// none outside them; seen over less, the ankle's events stand in.
TEST(FeetEvents, FeetSeenOverMostOfTheClipGiveTheirEventsThere) {
  test::AnalyticGait g;
  JointTrial t = test::analyticWalkTrial(g);
  const WalkingTrial w = prepareWalkingTrial(t);
  const Eigen::MatrixXd& m = w.joints.positionsMm;
  const double rate = w.joints.rateHz;
  Eigen::MatrixXd feet(m.rows(), kFootDims3);
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    for (Side side : {Side::Right, Side::Left}) {
      const Eigen::Vector3d ankle = m.row(r).segment<3>(3 * index(side == Side::Left ? Joint::LAnkle : Joint::RAnkle)).transpose();
      feet.row(r).segment<3>(3 * index(heelOf(side))) = (ankle + Eigen::Vector3d(0, -50, -40)).transpose();
      feet.row(r).segment<3>(3 * index(toeOf(side))) = (ankle + Eigen::Vector3d(0, 150, -40)).transpose();
    }
  const GaitEventSet whole = gaitEventsFromFeet(m, feet, rate);
  const Eigen::Index cut = m.rows() / 10;  // the right foot unseen in the first tenth
  feet.block(0, 3 * index(FootPoint::RHeel), cut, 6).setConstant(std::numeric_limits<double>::quiet_NaN());
  const GaitEventSet partly = gaitEventsFromFeet(m, feet, rate);
  EXPECT_EQ(partly.method, "kinematics (heel and toe)");
  const double cutS = static_cast<double>(cut) / rate;
  for (double s : partly.right.strikesS) EXPECT_GT(s, cutS);
  // The events the run holds are the whole clip's, but for the heel-strike lag's stride.
  for (double s : partly.right.offsS) {
    double nearest = 1e9;
    for (double o : whole.right.offsS) nearest = std::min(nearest, std::abs(o - s));
    EXPECT_LT(nearest, 0.5 / rate) << s;
  }
  EXPECT_GE(partly.right.offsS.size() + 1, whole.right.offsS.size());
  // Seen over less than kMinFeetSeenShare: the ankle's events for that foot.
  feet.block(0, 3 * index(FootPoint::RHeel), m.rows() / 4, 6).setConstant(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(gaitEventsFromFeet(m, feet, rate).method, "kinematics (heel and toe of one foot, the other's ankle)");
}

}  // namespace
}  // namespace ew
