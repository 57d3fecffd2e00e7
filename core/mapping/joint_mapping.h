#pragma once
// From a file's own points to the 15 joints of SPEC §1.

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

// SPEC §1 head rule, shared by every mapping that lacks head points: the head centre is
// placed on the pelvis->sternum axis, above the sternum, at kHeadFractionOfTrunk of the
// pelvis-sternum distance. 0.45: jugular notch to head centre (~210-230 mm) over pelvis
// centre to jugular notch (~470-510 mm) in adult anthropometry (Winter 2009, Table 4.1).
inline constexpr double kHeadFractionOfTrunk = 0.45;
Eigen::Vector3d estimateHead(const Eigen::Vector3d& pelvis, const Eigen::Vector3d& sternum);

// Fills JointTrial fields common to all mappings (file, format, rate, units, events,
// warnings, source labels) from the raw trial.
JointTrial jointTrialShell(const RawTrial& raw, std::string source, int frames);

}  // namespace ew
