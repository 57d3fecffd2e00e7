#include "core/mapping/functional_centre.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <cmath>
#include <limits>

#include "core/common/nan.h"
#include "core/common/thin_svd.h"

namespace ew {
namespace {

// A singular value below this fraction of the largest marks a free direction (a hinge's axis).
constexpr double kHingeRatio = 0.05;
// |cos| between a hinge axis and the joint->anchor direction above which the axis is taken
// to run along the segment, not across it (60 degrees).
constexpr double kMaxAxisAlongSegment = 0.5;

// Rigid pose of a cluster: x = R * shape + t, `shape` the cluster (centred) in the first
// frame where it is complete.
struct Pose {
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  bool ok = false;
};

Eigen::Matrix3Xd clusterAt(const std::vector<MarkerTrack>& cluster, int f) {
  Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(cluster.size()));
  for (std::size_t k = 0; k < cluster.size(); ++k)
    x.col(static_cast<Eigen::Index>(k)) = cluster[k].row(f).transpose();
  return x;
}

// Kabsch: the rotation taking the centred reference shape onto the centred frame.
Eigen::Matrix3d bestRotation(const Eigen::Matrix3Xd& frame, const Eigen::Matrix3Xd& shape) {
  const Eigen::Matrix3d h = frame * shape.transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d uv = svd.matrixU() * svd.matrixV().transpose();
  d(2, 2) = uv.determinant() < 0 ? -1.0 : 1.0;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

std::vector<Pose> clusterPoses(const std::vector<MarkerTrack>& cluster, int frames) {
  std::vector<Pose> poses(static_cast<std::size_t>(frames));
  Eigen::Matrix3Xd shape;
  for (int f = 0; f < frames; ++f) {
    const Eigen::Matrix3Xd x = clusterAt(cluster, f);
    if (!x.allFinite()) continue;
    const Eigen::Vector3d c = x.rowwise().mean();
    const Eigen::Matrix3Xd centred = x.colwise() - c;
    if (shape.size() == 0) shape = centred;
    poses[static_cast<std::size_t>(f)] = {bestRotation(centred, shape), c, true};
  }
  return poses;
}

// The axis of a hinge: the right singular vector of the smallest singular value, when that
// is below kHingeRatio of the largest. Moves x along it to the point nearest the anchor's
// mean position in the proximal cluster's frame.
void slideAlongAxis(const ThinSvd& svd, const std::vector<Pose>& p,
                    const std::vector<int>& frames, const MarkerTrack& anchor, Eigen::VectorXd& x) {
  const auto& s = svd.singularValues;
  if (s(5) >= kHingeRatio * s(0)) return;  // a ball joint: the point is determined
  const Eigen::VectorXd v = svd.v.col(5);
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int n = 0;
  for (int f : frames) {
    const Eigen::Vector3d h = anchor.row(f).transpose();
    if (!h.allFinite()) continue;
    const Pose& pp = p[static_cast<std::size_t>(f)];
    sum += pp.r.transpose() * (h - pp.t);
    ++n;
  }
  const Eigen::Vector3d axis = v.head<3>();
  if (n == 0 || axis.squaredNorm() < 1e-12) return;
  // Only across the segment: a free direction along it (little rotation about the long
  // axis) would slide the joint up to the anchor.
  const Eigen::Vector3d toAnchor = sum / n - x.head<3>();
  if (std::abs(toAnchor.normalized().dot(axis.normalized())) > kMaxAxisAlongSegment) return;
  x += toAnchor.dot(axis) / axis.squaredNorm() * v;
}

MarkerTrack clusterCentroid(const std::vector<MarkerTrack>& cluster) {
  MarkerTrack sum = MarkerTrack::Zero(cluster.front().rows(), 3);
  for (const auto& m : cluster) sum += m;
  return sum / static_cast<double>(cluster.size());
}

}  // namespace

MarkerTrack functionalJointCentre(const std::vector<MarkerTrack>& proximal,
                                  const std::vector<MarkerTrack>& distal,
                                  const MarkerTrack* anchor) {
  const int frames = proximal.empty() ? 0 : static_cast<int>(proximal.front().rows());
  MarkerTrack out = MarkerTrack::Constant(frames, 3, kNaN);
  if (proximal.size() < 3 || distal.size() < 3) return out;
  const auto p = clusterPoses(proximal, frames);
  const auto d = clusterPoses(distal, frames);
  std::vector<int> both;
  for (int f = 0; f < frames; ++f) {
    if (p[static_cast<std::size_t>(f)].ok && d[static_cast<std::size_t>(f)].ok) both.push_back(f);
  }
  if (static_cast<int>(both.size()) < kFunctionalMinFrames) return out;
  // R_p a + t_p = R_d b + t_d in every frame: [R_p  -R_d] [a; b] = t_d - t_p.
  Eigen::MatrixXd a(3 * static_cast<Eigen::Index>(both.size()), 6);
  Eigen::VectorXd rhs(a.rows());
  for (std::size_t i = 0; i < both.size(); ++i) {
    const Pose& pp = p[static_cast<std::size_t>(both[i])];
    const Pose& dd = d[static_cast<std::size_t>(both[i])];
    const auto row = 3 * static_cast<Eigen::Index>(i);
    a.block<3, 3>(row, 0) = pp.r;
    a.block<3, 3>(row, 3) = -dd.r;
    rhs.segment<3>(row) = dd.t - pp.t;
  }
  // A hinge leaves one direction (the axis) nearly free: singular values below 5 % of the
  // largest are dropped, so the solution is the minimum-norm point on the axis.
  const ThinSvd svd = thinSvd(a);
  Eigen::VectorXd x = solveThroughSvd(svd, rhs, kHingeRatio);
  if (anchor) slideAlongAxis(svd, p, both, *anchor, x);
  const Eigen::Vector3d inProximal = x.head<3>(), inDistal = x.tail<3>();
  for (int f = 0; f < frames; ++f) {
    const Pose& pp = p[static_cast<std::size_t>(f)];
    const Pose& dd = d[static_cast<std::size_t>(f)];
    const Eigen::Vector3d fromP = pp.r * inProximal + pp.t, fromD = dd.r * inDistal + dd.t;
    if (pp.ok && dd.ok)
      out.row(f) = (0.5 * (fromP + fromD)).transpose();
    else if (pp.ok)
      out.row(f) = fromP.transpose();
    else if (dd.ok)
      out.row(f) = fromD.transpose();
  }
  return out;
}

HipPair symmetricFunctionalHips(const std::vector<MarkerTrack>& pelvis,
                                const std::vector<MarkerTrack>& leftThigh,
                                const std::vector<MarkerTrack>& rightThigh, double widthMm) {
  if (pelvis.empty() || leftThigh.empty() || rightThigh.empty()) {
    const Eigen::Index frames = pelvis.empty() ? 0 : pelvis.front().rows();
    return {MarkerTrack::Constant(frames, 3, kNaN), MarkerTrack::Constant(frames, 3, kNaN)};
  }
  // Each fit nearly a hinge: its point on the flexion axis is taken nearest its thigh
  // cluster, so the pair's midpoint follows the thighs' (symmetric) clusters rather than
  // wherever the pelvis cluster sits.
  const MarkerTrack leftAnchor = clusterCentroid(leftThigh), rightAnchor = clusterCentroid(rightThigh);
  HipPair h{functionalJointCentre(pelvis, leftThigh, &leftAnchor),
            functionalJointCentre(pelvis, rightThigh, &rightAnchor)};
  for (Eigen::Index f = 0; f < h.left.rows(); ++f) {
    const Eigen::RowVector3d mid = 0.5 * (h.left.row(f) + h.right.row(f));
    const Eigen::RowVector3d across = h.left.row(f) - h.right.row(f);
    const double n = across.norm();
    const Eigen::RowVector3d half =
        n > 1e-9 ? Eigen::RowVector3d(0.5 * widthMm / n * across) : Eigen::RowVector3d::Constant(kNaN);
    h.left.row(f) = mid + half;
    h.right.row(f) = mid - half;
  }
  return h;
}

}  // namespace ew
