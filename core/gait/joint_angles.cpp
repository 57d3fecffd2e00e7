#include "core/gait/joint_angles.h"

#include <Eigen/Geometry>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <numbers>
#include <optional>
#include <utility>
#include <sstream>
#include <algorithm>
#include <array>
#include <limits>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/common/trial.h"
#include "core/io/atomic_write.h"

namespace ew {
namespace {

using Vec = Eigen::Vector3d;
using Rot = Eigen::Matrix3d;  // columns: the segment's X, Y, Z in the data's frame

constexpr double kDeg = 180.0 / std::numbers::pi;

std::optional<Vec> jointAt(const Eigen::Ref<const Eigen::MatrixXd>& frames, Eigen::Index t, Joint j) {
  const Vec p = frames.row(t).segment<3>(3 * index(j)).transpose();
  if (!p.allFinite()) return std::nullopt;
  return p;
}

// The unit `primary` and the unit part of `hint` perpendicular to it; nothing when either
// vanishes.
std::optional<std::pair<Vec, Vec>> orthonormalPair(const Vec& primary, const Vec& hint) {
  const double np = primary.norm();
  if (!(np > 1e-9)) return std::nullopt;
  const Vec a = primary / np;
  const Vec perp = hint - hint.dot(a) * a;
  const double nh = perp.norm();
  if (!(nh > 1e-9)) return std::nullopt;
  return std::pair{a, Vec(perp / nh)};
}

Rot frameOf(const Vec& Y, const Vec& Z) {
  Rot r;
  r << Y.cross(Z), Y, Z;
  return r;
}

// The frame whose Y is `y` and whose Z is `zHint` made perpendicular to it.
std::optional<Rot> frameFromYZ(const Vec& y, const Vec& zHint) {
  const auto p = orthonormalPair(y, zHint);
  if (!p) return std::nullopt;
  return frameOf(p->first, p->second);
}

// The frame whose Z is `z` and whose Y is `yHint` made perpendicular to it.
std::optional<Rot> frameFromZY(const Vec& z, const Vec& yHint) {
  const auto p = orthonormalPair(z, yHint);
  if (!p) return std::nullopt;
  return frameOf(p->second, p->first);
}

// R = Rz(a)·Rx(b)·Ry(c): (a, b, c) in degrees.
Vec cardanZXY(const Rot& r) {
  const double b = std::asin(std::clamp(r(2, 1), -1.0, 1.0));
  const double a = std::atan2(-r(0, 1), r(1, 1));
  const double c = std::atan2(-r(2, 0), r(2, 2));
  return Vec(a, b, c) * kDeg;
}

Vec relativeAngles(const Rot& parent, const Rot& child) { return cardanZXY(parent.transpose() * child); }

double smoothstep(double x, double lo, double hi) {
  const double s = std::clamp((x - lo) / (hi - lo), 0.0, 1.0);
  return s * s * (3.0 - 2.0 * s);
}

// The hinge axis of a joint between `proximal` (towards the body) and `distal` bones,
// pointing along `parentZ`, blended into parentZ where the limb is nearly straight.
// `bendsForward`: the distal bone swings forward when the joint bends (the elbow), not
// backward (the knee).
Vec hingeAxis(const Vec& toProximal, const Vec& toDistal, const Vec& parentZ, bool bendsForward) {
  const Vec cross = bendsForward ? toDistal.cross(toProximal) : toProximal.cross(toDistal);
  const double sine = cross.norm() / (toProximal.norm() * toDistal.norm());
  if (!(sine > 0.0) || !std::isfinite(sine)) return parentZ;
  Vec hinge = cross.normalized();
  const double w = smoothstep(sine, std::sin(5.0 / kDeg), std::sin(20.0 / kDeg));
  // Nearly straight, a hinge pointing against the parent's Z is a hyperextended joint (its
  // bend then reads negative). Bent further, the hinge is trusted as it is: an elbow with
  // the arm raised sideways has a hinge across the parent's Z, and orienting it by that
  // read a 100° bend as −100° in the Pose2Sim trial.
  if (w < 1.0 && hinge.dot(parentZ) < 0.0) hinge = -hinge;
  return w * hinge + (1.0 - w) * parentZ;
}

struct LimbJoints {
  Joint root, middle, end;
};
constexpr LimbJoints kRightLeg{Joint::RHip, Joint::RKnee, Joint::RAnkle};
constexpr LimbJoints kLeftLeg{Joint::LHip, Joint::LKnee, Joint::LAnkle};
constexpr LimbJoints kRightArm{Joint::RShoulder, Joint::RElbow, Joint::RWrist};
constexpr LimbJoints kLeftArm{Joint::LShoulder, Joint::LElbow, Joint::LWrist};

// Flexion, adduction, rotation at the limb's root and flexion at its middle joint, or
// nothing when a joint is missing. Left limbs mirror adduction and rotation.
std::optional<Eigen::Vector4d> limbAngles(const Eigen::Ref<const Eigen::MatrixXd>& frames, Eigen::Index t,
                                          const Rot& parent, const LimbJoints& limb, bool left, bool arm) {
  const auto root = jointAt(frames, t, limb.root), middle = jointAt(frames, t, limb.middle),
             end = jointAt(frames, t, limb.end);
  if (!root || !middle || !end) return std::nullopt;
  const Vec toRoot = *root - *middle, toEnd = *end - *middle;
  const Vec z = hingeAxis(toRoot, toEnd, parent.col(2), arm);
  const auto upper = frameFromYZ(toRoot, z), lower = frameFromYZ(-toEnd, z);
  if (!upper || !lower) return std::nullopt;
  const Vec rootAngles = relativeAngles(parent, *upper);
  const double side = left ? -1.0 : 1.0;
  const double bend = relativeAngles(*upper, *lower)(0);
  return Eigen::Vector4d(rootAngles(0), side * rootAngles(1), side * rootAngles(2), arm ? bend : -bend);
}

struct TrunkFrames {
  Rot pelvis, thorax;
};

std::optional<TrunkFrames> trunkFrames(const Eigen::Ref<const Eigen::MatrixXd>& frames, Eigen::Index t) {
  const auto pelvis = jointAt(frames, t, Joint::Pelvis), sternum = jointAt(frames, t, Joint::Sternum);
  const auto rHip = jointAt(frames, t, Joint::RHip), lHip = jointAt(frames, t, Joint::LHip);
  const auto rSh = jointAt(frames, t, Joint::RShoulder), lSh = jointAt(frames, t, Joint::LShoulder);
  if (!pelvis || !sternum || !rHip || !lHip || !rSh || !lSh) return std::nullopt;
  const Vec trunk = *sternum - *pelvis;
  const auto p = frameFromZY(*rHip - *lHip, trunk), th = frameFromZY(*rSh - *lSh, trunk);
  if (!p || !th) return std::nullopt;
  return TrunkFrames{*p, *th};
}

// Ground: Y up, X the mean pelvis forward made horizontal, Z = X × Y.
Rot groundFrame(const Eigen::Ref<const Eigen::MatrixXd>& frames, const Vec& up, const std::string& name) {
  const Vec Y = up.normalized();
  Vec forward = Vec::Zero();
  for (Eigen::Index t = 0; t < frames.rows(); ++t) {
    const auto rHip = jointAt(frames, t, Joint::RHip), lHip = jointAt(frames, t, Joint::LHip);
    if (!rHip || !lHip) continue;
    const Vec right = *rHip - *lHip;
    const Vec f = Y.cross(right);  // X = Y × Z
    if (f.norm() > 1e-9) forward += f.normalized();
  }
  const Vec horizontal = forward - forward.dot(Y) * Y;
  if (!(horizontal.norm() > 1e-9))
    throw Error(ErrorKind::BadData, name, "",
                "no frame has both hips off the up axis: the body's heading, and so the ground frame, is undefined");
  const Vec X = horizontal.normalized();
  Rot g;
  g << X, Y, X.cross(Y);
  return g;
}

void fillRow(JointAngles& out, Eigen::Index t, int column, const Eigen::VectorXd& values) {
  out.degrees.row(t).segment(column, values.size()) = values.transpose();
}

void anglesOfFrame(const Eigen::Ref<const Eigen::MatrixXd>& frames, Eigen::Index t, const Rot& ground,
                   JointAngles& out) {
  const auto trunk = trunkFrames(frames, t);
  if (const auto pelvis = jointAt(frames, t, Joint::Pelvis))
    out.pelvisM.row(t) = (ground.transpose() * *pelvis / 1000.0).transpose();
  if (!trunk) return;
  fillRow(out, t, 0, relativeAngles(ground, trunk->pelvis));
  fillRow(out, t, 3, relativeAngles(trunk->pelvis, trunk->thorax).tail<2>());
  const auto head = jointAt(frames, t, Joint::Head), sternum = jointAt(frames, t, Joint::Sternum);
  if (head && sternum) {
    if (const auto h = frameFromYZ(*head - *sternum, trunk->thorax.col(2))) {
      const Vec neck = relativeAngles(trunk->thorax, *h);
      fillRow(out, t, 5, Eigen::Vector2d(-neck(0), neck(1)));
    }
  }
  const std::array<std::pair<LimbJoints, bool>, 4> limbs = {{{kRightLeg, false}, {kLeftLeg, true},
                                                              {kRightArm, false}, {kLeftArm, true}}};
  for (int i = 0; i < 4; ++i) {
    const bool arm = i >= 2;
    const Rot& parent = arm ? trunk->thorax : trunk->pelvis;
    if (const auto a = limbAngles(frames, t, parent, limbs[i].first, limbs[i].second, arm)) fillRow(out, t, 7 + 4 * i, *a);
  }
}

std::optional<Vec> footPointAt(const Eigen::Ref<const Eigen::MatrixXd>& feet, Eigen::Index t, FootPoint p) {
  const Vec v = feet.row(t).segment<3>(3 * index(p)).transpose();
  if (!v.allFinite()) return std::nullopt;
  return v;
}

// Ankle flexion and foot progression of one side at frame t (NaN where a point is missing).
Eigen::Vector2d footAnglesOfFrame(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                  const Eigen::Ref<const Eigen::MatrixXd>& feet, Eigen::Index t,
                                  const Rot& ground, Side side) {
  Eigen::Vector2d out = Eigen::Vector2d::Constant(std::numeric_limits<double>::quiet_NaN());
  const bool left = side == Side::Left;
  const auto heel = footPointAt(feet, t, heelOf(side)), toe = footPointAt(feet, t, toeOf(side));
  if (!heel || !toe) return out;
  const Vec foot = *toe - *heel;
  if (!(foot.norm() > 1e-9)) return out;
  const auto knee = jointAt(frames, t, left ? Joint::LKnee : Joint::RKnee);
  const auto ankle = jointAt(frames, t, left ? Joint::LAnkle : Joint::RAnkle);
  if (knee && ankle && (*knee - *ankle).norm() > 1e-9) {
    const Vec shank = (*knee - *ankle).normalized();
    out(0) = 90.0 - std::acos(std::clamp(shank.dot(foot.normalized()), -1.0, 1.0)) * kDeg;
  }
  const double forward = foot.dot(ground.col(0)), right = foot.dot(ground.col(2));
  if (std::hypot(forward, right) > 1e-9) out(1) = std::atan2(left ? -right : right, forward) * kDeg;
  return out;
}

std::string formatNumber(double v) {
  if (!std::isfinite(v)) return "nan";
  if (v == 0.0) return "0";  // not "-0"
  std::ostringstream s;
  s << std::setprecision(8) << v;
  return s.str();
}

}  // namespace

const std::vector<std::string>& jointAngleNames() {
  static const std::vector<std::string> names = {
      "pelvis_tilt",     "pelvis_list",     "pelvis_rotation", "lumbar_bending",  "lumbar_rotation",
      "neck_flexion",    "neck_bending",    "hip_flexion_r",   "hip_adduction_r", "hip_rotation_r",
      "knee_angle_r",    "hip_flexion_l",   "hip_adduction_l", "hip_rotation_l",  "knee_angle_l",
      "arm_flex_r",      "arm_add_r",       "arm_rot_r",       "elbow_flex_r",    "arm_flex_l",
      "arm_add_l",       "arm_rot_l",       "elbow_flex_l"};
  return names;
}

JointAngles jointAngles(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, const Eigen::Vector3d& upMm,
                        const std::string& name) {
  if (framesMm.cols() != 3 * kJointCount)
    throw Error(ErrorKind::BadArgument, name, "",
                "joint angles need 45 columns (15 joints × x, y, z), got " + std::to_string(framesMm.cols()));
  if (!upMm.allFinite() || !(upMm.norm() > 0.0))
    throw Error(ErrorKind::BadArgument, name, "", "the up direction for the joint angles is zero or not finite");
  JointAngles out;
  out.names = jointAngleNames();
  const Eigen::Index T = framesMm.rows();
  out.degrees = Eigen::MatrixXd::Constant(T, static_cast<Eigen::Index>(out.names.size()),
                                          std::numeric_limits<double>::quiet_NaN());
  out.pelvisM = Eigen::MatrixXd::Constant(T, 3, std::numeric_limits<double>::quiet_NaN());
  if (T == 0) return out;
  const Rot ground = groundFrame(framesMm, upMm, name);
  for (Eigen::Index t = 0; t < T; ++t) anglesOfFrame(framesMm, t, ground, out);
  return out;
}

const std::vector<std::string>& footAngleNames() {
  static const std::vector<std::string> names = {"ankle_angle_r", "foot_progression_r", "ankle_angle_l",
                                                 "foot_progression_l"};
  return names;
}

JointAngles jointAnglesWithFeet(const Eigen::Ref<const Eigen::MatrixXd>& framesMm,
                                const Eigen::Ref<const Eigen::MatrixXd>& feetMm, const Eigen::Vector3d& upMm,
                                const std::string& name) {
  JointAngles out = jointAngles(framesMm, upMm, name);
  const Eigen::Index T = framesMm.rows(), first = out.degrees.cols();
  out.names.insert(out.names.end(), footAngleNames().begin(), footAngleNames().end());
  out.degrees.conservativeResize(T, static_cast<Eigen::Index>(out.names.size()));
  out.degrees.rightCols(4).setConstant(std::numeric_limits<double>::quiet_NaN());
  if (T == 0 || feetMm.rows() != T || feetMm.cols() != kFootDims3) return out;
  const Rot ground = groundFrame(framesMm, upMm, name);
  for (Eigen::Index t = 0; t < T; ++t) {
    out.degrees.row(t).segment<2>(first) = footAnglesOfFrame(framesMm, feetMm, t, ground, Side::Right).transpose();
    out.degrees.row(t).segment<2>(first + 2) = footAnglesOfFrame(framesMm, feetMm, t, ground, Side::Left).transpose();
  }
  return out;
}

Eigen::Vector3d bodyUp(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, double snapDegrees) {
  Vec sum = Vec::Zero();
  for (Eigen::Index t = 0; t < framesMm.rows(); ++t) {
    const auto head = jointAt(framesMm, t, Joint::Head), r = jointAt(framesMm, t, Joint::RAnkle),
               l = jointAt(framesMm, t, Joint::LAnkle);
    if (!head || !r || !l) continue;
    const Vec up = *head - 0.5 * (*r + *l);
    if (up.norm() > 1e-9) sum += up.normalized();
  }
  if (!(sum.norm() > 1e-12)) return Vec::Zero();
  const Vec up = sum.normalized();
  Eigen::Index axis = 0;
  up.cwiseAbs().maxCoeff(&axis);
  if (std::abs(up(axis)) >= std::cos(snapDegrees / kDeg)) return Vec::Unit(axis) * (up(axis) > 0.0 ? 1.0 : -1.0);
  return up;
}

void writeJointAngles(const std::string& file, const JointAngles& angles, double rateHz,
                      const std::vector<std::string>& comments) {
  const std::string ext = std::filesystem::path(file).extension().string();
  const bool mot = ext == ".mot";
  if (!mot && ext != ".csv")
    throw Error(ErrorKind::BadArgument, file, "", "joint angles are written as .csv or .mot (OpenSim), not '" + ext + "'");
  if (!(rateHz > 0.0)) throw Error(ErrorKind::BadArgument, file, "", "the frame rate must be positive");
  std::vector<std::string> columns = angles.names;
  for (const char* c : {"pelvis_tx", "pelvis_ty", "pelvis_tz"}) columns.emplace_back(c);
  const std::string sep = mot ? "\t" : ",";
  writeFileAtomically(file, [&](std::ostream& os) {
    const Eigen::Index T = angles.degrees.rows();
    if (mot) {
      os << std::filesystem::path(file).stem().string() << "\nversion=1\nnRows=" << T
         << "\nnColumns=" << columns.size() + 1 << "\ninDegrees=yes\n";
      for (const auto& c : comments) os << c << "\n";
      os << "endheader\n";
    } else {
      for (const auto& c : comments) os << "# " << c << "\n";
    }
    os << (mot ? "time" : "time_s");
    for (const auto& c : columns) os << sep << c;
    os << "\n";
    for (Eigen::Index t = 0; t < T; ++t) {
      os << formatNumber(static_cast<double>(t) / rateHz);
      for (Eigen::Index k = 0; k < angles.degrees.cols(); ++k) os << sep << formatNumber(angles.degrees(t, k));
      for (Eigen::Index k = 0; k < 3; ++k) os << sep << formatNumber(angles.pelvisM(t, k));
      os << "\n";
    }
  });
}

}  // namespace ew
