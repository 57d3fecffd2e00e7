#include "tests/common/synthetic_gait.h"

#include <cmath>

namespace ew::test {
namespace {

// Joint positions in a body frame: x right, y forward, z up; phase s = 2π f t.
Eigen::Matrix<double, 15, 3> bodyPose(double s) {
  Eigen::Matrix<double, 15, 3> p;
  const double bob = 15.0 * std::cos(2.0 * s);
  const double swingR = std::sin(s), swingL = -std::sin(s);
  auto foot = [](double swing, double phase) {
    // Foot lifts during swing (when moving forward), stays on the floor in stance.
    return Eigen::Vector2d(300.0 * swing, 80.0 + 60.0 * std::max(0.0, std::cos(phase)));
  };
  const Eigen::Vector2d fr = foot(swingR, s), fl = foot(swingL, s + M_PI);
  p << 0, 20, 1650 + bob,                  // head
      0, 10, 1420 + bob,                    // sternum
      0, 0, 950 + bob,                      // pelvis
      180, 10, 1400 + bob,                  // r_shoulder
      190, -120 * swingL, 1100 + bob,       // r_elbow (arms swing opposite to legs)
      195, -220 * swingL, 820 + bob,        // r_wrist
      -180, 10, 1400 + bob,                 // l_shoulder
      -190, -120 * swingR, 1100 + bob,      // l_elbow
      -195, -220 * swingR, 820 + bob,       // l_wrist
      90, 0, 950 + bob,                     // r_hip
      95, 0.5 * fr.x() + 40, 520 + 0.5 * fr.y(),  // r_knee
      100, fr.x(), fr.y(),                  // r_ankle
      -90, 0, 950 + bob,                    // l_hip
      -95, 0.5 * fl.x() + 40, 520 + 0.5 * fl.y(), // l_knee
      -100, fl.x(), fl.y();                 // l_ankle
  return p;
}

Eigen::Matrix3d labFromBody(const AnalyticGait& g) {
  // Body (x right, y forward, z up) -> lab z-up with heading, then -> the lab's up axis.
  const Eigen::Matrix3d heading =
      Eigen::AngleAxisd(g.headingDeg * M_PI / 180.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Eigen::Vector3d upAxis = Eigen::Vector3d::Zero();
  upAxis[g.up.axis] = g.up.sign;
  Eigen::Matrix3d toLab = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), upAxis).toRotationMatrix();
  if (upAxis.isApprox(-Eigen::Vector3d::UnitZ())) {
    toLab = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  }
  return toLab * heading;
}

}  // namespace

Eigen::MatrixXd analyticWalkFrames(const AnalyticGait& g) {
  const int frames = static_cast<int>(std::lround(g.durationS * g.rateHz));
  const Eigen::Matrix3d R = labFromBody(g);
  Eigen::MatrixXd m(frames, 45);
  for (int i = 0; i < frames; ++i) {
    const double t = i / g.rateHz;
    Eigen::Matrix<double, 15, 3> pose = bodyPose(2.0 * M_PI * g.strideHz * t);
    pose.col(1).array() += 1000.0 * g.speedMps * t;
    for (int j = 0; j < 15; ++j) {
      m.block<1, 3>(i, 3 * j) = (R * pose.row(j).transpose()).transpose();
    }
  }
  return m;
}

JointTrial analyticWalkTrial(const AnalyticGait& g) {
  JointTrial t;
  t.file = "analytic";
  t.format = "test";
  t.source = "analytic gait";
  t.rateHz = g.rateHz;
  t.units = "mm";
  t.positionsMm = analyticWalkFrames(g);
  return t;
}

}  // namespace ew::test
