#pragma once
// Joints a trial did not measure at all (JointTrial::missing: NaN in every frame), as
// opposed to gaps (a joint hidden for some frames, core/gait/gaps.h). Missing joints are
// estimated from a model (core/eigenwalker/joint_completion.h), never interpolated.
//
// Minimum to prepare a trial (METHOD §2-3) and estimate the rest:
//   - both ankles: the floor, the gait cycles and the phase reference z_l_ankle − z_r_ankle;
//   - a left-right pair for the heading z × (right − left): both hips, else both knees;
//   - a body centre for the progression and the steady window: the pelvis, else the
//     mid-hip (both hips).
// While the canonical frame is made, a missing pelvis is stood in for by the mid-hip and a
// missing hip by the knee of its side (prepare.cpp). The marker-set minimum of
// docs/JOINTS.md (pelvis, both knees, both ankles) satisfies this one.

#include <Eigen/Core>
#include <array>
#include <string>

#include "core/common/skeleton.h"
#include "core/common/trial.h"

namespace ew {

using JointMask = std::array<bool, kJointCount>;

bool anyJoint(const JointMask& mask);
int jointCount(const JointMask& mask);
// "head, sternum, r_wrist" (METHOD §1 names, joint order); "" for an empty mask.
std::string jointList(const JointMask& mask);

// Joints without one finite sample in any frame of a T × 45 (3D) or T × 30 (2D) matrix;
// other widths give an empty mask.
JointMask jointsMissingThroughout(const Eigen::Ref<const Eigen::MatrixXd>& frames);

// The trial's missing joints: flagged in JointTrial::missing, or without one finite
// sample in any frame (a CSV or a mapping that left the columns empty).
JointMask missingJointsOf(const JointTrial& trial);

// The joints whose absence breaks the minimum above; an empty mask when it is met.
JointMask lackingForMinimum(const JointMask& missing);

// Throws Error(BadData) "<stage>: too few joints measured to estimate the rest: r_hip,
// r_knee missing (needs both ankles, both hips or both knees, and the pelvis or both hips;
// missing in every frame: …)" naming `file` when the minimum above is not met.
void requireMinimumMeasured(const JointMask& missing, const std::string& file,
                            const std::string& stage);

}  // namespace ew
