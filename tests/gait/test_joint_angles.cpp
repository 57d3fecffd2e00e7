// Joint angles of a 15-joint skeleton (core/gait/joint_angles.h): single-axis poses built
// by hand geometry, a whole pose built from known angles by forward kinematics, invariance
// to the frame the skeleton is given in, missing joints, and the CSV / .mot files.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/gait/joint_angles.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

constexpr double kPi = std::numbers::pi;
double rad(double deg) { return deg * kPi / 180.0; }

// METHOD §2 frame: x right, y forward, z up.
const Eigen::Vector3d kUp(0, 0, 1);

void setJoint(Eigen::MatrixXd& f, Joint j, const Eigen::Vector3d& p) { f.block<1, 3>(0, 3 * index(j)) = p.transpose(); }
Eigen::Vector3d joint(const Eigen::MatrixXd& f, Joint j) { return f.block<1, 3>(0, 3 * index(j)).transpose(); }

// Upright, arms hanging, every segment vertical.
Eigen::MatrixXd standing() {
  Eigen::MatrixXd f(1, 45);
  setJoint(f, Joint::Pelvis, {0, 0, 1000});
  setJoint(f, Joint::Sternum, {0, 0, 1500});
  setJoint(f, Joint::Head, {0, 0, 1750});
  setJoint(f, Joint::RHip, {100, 0, 1000});
  setJoint(f, Joint::LHip, {-100, 0, 1000});
  setJoint(f, Joint::RKnee, {100, 0, 550});
  setJoint(f, Joint::LKnee, {-100, 0, 550});
  setJoint(f, Joint::RAnkle, {100, 0, 130});
  setJoint(f, Joint::LAnkle, {-100, 0, 130});
  setJoint(f, Joint::RShoulder, {180, 0, 1450});
  setJoint(f, Joint::LShoulder, {-180, 0, 1450});
  setJoint(f, Joint::RElbow, {180, 0, 1150});
  setJoint(f, Joint::LElbow, {-180, 0, 1150});
  setJoint(f, Joint::RWrist, {180, 0, 890});
  setJoint(f, Joint::LWrist, {-180, 0, 890});
  return f;
}

double angle(const JointAngles& a, const std::string& name, Eigen::Index t = 0) {
  const auto& names = a.names;
  const auto it = std::find(names.begin(), names.end(), name);
  EXPECT_NE(it, names.end()) << name;
  return a.degrees(t, it - names.begin());
}

TEST(JointAngles, StandingUprightIsZeroEverywhere) {
  const JointAngles a = jointAngles(standing(), kUp, "standing");
  ASSERT_EQ(a.degrees.cols(), 23);
  for (Eigen::Index k = 0; k < a.degrees.cols(); ++k) EXPECT_NEAR(a.degrees(0, k), 0.0, 1e-9) << a.names[k];
  EXPECT_NEAR(a.pelvisM(0, 1), 1.0, 1e-12);  // 1000 mm up
}

TEST(JointAngles, SingleAxisPosesBuiltByHand) {
  Eigen::MatrixXd f = standing();
  // Right thigh 30° forward, leg straight.
  setJoint(f, Joint::RKnee, Eigen::Vector3d(100, 450 * std::sin(rad(30)), 1000 - 450 * std::cos(rad(30))));
  setJoint(f, Joint::RAnkle, Eigen::Vector3d(100, 870 * std::sin(rad(30)), 1000 - 870 * std::cos(rad(30))));
  // Left knee bent 60°, thigh vertical: the shank swings backward.
  setJoint(f, Joint::LAnkle, Eigen::Vector3d(-100, -420 * std::sin(rad(60)), 550 - 420 * std::cos(rad(60))));
  // Right arm raised 90° forward, elbow bent 90° (forearm up).
  setJoint(f, Joint::RElbow, {180, 300, 1450});
  setJoint(f, Joint::RWrist, {180, 300, 1710});
  // Left arm out sideways by 40° (abduction), straight.
  setJoint(f, Joint::LElbow, Eigen::Vector3d(-180 - 300 * std::sin(rad(40)), 0, 1450 - 300 * std::cos(rad(40))));
  setJoint(f, Joint::LWrist, Eigen::Vector3d(-180 - 560 * std::sin(rad(40)), 0, 1450 - 560 * std::cos(rad(40))));
  const JointAngles a = jointAngles(f, kUp, "by hand");
  EXPECT_NEAR(angle(a, "hip_flexion_r"), 30.0, 1e-9);
  EXPECT_NEAR(angle(a, "knee_angle_r"), 0.0, 1e-9);
  EXPECT_NEAR(angle(a, "hip_flexion_l"), 0.0, 1e-9);
  EXPECT_NEAR(angle(a, "knee_angle_l"), 60.0, 1e-9);
  EXPECT_NEAR(angle(a, "hip_rotation_l"), 0.0, 1e-9);
  EXPECT_NEAR(angle(a, "arm_flex_r"), 90.0, 1e-9);
  EXPECT_NEAR(angle(a, "elbow_flex_r"), 90.0, 1e-9);
  EXPECT_NEAR(angle(a, "arm_add_l"), -40.0, 1e-9);
  EXPECT_NEAR(angle(a, "elbow_flex_l"), 0.0, 1e-9);
  for (const char* n : {"pelvis_tilt", "pelvis_list", "pelvis_rotation", "lumbar_bending", "lumbar_rotation"})
    EXPECT_NEAR(angle(a, n), 0.0, 1e-9) << n;
}

