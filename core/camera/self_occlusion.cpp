#include "core/camera/self_occlusion.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/common/skeleton.h"

namespace ew {
namespace {

// Segment radii, mm: an adult's trunk seen from the side or the front (half its depth and half
// its width lie either side of 120 mm), limbs tapering from thigh to forearm, and the girdles
// (sternum to shoulder, pelvis to hip) as thick as the trunk's edge. In kBones' order.
constexpr std::array<double, kBones.size()> kRadiusMm = {
    60.0,   // head–sternum (the neck)
    120.0,  // sternum–pelvis
    60.0, 60.0,   // sternum–shoulders
    45.0, 40.0,   // right upper arm, forearm
    45.0, 40.0,   // left
    60.0, 60.0,   // pelvis–hips
    70.0, 50.0,   // right thigh, shank
    70.0, 50.0,   // left
};

struct Seen {
  Eigen::Vector2d px;
  double depthMm = 0.0;
};

Seen seenAt(const Eigen::MatrixXd& px, const Eigen::MatrixXd& camera, Eigen::Index f, int j) {
  return {px.row(f).segment<2>(2 * j).transpose(), camera(f, 3 * j + 2)};
}

// Pixels per mm at frame f: the image's head-to-ankle span over the body's.
double pxPerMmAt(const Eigen::MatrixXd& px, const Eigen::Ref<const Eigen::MatrixXd>& framesMm,
                 Eigen::Index f) {
  const auto span = [&](const auto& row, int dims) {
    double lo = 1e300, hi = -1e300;
    for (int j = 0; j < kJointCount; ++j) {
      const double v = row(dims * j + dims - 1);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    return hi - lo;
  };
  const double body = span(framesMm.row(f), 3);
  return body > 1.0 ? span(px.row(f), 2) / body : 0.0;
}

// Whether bone b, nearer the camera, covers joint j's image at frame f.
bool covers(std::size_t b, int j, const Eigen::MatrixXd& px, const Eigen::MatrixXd& camera,
            Eigen::Index f, double pxPerMm) {
  const int p = index(kBones[b].first), c = index(kBones[b].second);
  if (p == j || c == j) return false;
  const Seen a = seenAt(px, camera, f, p), e = seenAt(px, camera, f, c), q = seenAt(px, camera, f, j);
  const Eigen::Vector2d along = e.px - a.px;
  const double t =
      along.squaredNorm() > 1e-9 ? std::clamp((q.px - a.px).dot(along) / along.squaredNorm(), 0.0, 1.0) : 0.0;
  const double distancePx = (a.px + t * along - q.px).norm();
  const double depthMm = a.depthMm + t * (e.depthMm - a.depthMm);
  return distancePx < kRadiusMm[b] * pxPerMm && depthMm < q.depthMm - kRadiusMm[b];
}

}  // namespace

Eigen::MatrixXd hiddenJoints(const Eigen::Ref<const Eigen::MatrixXd>& framesMm,
                             const Eigen::Ref<const Eigen::VectorXd>& timesS,
                             const WalkCamera& camera) {
  const Eigen::MatrixXd px = projectWalk(framesMm, timesS, camera);
  const Eigen::MatrixXd inCamera = walkInCameraFrame(framesMm, timesS, camera);
  Eigen::MatrixXd hidden = Eigen::MatrixXd::Zero(framesMm.rows(), kJointCount);
  for (Eigen::Index f = 0; f < framesMm.rows(); ++f) {
    const double pxPerMm = pxPerMmAt(px, framesMm, f);
    if (!(pxPerMm > 0.0) || !px.row(f).allFinite()) continue;
    for (int j = 0; j < kJointCount; ++j)
      for (std::size_t b = 0; b < kBones.size() && hidden(f, j) == 0.0; ++b)
        if (covers(b, j, px, inCamera, f, pxPerMm)) hidden(f, j) = 1.0;
  }
  return hidden;
}

}  // namespace ew
