#include "core/snippet/snippet_data.h"

#include <cmath>

#include "core/common/errors.h"
#include "core/common/skeleton.h"

namespace ew {

namespace {

void checkRate(double hz, const char* what) {
  if (!(hz > 0.0 && std::isfinite(hz)))
    throw Error(ErrorKind::BadArgument, "snippets", "", std::string(what) + " must be positive and finite");
}

void checkSnippetRange(const Eigen::Ref<const Eigen::MatrixXd>& frames, int start, int count) {
  if (frames.cols() != kDims3 || count < 1 || start < 0 || start + count > frames.rows())
    throw Error(ErrorKind::BadArgument, "snippets", "",
                "frames " + std::to_string(start) + "…" + std::to_string(start + count) +
                    " of a " + std::to_string(frames.rows()) + " × " + std::to_string(frames.cols()) +
                    " trial (45 columns expected)");
}

}  // namespace

Eigen::MatrixXd resampleFrames(const Eigen::Ref<const Eigen::MatrixXd>& frames, double fromHz,
                               double toHz) {
  checkRate(fromHz, "the input rate");
  checkRate(toHz, "the output rate");
  if (frames.rows() == 0) return Eigen::MatrixXd(0, frames.cols());
  const double span = static_cast<double>(frames.rows() - 1) / fromHz;
  const long out = static_cast<long>(std::floor(span * toHz + 1e-9)) + 1;
  Eigen::MatrixXd result(out, frames.cols());
  for (long i = 0; i < out; ++i) {
    const double pos = static_cast<double>(i) / toHz * fromHz;
    const long lo = std::min(static_cast<long>(std::floor(pos)), static_cast<long>(frames.rows() - 1));
    const long hi = std::min(lo + 1, static_cast<long>(frames.rows() - 1));
    const double f = pos - static_cast<double>(lo);
    // 0·NaN is NaN, so a NaN neighbour stays NaN even when f is 0 — intended: the sample
    // sits on a frame only when f is exactly 0 and then takes that frame alone.
    if (f <= 1e-12) result.row(i) = frames.row(lo);
    else result.row(i) = (1.0 - f) * frames.row(lo) + f * frames.row(hi);
  }
  return result;
}

SnippetPlacement snippetPlacement(const Eigen::Ref<const Eigen::MatrixXd>& frames, int start,
                                  int count) {
  checkSnippetRange(frames, start, count);
  const int mid = start + count / 2;
  const auto at = [&](Joint j, int axis) { return frames(mid, 3 * index(j) + axis); };
  SnippetPlacement p;
  p.originX = at(Joint::Pelvis, 0);
  p.originY = at(Joint::Pelvis, 1);
  // forward = z × (r_hip − l_hip) = (−dy, dx) for the hip vector (dx, dy).
  const double dx = at(Joint::RHip, 0) - at(Joint::LHip, 0);
  const double dy = at(Joint::RHip, 1) - at(Joint::LHip, 1);
  const double fx = -dy, fy = dx;
  p.headingRad = (fx == 0.0 && fy == 0.0) ? 0.0 : std::atan2(-fx, fy);
  return p;
}

Eigen::VectorXd localSnippet(const Eigen::Ref<const Eigen::MatrixXd>& frames, int start,
                             int count, const SnippetPlacement& placement) {
  checkSnippetRange(frames, start, count);
  const double c = std::cos(placement.headingRad), s = std::sin(placement.headingRad);
  Eigen::VectorXd x(static_cast<Eigen::Index>(count) * kDims3);
  for (int f = 0; f < count; ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const double px = frames(start + f, 3 * j) - placement.originX;
      const double py = frames(start + f, 3 * j + 1) - placement.originY;
      const Eigen::Index at = static_cast<Eigen::Index>(f) * kDims3 + 3 * j;
      // R(−h) (px, py): the heading turned back onto +y.
      x(at) = c * px + s * py;
      x(at + 1) = -s * px + c * py;
      x(at + 2) = frames(start + f, 3 * j + 2);
    }
  }
  return x;
}

Eigen::MatrixXd placeSnippet(const Eigen::Ref<const Eigen::VectorXd>& snippet, int count,
                             const SnippetPlacement& placement) {
  if (count < 1 || snippet.size() != static_cast<Eigen::Index>(count) * kDims3)
    throw Error(ErrorKind::BadArgument, "snippets", "",
                "a snippet of " + std::to_string(snippet.size()) + " values is not " +
                    std::to_string(count) + " frames of 45");
  const double c = std::cos(placement.headingRad), s = std::sin(placement.headingRad);
  Eigen::MatrixXd frames(count, kDims3);
  for (int f = 0; f < count; ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const Eigen::Index at = static_cast<Eigen::Index>(f) * kDims3 + 3 * j;
      const double lx = snippet(at), ly = snippet(at + 1);
      frames(f, 3 * j) = c * lx - s * ly + placement.originX;
      frames(f, 3 * j + 1) = s * lx + c * ly + placement.originY;
      frames(f, 3 * j + 2) = snippet(at + 2);
    }
  }
  return frames;
}

Eigen::MatrixXd cutTrainingSnippets(const std::vector<SnippetTrainingTrial>& trials, int count,
                                    int hop, double rateHz) {
  if (count < 1 || hop < 1)
    throw Error(ErrorKind::BadArgument, "snippets", "", "snippet length and hop must be ≥ 1");
  std::vector<Eigen::VectorXd> columns;
  for (const SnippetTrainingTrial& t : trials) {
    if (t.framesMm.cols() != kDims3)
      throw Error(ErrorKind::BadArgument, t.name, "", "training trial is not 15 joints in 3D");
    const Eigen::MatrixXd frames = resampleFrames(t.framesMm, t.rateHz, rateHz);
    for (int start = 0; start + count <= frames.rows(); start += hop) {
      if (!frames.middleRows(start, count).allFinite()) continue;
      columns.push_back(localSnippet(frames, start, count, snippetPlacement(frames, start, count)));
    }
  }
  Eigen::MatrixXd result(static_cast<Eigen::Index>(count) * kDims3,
                         static_cast<Eigen::Index>(columns.size()));
  for (size_t i = 0; i < columns.size(); ++i) result.col(static_cast<Eigen::Index>(i)) = columns[i];
  return result;
}

}  // namespace ew
