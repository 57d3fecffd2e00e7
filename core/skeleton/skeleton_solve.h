#pragma once
// A whole sequence reconstructed from geometry alone (Zou et al. 2009, §3.3.3): each frame
// placed depth-first along the tree (skeleton_tree.h). The paper picks one of each bone's
// two depths frame by frame; here the choice is made over the whole clip, in two stages.
//
// 1. Continuity, per bone: its depth offset δ(t) = ±g(t) must be smooth. Where the bone
//    turns through the image plane g touches 0 and δ crosses it with a steady slope; where
//    it only approaches the plane, δ turns back. Minimising the squared second difference of
//    δ over the sign sequences (Viterbi) gives each bone's branch over the clip up to one
//    sign.
// 2. Plausibility, over the clip: those 14 signs (2¹⁴ choices) are chosen by the least total
//    implausibility of the whole clip — hips not symmetric about the pelvis, the shoulder
//    line not along the hip line, the head not continuing the trunk, the trunk leaning
//    backward, a knee or an elbow bent against its hinge — searched as the torso's 64
//    choices, each with every limb's best of 4 given that torso. Each cost is unitless
//    (squared sines, 1 − cos); a hinge bent the wrong way by θ costs hingeWeight·sin²θ.
//
// "Up" (which way the body's head points in the rays' frame) makes "forward" and "leaning
// backward" mean something: an orthographic view frame's V, a level camera's −y.
//
// A guide replaces both stages (beyond the paper, which names a learnt prior as the way to
// choose): a pose per frame in the rays' frame — the eigenwalker's reconstruction of the
// same clip — and each bone, placed depth-first, takes the root whose bone vector is
// nearer the guide's (child − parent). Only the guide's bone directions matter, not where
// it stands, so a guide from an estimated camera a degree off still chooses well.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/skeleton/skeleton_tree.h"

namespace ew {

struct SkeletonSolveOptions {
  double hingeWeight = 10.0;     // knee and elbow bent against their hinge
  double symmetryWeight = 10.0;  // hips, shoulders, head and trunk lean (above)
  Eigen::Vector3d upMm{0.0, 0.0, 1.0};  // the body's up in the rays' frame (any length)
  std::vector<JointMatrix> guideMm;     // empty, or one pose per frame in the rays' frame
};

struct SkeletonSequence {
  Eigen::MatrixXd framesMm;                         // T × 45 in the rays' frame (mm)
  std::vector<std::array<int, kBoneCount>> signs;   // per frame, the branch of every bone
  std::array<int, kBoneCount> clampedFrames{};      // per bone, frames where it was clamped
  int clampedBoneFrames = 0;
  Eigen::VectorXd poseCost;                         // per frame, the chosen pose's implausibility (weighted)
};

// rays: one per frame; rootsMm: the pelvis of each frame (on its ray); rateHz > 0.
// Throws Error(BadArgument) for unequal lengths, no frames or a bad rate, and
// Error(BadData) naming the joint and frame for a ray that is not finite (an unseen joint),
// Error(BadArgument) for a guide that is not one finite pose per frame.
SkeletonSequence solveSkeletonSequence(const std::vector<JointRays>& rays, const std::vector<Eigen::Vector3d>& rootsMm,
                                       const BoneLengths& bones, double rateHz,
                                       const SkeletonSolveOptions& options = {});

}  // namespace ew