TEST(JointAngles, HipRotationIsSeenThroughTheBentKnee) {
  Eigen::MatrixXd f = standing();
  // Right knee bent 90° (shank backward), thigh turned internally by 25°: the front of the
  // knee turns towards the midline, so the backward-pointing shank swings outward (+x).
  const double r = rad(25);
  setJoint(f, Joint::RAnkle, Eigen::Vector3d(100 + 420 * std::sin(r), -420 * std::cos(r), 550));
  const JointAngles a = jointAngles(f, kUp, "rotation");
  EXPECT_NEAR(angle(a, "hip_rotation_r"), 25.0, 1e-9);
  EXPECT_NEAR(angle(a, "knee_angle_r"), 90.0, 1e-9);
  EXPECT_NEAR(angle(a, "hip_flexion_r"), 0.0, 1e-9);
  EXPECT_NEAR(angle(a, "hip_adduction_r"), 0.0, 1e-9);
}

TEST(JointAngles, TrunkLeanAndShoulderTwist) {
  Eigen::MatrixXd f = standing();
  // Trunk 10° forward about the pelvis; the shoulders turned 15° (right shoulder forward)
  // about the trunk; the head keeps on the trunk's line.
  const Eigen::Matrix3d lean(Eigen::AngleAxisd(rad(-10), Eigen::Vector3d::UnitX()));  // +z towards +y
  const Eigen::Matrix3d twist(Eigen::AngleAxisd(rad(15), Eigen::Vector3d::UnitZ()));   // +x towards +y
  const Eigen::Vector3d pelvis = joint(f, Joint::Pelvis);
  for (Joint j : {Joint::Sternum, Joint::Head, Joint::RShoulder, Joint::LShoulder, Joint::RElbow, Joint::LElbow,
                  Joint::RWrist, Joint::LWrist}) {
    Eigen::Vector3d p = joint(f, j) - pelvis;
    if (j != Joint::Sternum && j != Joint::Head) p = twist * p;
    setJoint(f, j, pelvis + lean * p);
  }
  const JointAngles a = jointAngles(f, kUp, "lean");
  EXPECT_NEAR(angle(a, "pelvis_tilt"), -10.0, 1e-9);  // OpenSim's: positive backward
  EXPECT_NEAR(angle(a, "lumbar_rotation"), 15.0, 1e-9);
  EXPECT_NEAR(angle(a, "lumbar_bending"), 0.0, 1e-9);
  EXPECT_NEAR(angle(a, "neck_flexion"), 0.0, 1e-9);
  EXPECT_NEAR(angle(a, "arm_flex_r"), 0.0, 1e-9);  // the arms went with the thorax
}

