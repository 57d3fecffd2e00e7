#include "core/skeleton/skeleton_camera.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/camera/lens_distortion.h"
#include "core/common/errors.h"
#include "core/common/statistics.h"
#include "core/gait/gaps.h"

namespace ew {

namespace {

std::vector<double> runningMedian(const std::vector<double>& x, int window) {
  const int half = std::max(0, window / 2);
  const int n = static_cast<int>(x.size());
  std::vector<double> out(x.size());
  for (int i = 0; i < n; ++i) {
    std::vector<double> w(x.begin() + std::max(0, i - half), x.begin() + std::min(n, i + half + 1));
    out[static_cast<size_t>(i)] = median(w);
  }
  return out;
}

// The body's up in the camera frame: the median image direction from pelvis to sternum.
Eigen::Vector3d imageUp(const Eigen::MatrixXd& px) {
  std::vector<double> du, dv;
  const Eigen::Index p = index(Joint::Pelvis), s = index(Joint::Sternum);
  for (Eigen::Index t = 0; t < px.rows(); ++t) {
    du.push_back(px(t, 2 * s) - px(t, 2 * p));
    dv.push_back(px(t, 2 * s + 1) - px(t, 2 * p + 1));
  }
  const Eigen::Vector3d up(median(du), median(dv), 0.0);
  return up.norm() > 0.0 ? up.normalized() : Eigen::Vector3d(0.0, -1.0, 0.0);
}

// The bones whose bound sets the depth: the long ones. The short ones (neck, clavicles,
// hips) are 40-60 px in a typical image, so a few pixels of detector offset — the
// shoulders' midpoint standing in for the sternum — move their bound by 10 % or more.
constexpr std::array<bool, kBoneCount> kDepthBones = {false, true, false, false, true, true, true,
                                                      true,  false, false, true, true, true, true};

}  // namespace

Eigen::Matrix3d rotationFromRodrigues(const std::array<double, 3>& rotation) {
  const Eigen::Vector3d r(rotation[0], rotation[1], rotation[2]);
  const double angle = r.norm();
  if (angle < 1e-15) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, r / angle).toRotationMatrix();
}

PinholeIntrinsics intrinsicsOf(const CalibratedCamera& c) { return {c.fxPx, c.fyPx, c.cxPx, c.cyPx}; }

std::vector<double> rootDistancesFromBones(const std::vector<JointRays>& rays, const BoneLengths& bones,
                                           int windowFrames) {
  std::vector<double> bound;
  bound.reserve(rays.size());
  for (const JointRays& r : rays) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t b = 0; b < kBones.size(); ++b) {
      if (!kDepthBones[b]) continue;
      const double sine = r.direction.col(index(kBones[b].first)).cross(r.direction.col(index(kBones[b].second))).norm();
      if (sine > 1e-12) best = std::min(best, bones.mm[b] / sine);
    }
    bound.push_back(best);
  }
  return runningMedian(bound, windowFrames);
}

SkeletonCameraResult reconstructThroughCamera(const Eigen::Ref<const Eigen::MatrixXd>& jointsPx,
                                              const CalibratedCamera& camera, const BoneLengths& bones,
                                              double rateHz, const std::string& name,
                                              const SkeletonCameraOptions& options) {
  if (jointsPx.rows() == 0 || jointsPx.cols() != 2 * kJointCount)
    throw Error(ErrorKind::BadArgument, name, "", "expected frames of 15 joints in pixels");
  if (!(rateHz > 0.0 && std::isfinite(rateHz))) throw Error(ErrorKind::BadArgument, name, "", "the rate must be positive");
  SkeletonCameraResult result;
  Eigen::MatrixXd px = jointsPx;
  undistortPixels(camera, px);  // a point outside the calibrated field becomes a gap
  for (int j = 0; j < kJointCount; ++j) {
    const auto unseen = static_cast<int>(px.col(2 * j).array().isNaN().count());
    if (unseen == px.rows())
      throw Error(ErrorKind::BadData, name, "", std::string(jointName(static_cast<Joint>(j))) + " is seen in no frame");
    result.filledPoints += unseen;
    fillAllGapsLinearly(px.col(2 * j));
    fillAllGapsLinearly(px.col(2 * j + 1));
  }
  std::vector<JointRays> rays;
  for (Eigen::Index t = 0; t < px.rows(); ++t) rays.push_back(pinholeRays(px.row(t), intrinsicsOf(camera)));
  const int window = std::max(1, static_cast<int>(std::lround(options.depthWindowS * rateHz)) | 1);
  result.rootDistanceMm = rootDistancesFromBones(rays, bones, window);
  std::vector<Eigen::Vector3d> roots;
  for (size_t t = 0; t < rays.size(); ++t) {
    const Eigen::Index p = index(Joint::Pelvis);
    roots.push_back(rays[t].origin.col(p) + result.rootDistanceMm[t] * rays[t].direction.col(p));
  }
  SkeletonSolveOptions solve = options.solve;
  solve.upMm = imageUp(px);
  result.sequence = solveSkeletonSequence(rays, roots, bones, rateHz, solve);
  if (camera.hasExtrinsics) {
    const Eigen::Matrix3d r = rotationFromRodrigues(camera.rotation);
    const Eigen::Vector3d tr(camera.translationMm[0], camera.translationMm[1], camera.translationMm[2]);
    result.worldMm.resize(result.sequence.framesMm.rows(), 3 * kJointCount);
    for (Eigen::Index t = 0; t < result.worldMm.rows(); ++t)
      for (int j = 0; j < kJointCount; ++j)
        result.worldMm.block<1, 3>(t, 3 * j) =
            (r.transpose() * (result.sequence.framesMm.block<1, 3>(t, 3 * j).transpose() - tr)).transpose();
  }
  return result;
}

}  // namespace ew

