#include "core/gait/canonical_frame.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/common/errors.h"

namespace ew {
namespace {

// These work on frames already checked by their caller (prepare.cpp); an empty matrix here
// is a programming error, reported as one rather than read out of bounds.
void requireFrames(const Eigen::MatrixXd& m, const char* what) {
  if (m.rows() == 0 || m.cols() < kDims3 || m.cols() % 3 != 0) {
    throw Error(
        ErrorKind::BadArgument, "", "",
        std::string("canonical frame: ") + what + " needs at least one frame of 45 columns");
  }
}

// The 15 joints and any points carried after them (3 columns each).
int pointsIn(const Eigen::MatrixXd& m) { return static_cast<int>(m.cols() / 3); }

Eigen::Vector3d meanJoint(const Eigen::MatrixXd& m, Joint j) {
  return m.middleCols<3>(3 * index(j)).colwise().mean().transpose();
}

}  // namespace

SignedAxis detectUpAxis(const Eigen::MatrixXd& m) {
  requireFrames(m, "the up axis");
  const Eigen::Vector3d ankles = 0.5 * (meanJoint(m, Joint::LAnkle) + meanJoint(m, Joint::RAnkle));
  const Eigen::Vector3d up = meanJoint(m, Joint::Head) - ankles;
  Eigen::Index axis = 0;
  up.cwiseAbs().maxCoeff(&axis);
  return SignedAxis{static_cast<int>(axis), up[axis] >= 0 ? 1 : -1};
}

Eigen::Matrix3d rotationToZUp(const SignedAxis& up) {
  Eigen::Vector3d from = Eigen::Vector3d::Zero();
  from[up.axis] = up.sign;
  if (from.isApprox(-Eigen::Vector3d::UnitZ())) {
    // FromTwoVectors picks an arbitrary axis for opposite vectors; fix it to x.
    return Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  }
  return Eigen::Quaterniond::FromTwoVectors(from, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

void rotateFrames(Eigen::MatrixXd& m, const Eigen::Matrix3d& rotation) {
  for (int j = 0; j < pointsIn(m); ++j) {
    m.middleCols<3>(3 * j) = m.middleCols<3>(3 * j) * rotation.transpose();
  }
}

Eigen::Vector2d facingDirection(const Eigen::MatrixXd& m) {
  const Eigen::MatrixXd right =
      m.middleCols<3>(3 * index(Joint::RHip)) - m.middleCols<3>(3 * index(Joint::LHip));
  // z x (rx, ry, rz) = (-ry, rx, 0): the horizontal forward direction.
  Eigen::Vector2d sum(-right.col(1).sum(), right.col(0).sum());
  const double norm = sum.norm();
  return norm > 0 ? Eigen::Vector2d(sum / norm) : Eigen::Vector2d::Zero();
}

double rotateFacingToY(Eigen::MatrixXd& m) {
  const Eigen::Vector2d f = facingDirection(m);
  if (f.isZero()) return 0.0;
  // Rotate by the angle taking f to +y.
  const double angle = std::atan2(f.x(), f.y());
  rotateFrames(m, Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix());
  return angle;
}

Eigen::Vector2d removeProgression(Eigen::MatrixXd& m, double rateHz) {
  requireFrames(m, "removing progression");
  if (m.rows() < 2 || !(rateHz > 0)) {
    throw Error(ErrorKind::BadArgument, "", "",
                "canonical frame: removing progression needs two frames and a rate");
  }
  const Eigen::Index frames = m.rows();
  Eigen::MatrixXd design(frames, 2);
  for (Eigen::Index r = 0; r < frames; ++r) {
    design(r, 0) = 1.0;
    design(r, 1) = static_cast<double>(r) / rateHz;
  }
  const Eigen::MatrixXd pelvisXY = m.middleCols<2>(3 * index(Joint::Pelvis));
  const Eigen::MatrixXd coef = design.colPivHouseholderQr().solve(pelvisXY);  // 2 x 2
  const Eigen::MatrixXd trend = design * coef;
  for (int j = 0; j < pointsIn(m); ++j) m.middleCols<2>(3 * j) -= trend;
  return coef.row(1).transpose();
}

void placeOnFloor(Eigen::MatrixXd& m) {
  requireFrames(m, "placing on the floor");
  const Eigen::Index frames = m.rows();
  std::vector<double> lowest(static_cast<size_t>(frames));
  for (Eigen::Index r = 0; r < frames; ++r) {
    lowest[static_cast<size_t>(r)] =
        std::min(m(r, 3 * index(Joint::LAnkle) + 2), m(r, 3 * index(Joint::RAnkle) + 2));
  }
  const auto k = static_cast<size_t>(std::floor(0.05 * static_cast<double>(frames - 1)));
  std::nth_element(lowest.begin(), lowest.begin() + static_cast<long>(k), lowest.end());
  const double floorZ = lowest[k];
  for (int j = 0; j < pointsIn(m); ++j) m.col(3 * j + 2).array() -= floorZ;
}

}  // namespace ew
