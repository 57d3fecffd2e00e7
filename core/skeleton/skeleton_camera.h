#pragma once
// The skeleton engine through a calibrated pinhole camera (Zou et al. 2009, §3.3): pixels
// with the lens distortion taken out become rays from the centre of projection, the
// pelvis is put at the depth the bone lengths allow, the tree is placed and its branches
// chosen over the clip (skeleton_solve.h), and — when the calibration has extrinsics — the
// result is carried into the calibration's world frame.
//
// The pelvis depth (§3.3.2 estimates a scale–depth relation T(dz) from a special frame
// instead): no bone can look longer than it is, so a bone whose two rays are φ apart lies
// no farther than L / sin φ; the tightest of the 14 bounds (a bone nearly parallel to the
// image plane) is the depth, up to 1/cos of that bone's tilt. A running median over the
// clip takes out single-frame noise.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/camera/calibration_file.h"
#include "core/skeleton/skeleton_solve.h"

namespace ew {

// R of a Rodrigues vector (axis × angle).
Eigen::Matrix3d rotationFromRodrigues(const std::array<double, 3>& rotation);

PinholeIntrinsics intrinsicsOf(const CalibratedCamera& camera);

// The tightest bone bound on the pelvis's distance along its ray, per frame (mm); then a
// running median over `windowFrames` (odd; 1 = none).
std::vector<double> rootDistancesFromBones(const std::vector<JointRays>& rays, const BoneLengths& bones,
                                           int windowFrames);

struct SkeletonCameraOptions {
  SkeletonSolveOptions solve;   // its upMm is replaced by the image's up (the median
                                // pelvis → sternum direction), in the camera frame
  double depthWindowS = 0.25;   // the running median of the pelvis depth
};

struct SkeletonCameraResult {
  SkeletonSequence sequence;            // camera frame: x right, y down, z forward (mm)
  Eigen::MatrixXd worldMm;              // T × 45 in the calibration's world frame (empty without extrinsics)
  std::vector<double> rootDistanceMm;   // the pelvis's distance along its ray, per frame
  int filledPoints = 0;                 // joint-frames not seen, interpolated over time
};

// jointsPx: T × 30 (u, v per joint, METHOD §1 order; NaN = not seen). A joint missing in
// some frames is interpolated over time (held at the ends). Throws Error(BadData) naming
// `name` and the joint for a joint never seen, Error(BadArgument) for no frames or a bad rate.
SkeletonCameraResult reconstructThroughCamera(const Eigen::Ref<const Eigen::MatrixXd>& jointsPx,
                                              const CalibratedCamera& camera, const BoneLengths& bones,
                                              double rateHz, const std::string& name,
                                              const SkeletonCameraOptions& options = {});

}  // namespace ew

namespace ew {

// A reconstruction in a calibration's world frame against a 3D reference of the same
// frames (the same rate, frame 0 = frame 0), e.g. the triangulated keypoints of the other
// cameras. The reference's axes may be any of the 24 right-handed signed permutations of
// the world's (Pose2Sim writes its TRC Y-up, (x, y, z) = world (y, z, x)): the one that
// fits best after removing the mean translation is used and reported.
struct ReferenceComparison {
  Eigen::Matrix3d referenceToWorld = Eigen::Matrix3d::Identity();
  int frames = 0;                      // frames both have (every joint finite)
  double rawMm = 0.0;                  // MPJPE as reconstructed
  double meanTranslationMm = 0.0;      // after removing the clip's mean offset
  double procrustesMm = 0.0;           // after each frame's best rotation and translation (no scale)
  std::array<double, kJointCount> perJointMm{};  // mean-translation MPJPE per joint
};

// Both T × 45 mm. Throws Error(BadData) naming `name` when no frame has every joint in both.
ReferenceComparison compareWithReference(const Eigen::Ref<const Eigen::MatrixXd>& worldMm,
                                         const Eigen::Ref<const Eigen::MatrixXd>& referenceMm,
                                         const std::string& name);

}  // namespace ew
