#pragma once
// Joints a trial did not measure at all (JointTrial::missing: NaN in every frame), as
// opposed to gaps (a joint hidden for some frames, core/gait/gaps.h). Missing joints are
// estimated from a model (core/engine/joint_completion.h), never interpolated.
//
// Minimum (kMinimumMeasured): both hips — the heading of SPEC §2 is z × (r_hip − l_hip) —
// and both ankles — the floor, the gait cycles and the phase reference of SPEC §3
// (z_l_ankle − z_r_ankle). A missing pelvis is stood in for by the mid-hip while the
// canonical frame is made (prepare.cpp); every other joint may be missing.

#include <Eigen/Core>
#include <array>
#include <string>

#include "core/common/skeleton.h"
#include "core/common/trial.h"

namespace ew {

using JointMask = std::array<bool, kJointCount>;

inline constexpr std::array<Joint, 4> kMinimumMeasured = {Joint::RHip, Joint::LHip, Joint::RAnkle,
                                                          Joint::LAnkle};

bool anyJoint(const JointMask& mask);
int jointCount(const JointMask& mask);
// "head, sternum, r_wrist" (SPEC §1 names, joint order); "" for an empty mask.
std::string jointList(const JointMask& mask);

// Joints without one finite sample in any frame of a T × 45 (3D) or T × 30 (2D) matrix;
// other widths give an empty mask.
JointMask jointsMissingThroughout(const Eigen::Ref<const Eigen::MatrixXd>& frames);

// The trial's missing joints: flagged in JointTrial::missing, or without one finite
// sample in any frame (a CSV or a mapping that left the columns empty).
JointMask missingJointsOf(const JointTrial& trial);

// Throws Error(BadData) "<stage>: too few joints measured to estimate the rest: r_hip
// missing (needs both hips and both ankles; missing in every frame: …)" naming `file`
// when a joint of kMinimumMeasured is missing.
void requireMinimumMeasured(const JointMask& missing, const std::string& file,
                            const std::string& stage);

}  // namespace ew
