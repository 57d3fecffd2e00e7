#include "core/skeleton/skeleton_tree.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/common/errors.h"
#include "core/common/statistics.h"

namespace ew {

namespace {

Eigen::Vector3d jointOf(const Eigen::Ref<const Eigen::MatrixXd>& frames, Eigen::Index t, Joint j) {
  return frames.row(t).segment<3>(3 * index(j)).transpose();
}

}  // namespace

BoneLengths boneLengthsFromFrames(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, const std::string& name) {
  if (framesMm.cols() != kDims3) {
    throw Error(ErrorKind::BadArgument, name, "", "bone lengths need T × 45 frames, got " +
                                                      std::to_string(framesMm.cols()) + " columns");
  }
  BoneLengths bones;
  for (int b = 0; b < kBoneCount; ++b) {
    const auto [a, c] = kBones[static_cast<size_t>(b)];
    std::vector<double> lengths;
    for (Eigen::Index t = 0; t < framesMm.rows(); ++t) {
      const double l = (jointOf(framesMm, t, a) - jointOf(framesMm, t, c)).norm();
      if (std::isfinite(l)) lengths.push_back(l);
    }
    if (lengths.empty()) {
      throw Error(ErrorKind::BadData, name, "",
                  "no frame sees both ends of the bone " + std::string(jointName(a)) + "–" +
                      std::string(jointName(c)) + ", so its length is unknown");
    }
    bones.mm[static_cast<size_t>(b)] = median(std::move(lengths));
  }
  return bones;
}

Eigen::MatrixXd withBoneLengths(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, const BoneLengths& bones) {
  Eigen::MatrixXd out = framesMm;
  for (Eigen::Index t = 0; t < out.rows(); ++t) {
    for (const TreeBone& tb : kTreeOrder) {
      const Eigen::Vector3d along = jointOf(framesMm, t, tb.child) - jointOf(framesMm, t, tb.parent);
      const Eigen::Vector3d parent = out.row(t).segment<3>(3 * index(tb.parent)).transpose();
      out.row(t).segment<3>(3 * index(tb.child)) =
          (parent + along.normalized() * bones.mm[static_cast<size_t>(tb.bone)]).transpose();
    }
  }
  return out;
}

JointRays pinholeRays(const Eigen::Ref<const Eigen::RowVectorXd>& uvPx, const PinholeIntrinsics& camera) {
  JointRays rays;
  rays.origin.setZero();
  for (int j = 0; j < kJointCount; ++j) {
    const Eigen::Vector3d d((uvPx(2 * j) - camera.cxPx) / camera.fxPx, (uvPx(2 * j + 1) - camera.cyPx) / camera.fyPx,
                            1.0);
    rays.direction.col(j) = d.normalized();
  }
  return rays;
}

JointRays orthographicRays(const Eigen::Ref<const Eigen::RowVectorXd>& uvMm) {
  JointRays rays;
  for (int j = 0; j < kJointCount; ++j) {
    rays.origin.col(j) = Eigen::Vector3d(uvMm(2 * j), 0.0, uvMm(2 * j + 1));
    rays.direction.col(j) = Eigen::Vector3d::UnitY();
  }
  return rays;
}

RayRoots rootsOnRay(const JointRays& rays, int joint, const Eigen::Vector3d& parentMm, double lengthMm) {
  const Eigen::Vector3d toParent = parentMm - rays.origin.col(joint);
  RayRoots r;
  r.t0 = rays.direction.col(joint).dot(toParent);
  const double disc = lengthMm * lengthMm - (toParent.squaredNorm() - r.t0 * r.t0);
  r.clamped = disc < 0.0;
  r.halfGap = disc > 0.0 ? std::sqrt(disc) : 0.0;
  return r;
}

TreePlacement placeTree(const JointRays& rays, const Eigen::Vector3d& rootMm, const BoneLengths& bones,
                        const std::array<int, kBoneCount>& signs) {
  TreePlacement p;
  p.joints.col(index(Joint::Pelvis)) = rootMm;
  for (const TreeBone& tb : kTreeOrder) {
    const int c = index(tb.child);
    const auto b = static_cast<size_t>(tb.bone);
    const RayRoots r = rootsOnRay(rays, c, p.joints.col(index(tb.parent)), bones.mm[b]);
    p.clamped[b] = r.clamped;
    p.halfGapMm[b] = r.halfGap;
    p.joints.col(c) = rays.origin.col(c) + (r.t0 + signs[b] * r.halfGap) * rays.direction.col(c);
  }
  return p;
}

std::array<int, kBoneCount> branchSigns(const JointRays& rays, const JointMatrix& joints) {
  std::array<int, kBoneCount> signs{};
  for (const TreeBone& tb : kTreeOrder) {
    const int c = index(tb.child);
    const double t0 = rootsOnRay(rays, c, joints.col(index(tb.parent)), 0.0).t0;
    const double t = rays.direction.col(c).dot(joints.col(c) - rays.origin.col(c));
    signs[static_cast<size_t>(tb.bone)] = t >= t0 ? 1 : -1;
  }
  return signs;
}

int boneBetween(Joint a, Joint b) {
  for (std::size_t i = 0; i < kBones.size(); ++i)
    if ((kBones[i].first == a && kBones[i].second == b) || (kBones[i].first == b && kBones[i].second == a))
      return static_cast<int>(i);
  return -1;
}

}  // namespace ew
