#pragma once
// BVH writer for 15-joint walkers (read back by readBvh + mapSkeletonJoints; opens in
// Blender). Skeleton, with Mixamo/CMU joint names the mapper knows:
//
//   Hips (root, at the pelvis; Xposition Yposition Zposition Zrotation Xrotation Yrotation)
//     LeftUpLeg (l_hip) > LeftLeg (l_knee) > LeftFoot (l_ankle) > End Site (toe tip)
//     RightUpLeg … likewise
//     Spine (pelvis) > Spine1 (sternum) > Neck (sternum) > Head (half-way to the head
//       centre) > End Site (as far beyond the head centre as Head is below it, so Head
//       and its End Site average to the head centre, as the mapper takes it)
//                      Spine1 > LeftShoulder (sternum) > LeftArm (l_shoulder) >
//                        LeftForeArm (l_elbow) > LeftHand (l_wrist) > End Site (fingertips)
//                      Spine1 > RightShoulder … likewise
//
// Every other joint has "Zrotation Xrotation Yrotation" (R = Rz·Rx·Ry, degrees). The rest
// pose stands upright (legs and arms hanging, facing −Z) with the walker's mean bone
// lengths as OFFSETs. Each frame's rotations turn every bone onto its measured direction
// (shortest arc from the parent's frame, so twist is inherited, not invented); the hips'
// rotation also aligns the pelvis's left-right axis. Forward kinematics therefore gives
// back each joint exactly when the walker's bone lengths are constant and its pelvis is
// the mid-point of the hips (true of the synthetic walkers; docs/SYNTHETIC.md).
//
// Axes: BVH is +Y up. Ours (METHOD §2) is x right, y forward, z up, so X = x, Y = z, Z = −y
// (a proper rotation; the walker faces −Z, as Blender's importer expects). Units: mm.

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>

namespace ew {

struct BvhWriteOptions {
  // Toe tips (frames × 6: right x,y,z, left x,y,z; same frame and units as the joints)
  // to point the feet; without them the feet keep the shank's rotation.
  std::optional<Eigen::MatrixXd> toesMm;
  int decimals = 6;  // channel values: 1e-6 mm / 1e-6° (FK error well under 1e-3 mm)
};

// BVH text for frames (T × 45, METHOD §1 order, mm, canonical axes) at rateHz.
// Throws Error(BadArgument) for a wrong shape, a non-positive rate, fewer than 1 frame
// or non-finite values.
std::string formatBvh(const Eigen::MatrixXd& framesX45, double rateHz,
                      const BvhWriteOptions& options = {});

// Writes formatBvh(...) atomically (temporary file, then rename).
void writeBvh(const std::filesystem::path& file, const Eigen::MatrixXd& framesX45, double rateHz,
              const BvhWriteOptions& options = {});

}  // namespace ew
