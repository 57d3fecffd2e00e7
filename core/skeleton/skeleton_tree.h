#pragma once
// The 15-joint skeleton as a tree rooted at the pelvis, for reconstructing a pose from
// geometry alone (Zou et al. 2009, §3.1 and §3.3.3): every joint lies on its image ray,
// every bone keeps its length, and the joints are placed depth-first from the root.
//
// A joint's ray is P(t) = origin + t·direction (direction unit length): a pinhole camera's
// rays start at the centre of projection, an orthographic view's are parallel. With the
// parent P_p placed, the bone length L gives the quadratic of Zou et al.'s eq. 5,
//   |origin + t·direction − P_p|² = L²  ⇒  t = t₀ ± √(L² − ρ²),
//   t₀ = direction·(P_p − origin),  ρ = distance from P_p to the ray,
// two depths per bone (sign +: farther along the ray than the point nearest the parent).
// When ρ > L the bone looks longer than it can be (noise, a wrong length): the joint is
// clamped to t₀ and the bone counted as clamped.

#include <Eigen/Core>
#include <array>
#include <string>

#include "core/common/skeleton.h"

namespace ew {

inline constexpr int kBoneCount = static_cast<int>(kBones.size());  // 14

// The tree in depth-first order from the pelvis: each entry places `child` from `parent`
// along bone `bone` (an index into kBones).
struct TreeBone {
  Joint parent;
  Joint child;
  int bone;
};
inline constexpr std::array<TreeBone, kBoneCount> kTreeOrder = {{
    {Joint::Pelvis, Joint::Sternum, 1},
    {Joint::Sternum, Joint::Head, 0},
    {Joint::Sternum, Joint::RShoulder, 2},
    {Joint::Sternum, Joint::LShoulder, 3},
    {Joint::Pelvis, Joint::RHip, 8},
    {Joint::Pelvis, Joint::LHip, 9},
    {Joint::RShoulder, Joint::RElbow, 4},
    {Joint::RElbow, Joint::RWrist, 5},
    {Joint::LShoulder, Joint::LElbow, 6},
    {Joint::LElbow, Joint::LWrist, 7},
    {Joint::RHip, Joint::RKnee, 10},
    {Joint::RKnee, Joint::RAnkle, 11},
    {Joint::LHip, Joint::LKnee, 12},
    {Joint::LKnee, Joint::LAnkle, 13},
}};

// The index into kBones of the bone between a and b (either order); −1 when none.
int boneBetween(Joint a, Joint b);

// Lengths of the 14 bones of kBones, mm.
struct BoneLengths {
  std::array<double, kBoneCount> mm{};
};

// Each bone's median length over the frames that see both its joints (T × 45, mm).
// Throws Error(BadData) naming `name` and the bone when no frame sees it.
BoneLengths boneLengthsFromFrames(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, const std::string& name);

// The frames with every bone set to `bones` (T × 45): each child is moved along its bone's
// direction from its (already moved) parent, depth-first from the pelvis. A skeleton that
// is rigid in the sense the geometry assumes; used to build exact test cases.
Eigen::MatrixXd withBoneLengths(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, const BoneLengths& bones);

using JointMatrix = Eigen::Matrix<double, 3, kJointCount>;  // one column per joint

struct JointRays {
  JointMatrix origin;
  JointMatrix direction;  // unit vectors
};

// Pinhole intrinsics in pixels (x right, y down); the camera frame is x right, y down,
// z forward (along the optical axis), mm.
struct PinholeIntrinsics {
  double fxPx = 1000.0, fyPx = 1000.0;
  double cxPx = 0.0, cyPx = 0.0;
};

// The rays of one frame's 30 pixel coordinates (u, v per joint).
JointRays pinholeRays(const Eigen::Ref<const Eigen::RowVectorXd>& uvPx, const PinholeIntrinsics& camera);
// The rays of an orthographic view (METHOD §5): u, v in mm (v up), in the view's frame
// (U along the image's horizontal, D the depth away from the camera, V up): origin
// (u, 0, v), direction (0, 1, 0).
JointRays orthographicRays(const Eigen::Ref<const Eigen::RowVectorXd>& uvMm);

// Eq. 5 for one bone: where along `joint`'s ray the points at `lengthMm` from `parentMm`
// are, t₀ ± halfGap (halfGap 0 and `clamped` when the ray passes farther than the length).
struct RayRoots {
  double t0 = 0.0;
  double halfGap = 0.0;
  bool clamped = false;
};
RayRoots rootsOnRay(const JointRays& rays, int joint, const Eigen::Vector3d& parentMm, double lengthMm);

// One frame placed depth-first with the root at `rootMm` and the sign of every bone's
// root (signs[bone] = +1 or −1, indexed as kBones). Reports which bones were clamped and,
// for each bone, half the distance between its two roots (√(L² − ρ²), 0 when clamped).
struct TreePlacement {
  JointMatrix joints;
  std::array<bool, kBoneCount> clamped{};
  std::array<double, kBoneCount> halfGapMm{};
};
TreePlacement placeTree(const JointRays& rays, const Eigen::Vector3d& rootMm, const BoneLengths& bones,
                        const std::array<int, kBoneCount>& signs);

// The sign of each bone of a known pose along the given rays (+1 when the child is farther
// along its ray than the point nearest its parent): the branch the truth is on.
std::array<int, kBoneCount> branchSigns(const JointRays& rays, const JointMatrix& joints);

}  // namespace ew