namespace ew {

namespace {

// The 24 rotations that permute and flip the axes.
std::vector<Eigen::Matrix3d> signedPermutations() {
  std::vector<Eigen::Matrix3d> out;
  const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (const auto& p : perms)
    for (int s = 0; s < 8; ++s) {
      Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
      for (int r = 0; r < 3; ++r) m(r, p[r]) = (s >> r) & 1 ? -1.0 : 1.0;
      if (m.determinant() > 0.0) out.push_back(m);
    }
  return out;
}

using FramePoints = Eigen::Matrix<double, 3, kJointCount>;

FramePoints pointsOf(const Eigen::Ref<const Eigen::MatrixXd>& frames, Eigen::Index t) {
  FramePoints p;
  for (int j = 0; j < kJointCount; ++j) p.col(j) = frames.block<1, 3>(t, 3 * j).transpose();
  return p;
}

// Mean joint error after the best rigid motion of `a` onto `b` (Kabsch, no scale).
double procrustesError(const FramePoints& a, const FramePoints& b) {
  const Eigen::Vector3d ca = a.rowwise().mean(), cb = b.rowwise().mean();
  const FramePoints a0 = a.colwise() - ca, b0 = b.colwise() - cb;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(b0 * a0.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0.0 ? -1.0 : 1.0;
  const Eigen::Matrix3d r = svd.matrixU() * d * svd.matrixV().transpose();
  return ((r * a0) - b0).colwise().norm().mean();
}

}  // namespace

ReferenceComparison compareWithReference(const Eigen::Ref<const Eigen::MatrixXd>& worldMm,
                                         const Eigen::Ref<const Eigen::MatrixXd>& referenceMm,
                                         const std::string& name) {
  std::vector<Eigen::Index> frames;
  for (Eigen::Index t = 0; t < std::min(worldMm.rows(), referenceMm.rows()); ++t)
    if (worldMm.row(t).allFinite() && referenceMm.row(t).allFinite()) frames.push_back(t);
  if (frames.empty()) throw Error(ErrorKind::BadData, name, "", "no frame has every joint in both the reconstruction and the reference");
  // The axes are chosen by the mean-translation error alone; the raw and the Procrustes
  // errors (the latter the same for any proper rotation of the reference) only for them.
  const double n = static_cast<double>(frames.size());
  ReferenceComparison best;
  best.frames = static_cast<int>(frames.size());
  best.meanTranslationMm = std::numeric_limits<double>::infinity();
  for (const Eigen::Matrix3d& axes : signedPermutations()) {
    Eigen::Vector3d offset = Eigen::Vector3d::Zero();
    for (Eigen::Index t : frames) offset += (axes * pointsOf(referenceMm, t) - pointsOf(worldMm, t)).rowwise().sum();
    offset /= n * kJointCount;
    Eigen::Matrix<double, 1, kJointCount> perJoint = Eigen::Matrix<double, 1, kJointCount>::Zero();
    for (Eigen::Index t : frames)
      perJoint += ((pointsOf(worldMm, t).colwise() + offset) - axes * pointsOf(referenceMm, t)).colwise().norm();
    perJoint /= n;
    if (perJoint.mean() >= best.meanTranslationMm) continue;
    best.referenceToWorld = axes;
    best.meanTranslationMm = perJoint.mean();
    for (int j = 0; j < kJointCount; ++j) best.perJointMm[static_cast<size_t>(j)] = perJoint(j);
  }
  for (Eigen::Index t : frames) {
    const FramePoints ref = best.referenceToWorld * pointsOf(referenceMm, t), rec = pointsOf(worldMm, t);
    best.rawMm += (rec - ref).colwise().norm().mean() / n;
    best.procrustesMm += procrustesError(rec, ref) / n;
  }
  return best;
}

}  // namespace ew