// Forward kinematics in the segment frames (X forward, Y up, Z right) with the same
// Z, X, Y rotation order, mirrored on the left.
Eigen::Matrix3d zxy(double a, double b, double c) {
  return (Eigen::AngleAxisd(rad(a), Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(rad(b), Eigen::Vector3d::UnitX()) *
          Eigen::AngleAxisd(rad(c), Eigen::Vector3d::UnitY()))
      .toRotationMatrix();
}

struct LimbPose {
  double flex, add, rot, bend;
};

void placeLimb(Eigen::MatrixXd& f, const Eigen::Matrix3d& parent, Joint root, Joint middle, Joint end,
               const LimbPose& p, bool left, bool arm, double upper, double lower) {
  const double side = left ? -1.0 : 1.0;
  const Eigen::Matrix3d seg1 = parent * zxy(p.flex, side * p.add, side * p.rot);
  const Eigen::Matrix3d seg2 = seg1 * zxy(arm ? p.bend : -p.bend, 0, 0);
  const Eigen::Vector3d m = joint(f, root) - upper * seg1.col(1);
  setJoint(f, middle, m);
  setJoint(f, end, m - lower * seg2.col(1));
}

TEST(JointAngles, AWholePoseFromKnownAnglesIsReadBack) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::Matrix3d ground;
    ground << Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX();
    // The ground's forward is the clip's mean heading (the pelvis's, made horizontal): for
    // one frame tilt alone or list alone keep it on X (rotation has its own test below).
    const Eigen::Vector3d pelvisAngles(trial % 2 ? 0.0 : 15 * u(rng), trial % 2 ? 10 * u(rng) : 0.0, 0.0);
    const Eigen::Matrix3d pelvis = ground * zxy(pelvisAngles(0), pelvisAngles(1), pelvisAngles(2));
    Eigen::MatrixXd f(1, 45);
    const Eigen::Vector3d root(0, 0, 1000);
    setJoint(f, Joint::Pelvis, root);
    setJoint(f, Joint::RHip, root + 100 * pelvis.col(2));
    setJoint(f, Joint::LHip, root - 100 * pelvis.col(2));
    setJoint(f, Joint::Sternum, root + 500 * pelvis.col(1));
    setJoint(f, Joint::Head, root + 750 * pelvis.col(1));
    const Eigen::Vector3d sternum = root + 500 * pelvis.col(1);
    setJoint(f, Joint::RShoulder, sternum - 50 * pelvis.col(1) + 180 * pelvis.col(2));
    setJoint(f, Joint::LShoulder, sternum - 50 * pelvis.col(1) - 180 * pelvis.col(2));
    std::array<LimbPose, 4> limbs;
    for (auto& l : limbs) l = {40 * u(rng), 15 * u(rng), 30 * u(rng), 60 + 40 * u(rng)};  // bent ≥ 20°
    placeLimb(f, pelvis, Joint::RHip, Joint::RKnee, Joint::RAnkle, limbs[0], false, false, 450, 420);
    placeLimb(f, pelvis, Joint::LHip, Joint::LKnee, Joint::LAnkle, limbs[1], true, false, 450, 420);
    placeLimb(f, pelvis, Joint::RShoulder, Joint::RElbow, Joint::RWrist, limbs[2], false, true, 300, 260);
    placeLimb(f, pelvis, Joint::LShoulder, Joint::LElbow, Joint::LWrist, limbs[3], true, true, 300, 260);
    const JointAngles a = jointAngles(f, kUp, "fk");
    EXPECT_NEAR(angle(a, "pelvis_tilt"), pelvisAngles(0), 1e-9);
    EXPECT_NEAR(angle(a, "pelvis_list"), pelvisAngles(1), 1e-9);
    const std::array<std::string, 4> hip = {"hip_flexion_r", "hip_adduction_r", "hip_rotation_r", "knee_angle_r"};
    const std::array<std::array<std::string, 4>, 4> names = {
        hip,
        std::array<std::string, 4>{"hip_flexion_l", "hip_adduction_l", "hip_rotation_l", "knee_angle_l"},
        std::array<std::string, 4>{"arm_flex_r", "arm_add_r", "arm_rot_r", "elbow_flex_r"},
        std::array<std::string, 4>{"arm_flex_l", "arm_add_l", "arm_rot_l", "elbow_flex_l"}};
    for (int i = 0; i < 4; ++i) {
      const LimbPose& p = limbs[i];
      EXPECT_NEAR(angle(a, names[i][0]), p.flex, 1e-9) << names[i][0];
      EXPECT_NEAR(angle(a, names[i][1]), p.add, 1e-9) << names[i][1];
      EXPECT_NEAR(angle(a, names[i][2]), p.rot, 1e-9) << names[i][2];
      EXPECT_NEAR(angle(a, names[i][3]), p.bend, 1e-9) << names[i][3];
    }
  }
}

TEST(JointAngles, PelvisRotationIsAboutTheClipsMeanHeading) {
  // Two frames turned ±20° about the vertical through the pelvis: the mean heading is +y.
  Eigen::MatrixXd f(2, 45);
  for (int t = 0; t < 2; ++t) {
    const Eigen::Matrix3d turn(Eigen::AngleAxisd(rad(t ? -20 : 20), Eigen::Vector3d::UnitZ()));
    const Eigen::MatrixXd s = standing();
    for (int j = 0; j < kJointCount; ++j) {
      const Eigen::Vector3d p = joint(s, Joint(j)) - joint(s, Joint::Pelvis);
      f.block<1, 3>(t, 3 * j) = (joint(s, Joint::Pelvis) + turn * p).transpose();
    }
  }
  const JointAngles a = jointAngles(f, kUp, "turning");
  // A turn to the left (seen from above, counterclockwise: the right hip forward) is a
  // positive rotation about the up axis, as OpenSim's pelvis_rotation.
  EXPECT_NEAR(angle(a, "pelvis_rotation", 0), 20.0, 1e-9);
  EXPECT_NEAR(angle(a, "pelvis_rotation", 1), -20.0, 1e-9);
  EXPECT_NEAR(angle(a, "pelvis_tilt", 0), 0.0, 1e-9);
  EXPECT_NEAR(angle(a, "hip_rotation_r", 0), 0.0, 1e-9);
}

