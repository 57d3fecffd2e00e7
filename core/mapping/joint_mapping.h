#pragma once
// From a file's own points to the 15 joints of METHOD §1.

#include "core/common/trial.h"

namespace ew {

// Dispatches on RawTrial::kind: canonical joints pass through, skeleton joints go through
// mapSkeletonJoints (BVH/ASF naming), markers through mapMarkerSet. Throws
// Error(UnknownMarkerSet) listing the labels found and what is needed.
JointTrial toJointTrial(const RawTrial& raw);

// Skin markers -> 15 joints, for the marker sets in core/mapping/marker_sets.h.
JointTrial mapMarkerSet(const RawTrial& raw);

// Skeleton joint centres (BVH / ASF) -> 15 joints: CMU and Mixamo-style names.
JointTrial mapSkeletonJoints(const RawTrial& raw);

// METHOD §1 head rule, shared by every mapping that lacks head points: the head centre is
// placed on the pelvis->sternum axis, above the sternum, at kHeadFractionOfTrunk of the
// pelvis-sternum distance. 0.30: in stature fractions (Drillis & Contini 1966; Winter 2009,
// fig. 4.1) the neck base (mid C7 / jugular notch) is at ~0.83 H, the head centre (ear
// level) at ~0.925 H and the hip-joint level at ~0.52 H, so head-above-sternum over trunk
// is ~0.095/0.31 = 0.3 (about 165 mm for H = 1.75 m). The CMU skeletons, which do measure
// the head, give 126-147 mm over a 530-560 mm trunk (0.24-0.27): the rule keeps estimated
// heads of marker-based sources where the measured ones are, so a mixed-source model does
// not learn "source" as a head-height component.
inline constexpr double kHeadFractionOfTrunk = 0.30;
Eigen::Vector3d estimateHead(const Eigen::Vector3d& pelvis, const Eigen::Vector3d& sternum);

// Fills JointTrial fields common to all mappings (file, format, rate, units, events,
// warnings, source labels) from the raw trial.
JointTrial jointTrialShell(const RawTrial& raw, std::string source, int frames);

}  // namespace ew
