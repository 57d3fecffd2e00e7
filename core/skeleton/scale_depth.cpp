#include "core/skeleton/scale_depth.h"

#include <cmath>

#include "core/camera/focal_length.h"
#include "core/common/errors.h"

namespace ew {
namespace {

Eigen::Vector2d pointOf(const Eigen::Ref<const Eigen::RowVectorXd>& frame, Joint j, const std::string& what) {
  const Eigen::Vector2d p(frame(2 * index(j)), frame(2 * index(j) + 1));
  if (!p.allFinite())
    throw Error(ErrorKind::BadData, what, "",
                "the " + std::string(jointName(j)) + " is not seen in the frame chosen for the scale-depth relation");
  return p;
}

std::string boneName(Joint a, Joint b) { return std::string(jointName(a)) + "-" + std::string(jointName(b)); }

}  // namespace

ScaleDepthFocal focalFromScaleDepth(const Eigen::Ref<const Eigen::RowVectorXd>& frame, double cxPx, double cyPx,
                                    const std::array<Joint, 4>& chain, const BoneLengths& bones,
                                    const std::string& what) {
  std::array<int, 3> bone{};
  for (int k = 0; k < 3; ++k) {
    bone[k] = boneBetween(chain[k], chain[k + 1]);
    if (bone[k] < 0)
      throw Error(ErrorKind::BadArgument, what, "",
                  "no bone joins the " + std::string(jointName(chain[k])) + " and the " +
                      std::string(jointName(chain[k + 1])) + ": the scale-depth relation needs a chain of three linked segments");
  }
  if (frame.size() != kDims2) throw Error(ErrorKind::BadArgument, what, "", "a frame has 30 pixel coordinates");
  const Eigen::Vector2d centre(cxPx, cyPx);
  std::array<Eigen::Vector2d, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = pointOf(frame, chain[k], what) - centre;
  const auto scaleOf = [&](int k) {
    const double imageLength = (p[k + 1] - p[k]).norm();
    if (!(imageLength > 1e-9))
      throw Error(ErrorKind::BadData, what, "",
                  "the " + boneName(chain[k], chain[k + 1]) + " has no length in the image: it cannot be parallel to it");
    return bones.mm[bone[k]] / imageLength;
  };
  ScaleDepthFocal r;
  r.nearScaleMmPerPx = scaleOf(0);
  r.farScaleMmPerPx = scaleOf(2);
  const Eigen::Vector2d across = r.farScaleMmPerPx * p[2] - r.nearScaleMmPerPx * p[1];  // eq. 3
  const double dz2 = bones.mm[bone[1]] * bones.mm[bone[1]] - across.squaredNorm();
  if (!(dz2 >= 0.0))
    throw Error(ErrorKind::BadData, what, "",
                "the " + boneName(chain[1], chain[2]) +
                    " looks longer than it is: the outer segments are not parallel to the image plane in this frame");
  r.depthStepMm = std::sqrt(dz2);
  const double ds = std::abs(r.farScaleMmPerPx - r.nearScaleMmPerPx);  // eq. 4
  if (!(ds > 1e-12 * r.nearScaleMmPerPx) || !(r.depthStepMm > 0.0))
    throw Error(ErrorKind::BadData, what, "",
                "the outer segments are at one depth: the scale-depth relation leaves the focal length undetermined");
  r.focalPx = r.depthStepMm / ds;
  // Nearly parallel segments at nearly one depth give any number: not a camera's, not an answer.
  if (const std::string problem = focalLengthProblem(r.focalPx); !problem.empty())
    throw Error(ErrorKind::BadData, what, "", "the scale-depth relation gives a " + problem + " (choose another frame or chain)");
  return r;
}

}  // namespace ew
