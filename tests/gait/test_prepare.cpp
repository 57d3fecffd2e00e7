#include <gtest/gtest.h>

#include <cmath>

#include "core/common/errors.h"
#include "core/gait/canonical_frame.h"
#include "core/gait/gait_cycles.h"
#include "core/gait/prepare.h"
#include "tests/common/synthetic_gait.h"

namespace ew {
namespace {

using test::AnalyticGait;
using test::analyticWalkTrial;

// The normaliser must undo any lab frame: up axis, heading and progression.
class PrepareInAnyLabFrame : public ::testing::TestWithParam<std::tuple<int, int, double>> {};

TEST_P(PrepareInAnyLabFrame, RecoversCanonicalFrameSpeedAndStride) {
  auto [axis, sign, heading] = GetParam();
  AnalyticGait g;
  g.up = SignedAxis{axis, sign};
  g.headingDeg = heading;
  const WalkingTrial w = prepareWalkingTrial(analyticWalkTrial(g));
  const Eigen::MatrixXd& m = w.joints.positionsMm;
  // Facing +y, right hip on +x, head up.
  EXPECT_GT(m.col(3 * index(Joint::RHip)).mean(), 80.0);
  EXPECT_LT(m.col(3 * index(Joint::LHip)).mean(), -80.0);
  EXPECT_NEAR(m.col(3 * index(Joint::RHip) + 1).mean(), m.col(3 * index(Joint::LHip) + 1).mean(), 1e-6);
  EXPECT_GT(m.col(3 * index(Joint::Head) + 2).mean(), 1500.0);
  // Progression removed: the pelvis stays near the origin horizontally.
  EXPECT_LT(m.col(3 * index(Joint::Pelvis) + 1).cwiseAbs().maxCoeff(), 30.0);
  EXPECT_NEAR(w.speedMps, g.speedMps, 0.02);
  // Feet on the floor: the 5th percentile of the lower ankle is 0 (ankle height min is 80).
  EXPECT_LT(std::abs(std::min(m.col(3 * index(Joint::LAnkle) + 2).minCoeff(),
                              m.col(3 * index(Joint::RAnkle) + 2).minCoeff())), 1.0);
  EXPECT_NEAR(w.cycles.strideHz, g.strideHz, 0.02);
  EXPECT_EQ(w.cycles.method, "foot contacts");
  EXPECT_NEAR(w.cycles.cycleCount, g.durationS * g.strideHz, 0.1);
}

INSTANTIATE_TEST_SUITE_P(LabFrames, PrepareInAnyLabFrame,
                         ::testing::Values(std::make_tuple(2, 1, 0.0), std::make_tuple(2, 1, 180.0),
                                           std::make_tuple(1, 1, 37.0), std::make_tuple(0, -1, -120.0),
                                           std::make_tuple(2, -1, 90.0)));

TEST(GaitCycles, KinematicStrikesAtMaximumAnkleLead) {
  AnalyticGait g;
  g.speedMps = 0.0;
  const WalkingTrial w = prepareWalkingTrial(analyticWalkTrial(g));
  ASSERT_GE(w.cycles.rightStrikesS.size(), 2u);
  // Right heel strike where sin(2πft) = 1: t = (0.25 + k) / f.
  for (double t : w.cycles.rightStrikesS) {
    const double phase = std::fmod(t * g.strideHz, 1.0);
    EXPECT_NEAR(phase, 0.25, 0.03) << t;
  }
  for (double t : w.cycles.leftStrikesS) {
    EXPECT_NEAR(std::fmod(t * g.strideHz, 1.0), 0.75, 0.03) << t;
  }
}

TEST(GaitCycles, FileEventsWinOverKinematics) {
  AnalyticGait g;
  JointTrial t = analyticWalkTrial(g);
  // Events that imply 1.0 Hz although the kinematics say 0.9 Hz: the file is trusted.
  for (double s : {0.2, 1.2, 2.2}) t.events.push_back({Side::Right, GaitEventType::FootStrike, s, "Foot Strike"});
  PrepareOptions whole;
  whole.cropToSteadyWindow = false;
  const WalkingTrial w = prepareWalkingTrial(t, whole);
  EXPECT_EQ(w.cycles.method, "file events");
  EXPECT_NEAR(w.cycles.strideHz, 1.0, 1e-9);
}

TEST(Prepare, ShortGapsAreBridgedAndReported) {
  JointTrial t = analyticWalkTrial(AnalyticGait{});
  t.positionsMm.block(100, 3 * index(Joint::RKnee), 5, 3).setConstant(std::nan(""));
  const WalkingTrial w = prepareWalkingTrial(t);
  EXPECT_TRUE(w.joints.positionsMm.allFinite());
  ASSERT_FALSE(w.joints.warnings.empty());
  EXPECT_NE(w.joints.warnings.front().find("r_knee"), std::string::npos);
}

TEST(Prepare, LongGapLimitsTheWindowToTheLongestCompleteRun) {
  JointTrial t = analyticWalkTrial(AnalyticGait{0.9, 1.2, 100.0, 6.0});
  t.positionsMm.block(100, 3 * index(Joint::LWrist), 50, 3).setConstant(std::nan(""));
  const WalkingTrial w = prepareWalkingTrial(t);
  EXPECT_GE(w.windowBegin, 150);
}

TEST(Prepare, StandingStillIsNotWalking) {
  JointTrial t = analyticWalkTrial(AnalyticGait{});
  for (Eigen::Index r = 1; r < t.positionsMm.rows(); ++r) t.positionsMm.row(r) = t.positionsMm.row(0);
  try {
    prepareWalkingTrial(t);
    FAIL() << "a standing trial was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadData);
    EXPECT_NE(std::string(e.what()).find("not walking: "), std::string::npos) << e.what();
  }
}

TEST(Prepare, LessThanOneCycleIsAnError) {
  JointTrial t = analyticWalkTrial(AnalyticGait{0.9, 1.2, 100.0, 0.8});
  EXPECT_THROW(prepareWalkingTrial(t), Error);
}

TEST(Prepare, OneFrameIsAStaticTrial) {
  JointTrial t = analyticWalkTrial(AnalyticGait{});
  t.positionsMm.conservativeResize(1, Eigen::NoChange);
  try {
    prepareWalkingTrial(t);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("static trial"), std::string::npos);
  }
}

TEST(Prepare, JointMissingEverywhereIsNamed) {
  JointTrial t = analyticWalkTrial(AnalyticGait{});
  t.positionsMm.col(3 * index(Joint::LElbow)).setConstant(std::nan(""));
  try {
    prepareWalkingTrial(t);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("l_elbow"), std::string::npos) << e.what();
  }
}

TEST(SteadyWindow, DropsAStartFromStanding) {
  AnalyticGait g{0.9, 1.2, 100.0, 6.0};
  JointTrial t = analyticWalkTrial(g);
  // First 2 s: standing still at the start position.
  for (Eigen::Index r = 1; r < 200; ++r) t.positionsMm.row(r) = t.positionsMm.row(0);
  for (Eigen::Index r = 200; r < t.positionsMm.rows(); ++r) {
    for (int j = 0; j < kJointCount; ++j) t.positionsMm(r, 3 * j + 1) -= 2.0 * 1200.0;
  }
  const WalkingTrial w = prepareWalkingTrial(t);
  EXPECT_GE(w.windowBegin, 180);
  EXPECT_NEAR(w.speedMps, 1.2, 0.05);
}

}  // namespace
}  // namespace ew
