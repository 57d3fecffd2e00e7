#include "core/eigenwalker/projection.h"

#include <cmath>
#include <numbers>

#include "core/common/errors.h"
#include "core/common/skeleton.h"

namespace ew {
namespace {

void requireRows(Eigen::Index rows, Eigen::Index expected, const char* what) {
  if (rows != expected) {
    throw Error(ErrorKind::BadArgument, "", "",
                std::string("projection: ") + what + ": expected " + std::to_string(expected) +
                    " rows, got " + std::to_string(rows));
  }
}

// A non-finite α would turn every output into NaN. (NaN coordinates, by contrast, are
// missing samples and pass through as NaN on purpose.)
void requireAngle(double alphaDeg, const char* what) {
  if (!std::isfinite(alphaDeg)) {
    throw Error(ErrorKind::BadArgument, "", "",
                std::string("projection: ") + what + ": the view angle must be finite, got " +
                    std::to_string(alphaDeg) + "°");
  }
}

// Applies (x,y,z) → (u,v) to every triple of every column; `triples` = rows / 3.
Eigen::MatrixXd projectTriples(const Eigen::Ref<const Eigen::MatrixXd>& xyz, double alphaDeg) {
  const double a = degToRad(alphaDeg), c = std::cos(a), s = std::sin(a);
  const Eigen::Index triples = xyz.rows() / 3;
  Eigen::MatrixXd uv(2 * triples, xyz.cols());
  for (Eigen::Index j = 0; j < xyz.cols(); ++j) {
    for (Eigen::Index i = 0; i < triples; ++i) {
      uv(2 * i, j) = c * xyz(3 * i, j) + s * xyz(3 * i + 1, j);
      uv(2 * i + 1, j) = xyz(3 * i + 2, j);
    }
  }
  return uv;
}

Eigen::MatrixXd depthOfTriples(const Eigen::Ref<const Eigen::MatrixXd>& xyz, double alphaDeg) {
  const double a = degToRad(alphaDeg), c = std::cos(a), s = std::sin(a);
  const Eigen::Index triples = xyz.rows() / 3;
  Eigen::MatrixXd d(triples, xyz.cols());
  for (Eigen::Index j = 0; j < xyz.cols(); ++j) {
    for (Eigen::Index i = 0; i < triples; ++i) d(i, j) = -s * xyz(3 * i, j) + c * xyz(3 * i + 1, j);
  }
  return d;
}

}  // namespace

double degToRad(double deg) { return deg * (std::numbers::pi / 180.0); }

double wrapDeg(double deg) {
  double a = std::remainder(deg, 360.0);  // [−180, 180]
  return a <= -180.0 ? a + 360.0 : a;
}

Eigen::MatrixXd projectionMatrix(double alphaDeg) {
  requireAngle(alphaDeg, "projectionMatrix");
  const double a = degToRad(alphaDeg), c = std::cos(a), s = std::sin(a);
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(2 * kPointsPerWalker, 3 * kPointsPerWalker);
  for (int i = 0; i < kPointsPerWalker; ++i) {
    m(2 * i, 3 * i) = c;
    m(2 * i, 3 * i + 1) = s;
    m(2 * i + 1, 3 * i + 2) = 1.0;
  }
  return m;
}

Eigen::MatrixXd projectToView(const Eigen::Ref<const Eigen::MatrixXd>& w, double alphaDeg) {
  requireRows(w.rows(), 3 * kPointsPerWalker, "projectToView");
  requireAngle(alphaDeg, "projectToView");
  return projectTriples(w, alphaDeg);
}

Eigen::MatrixXd depthAtView(const Eigen::Ref<const Eigen::MatrixXd>& w, double alphaDeg) {
  requireRows(w.rows(), 3 * kPointsPerWalker, "depthAtView");
  requireAngle(alphaDeg, "depthAtView");
  return depthOfTriples(w, alphaDeg);
}

Eigen::MatrixXd composeFromView(const Eigen::Ref<const Eigen::MatrixXd>& uv,
                                const Eigen::Ref<const Eigen::MatrixXd>& depth, double alphaDeg) {
  requireRows(uv.rows(), 2 * kPointsPerWalker, "composeFromView (image)");
  requireRows(depth.rows(), kPointsPerWalker, "composeFromView (depth)");
  if (uv.cols() != depth.cols())
    throw Error(ErrorKind::BadArgument, "", "",
                "projection: composeFromView: column counts differ");
  requireAngle(alphaDeg, "composeFromView");
  // [x; y] = Rᵀ [u; d] for the rotation R = [c s; −s c] that maps (x, y) to (u, d).
  const double a = degToRad(alphaDeg), c = std::cos(a), s = std::sin(a);
  Eigen::MatrixXd w(3 * kPointsPerWalker, uv.cols());
  for (Eigen::Index j = 0; j < uv.cols(); ++j) {
    for (Eigen::Index i = 0; i < kPointsPerWalker; ++i) {
      const double u = uv(2 * i, j), d = depth(i, j);
      w(3 * i, j) = c * u - s * d;
      w(3 * i + 1, j) = s * u + c * d;
      w(3 * i + 2, j) = uv(2 * i + 1, j);
    }
  }
  return w;
}

Eigen::MatrixXd projectFramesToView(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                    double alphaDeg) {
  if (frames.cols() != kDims3)
    throw Error(ErrorKind::BadArgument, "", "",
                "projection: projectFramesToView needs T × 45 frames, got " +
                    std::to_string(frames.cols()) + " columns");
  requireAngle(alphaDeg, "projectFramesToView");
  return projectTriples(frames.transpose(), alphaDeg).transpose();
}

Eigen::MatrixXd depthFramesAtView(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                  double alphaDeg) {
  if (frames.cols() != kDims3)
    throw Error(ErrorKind::BadArgument, "", "",
                "projection: depthFramesAtView needs T × 45 frames, got " +
                    std::to_string(frames.cols()) + " columns");
  requireAngle(alphaDeg, "depthFramesAtView");
  return depthOfTriples(frames.transpose(), alphaDeg).transpose();
}

}  // namespace ew
