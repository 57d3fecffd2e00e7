#pragma once
// A synthetic walker with exactly rigid bones seen through a known pinhole camera: the
// skeleton engine's exact test cases (test_skeleton_solve.cpp, test_skeleton_camera.cpp).
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()
#include <cmath>

#include "core/skeleton/skeleton_tree.h"
#include "core/synth/population.h"

namespace ew {
namespace {

// A synthetic walker (overground, 30 Hz, 2 cycles) with every bone made exactly rigid.
struct RigidWalk {
  Eigen::MatrixXd framesMm;  // T × 45, x right, y forward, z up
  BoneLengths bones;
};

inline const RigidWalk& rigidWalk() {
  static const RigidWalk w = [] {
    PopulationOptions o;
    o.count = 1;
    o.simulation.rateHz = 30.0;
    o.simulation.cycles = 2;
    const SynthWalker walker = generatePopulation(o).front();
    RigidWalk out;
    out.bones = boneLengthsFromFrames(walker.trial.positionsMm, "SYN001");
    out.framesMm = withBoneLengths(walker.trial.positionsMm, out.bones);
    return out;
  }();
  return w;
}

// A camera 4.5 m from the middle of the walk, at azimuth `azimuthDeg` from the walker's
// right (0: a side view from the right), 1.2 m high, looking at the pelvis height.
struct Camera {
  Eigen::Matrix3d worldToCamera;
  Eigen::Vector3d centre;
  PinholeIntrinsics intrinsics{1400.0, 1400.0, 960.0, 540.0};
};

inline Camera cameraAt(const Eigen::MatrixXd& frames, double azimuthDeg) {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  for (Eigen::Index f = 0; f < frames.rows(); ++f) target += frames.row(f).segment<3>(3 * index(Joint::Pelvis)).transpose();
  target /= static_cast<double>(frames.rows());
  const double a = azimuthDeg * 3.14159265358979323846 / 180.0;
  Camera c;
  c.centre = target + Eigen::Vector3d(4500.0 * std::cos(a), -4500.0 * std::sin(a), 0.0);
  c.centre.z() = 1200.0;
  const Eigen::Vector3d z = (target - c.centre).normalized();
  const Eigen::Vector3d x = z.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d y = z.cross(x);
  c.worldToCamera.row(0) = x.transpose();
  c.worldToCamera.row(1) = y.transpose();
  c.worldToCamera.row(2) = z.transpose();
  return c;
}

inline JointMatrix inCamera(const Camera& c, const Eigen::MatrixXd& frames, Eigen::Index f) {
  JointMatrix j;
  for (int k = 0; k < kJointCount; ++k)
    j.col(k) = c.worldToCamera * (frames.row(f).segment<3>(3 * k).transpose() - c.centre);
  return j;
}

inline Eigen::RowVectorXd pixels(const Camera& c, const JointMatrix& j) {
  Eigen::RowVectorXd uv(kDims2);
  for (int k = 0; k < kJointCount; ++k) {
    uv(2 * k) = c.intrinsics.cxPx + c.intrinsics.fxPx * j(0, k) / j(2, k);
    uv(2 * k + 1) = c.intrinsics.cyPx + c.intrinsics.fyPx * j(1, k) / j(2, k);
  }
  return uv;
}

}  // namespace
}  // namespace ew