TEST(JointAngles, TheFrameTheSkeletonIsGivenInDoesNotMatter) {
  Eigen::MatrixXd f = standing();
  setJoint(f, Joint::RAnkle, Eigen::Vector3d(160, -380, 700));
  setJoint(f, Joint::LElbow, Eigen::Vector3d(-250, 150, 1200));
  const Eigen::Matrix3d r = Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  Eigen::MatrixXd g = f;
  for (int j = 0; j < kJointCount; ++j) g.block<1, 3>(0, 3 * j) = (r * joint(f, Joint(j)) + Eigen::Vector3d(5, -7, 9)).transpose();
  const JointAngles a = jointAngles(f, kUp, "a"), b = jointAngles(g, r * kUp * 3.0, "b");
  EXPECT_LT((a.degrees - b.degrees).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(JointAngles, AMissingJointLeavesOnlyItsAnglesEmpty) {
  Eigen::MatrixXd f = standing();
  setJoint(f, Joint::LWrist, Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()));
  const JointAngles a = jointAngles(f, kUp, "no wrist");
  for (Eigen::Index k = 0; k < a.degrees.cols(); ++k) {
    const bool leftArm = a.names[k].ends_with("_l") && (a.names[k].starts_with("arm") || a.names[k].starts_with("elbow"));
    EXPECT_EQ(std::isnan(a.degrees(0, k)), leftArm) << a.names[k];
  }
}

TEST(JointAngles, BadInputIsAClearError) {
  EXPECT_THROW(jointAngles(Eigen::MatrixXd::Zero(2, 44), kUp, "x"), Error);
  EXPECT_THROW(jointAngles(standing(), Eigen::Vector3d::Zero(), "x"), Error);
  Eigen::MatrixXd blind = Eigen::MatrixXd::Constant(3, 45, std::numeric_limits<double>::quiet_NaN());
  try {
    jointAngles(blind, kUp, "blind.csv");
    FAIL() << "no heading must be an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("blind.csv"), std::string::npos) << e.what();
  }
}

TEST(JointAngles, BodyUpIsTheSnappedHeadAboveTheAnkles) {
  const Eigen::MatrixXd f = standing();
  EXPECT_TRUE(bodyUp(f).isApprox(kUp));
  Eigen::MatrixXd yDown = f;
  for (int j = 0; j < kJointCount; ++j) {
    const Eigen::Vector3d p = joint(f, Joint(j));
    yDown.block<1, 3>(0, 3 * j) << p(0), -p(2), p(1);
  }
  EXPECT_TRUE(bodyUp(yDown).isApprox(Eigen::Vector3d(0, -1, 0)));
  Eigen::MatrixXd tilted = f;
  setJoint(tilted, Joint::Head, Eigen::Vector3d(0, 1000, 1750));  // 46° off z: not snapped
  EXPECT_GT(bodyUp(tilted)(1), 0.5);
}

TEST(JointAngles, CsvAndOpenSimMotFiles) {
  const auto dir = test::makeTempDir("joint_angles");
  Eigen::MatrixXd f(3, 45);
  for (int t = 0; t < 3; ++t) f.row(t) = standing().row(0);
  const JointAngles a = jointAngles(f, kUp, "three");
  writeJointAngles((dir / "a.mot").string(), a, 100.0, {"source=test"});
  std::ifstream mot(dir / "a.mot");
  std::vector<std::string> lines;
  for (std::string line; std::getline(mot, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 11u);
  EXPECT_EQ(lines[0], "a");
  EXPECT_EQ(lines[1], "version=1");
  EXPECT_EQ(lines[2], "nRows=3");
  EXPECT_EQ(lines[3], "nColumns=27");
  EXPECT_EQ(lines[4], "inDegrees=yes");
  EXPECT_EQ(lines[5], "source=test");
  EXPECT_EQ(lines[6], "endheader");
  EXPECT_TRUE(lines[7].starts_with("time\tpelvis_tilt\t"));
  EXPECT_TRUE(lines[7].ends_with("\tpelvis_tx\tpelvis_ty\tpelvis_tz"));
  EXPECT_TRUE(lines[9].starts_with("0.01\t0\t")) << lines[9];
  writeJointAngles((dir / "a.csv").string(), a, 100.0, {"from a test"});
  const std::string csv = test::readTextFile(dir / "a.csv");
  EXPECT_TRUE(csv.starts_with("# from a test\ntime_s,pelvis_tilt,")) << csv.substr(0, 80);
  EXPECT_THROW(writeJointAngles((dir / "a.txt").string(), a, 100.0), Error);
  EXPECT_THROW(writeJointAngles((dir / "missing" / "a.mot").string(), a, 100.0), Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "missing"));
}

}  // namespace
}  // namespace ew
