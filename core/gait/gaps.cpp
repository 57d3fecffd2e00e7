#include "core/gait/gaps.h"

#include <cmath>

#include "core/common/skeleton.h"

namespace ew {
namespace {

bool jointMissing(const Eigen::MatrixXd& m, Eigen::Index row, int joint) {
  return !m.block<1, 3>(row, 3 * joint).allFinite();
}

void interpolateJoint(Eigen::MatrixXd& m, int joint, Eigen::Index before, Eigen::Index after) {
  const auto a = m.block<1, 3>(before, 3 * joint).eval();
  const auto b = m.block<1, 3>(after, 3 * joint).eval();
  const double span = static_cast<double>(after - before);
  for (Eigen::Index r = before + 1; r < after; ++r) {
    const double s = static_cast<double>(r - before) / span;
    m.block<1, 3>(r, 3 * joint) = (1.0 - s) * a + s * b;
  }
}

}  // namespace

GapReport bridgeShortGaps(Eigen::MatrixXd& m, int maxGapFrames) {
  GapReport report;
  const Eigen::Index frames = m.rows();
  for (int j = 0; j < kJointCount; ++j) {
    Eigen::Index r = 0;
    while (r < frames) {
      if (!jointMissing(m, r, j)) { ++r; continue; }
      Eigen::Index start = r;
      while (r < frames && jointMissing(m, r, j)) ++r;
      const Eigen::Index length = r - start;
      if (start == 0 || r == frames || length > maxGapFrames) continue;
      interpolateJoint(m, j, start - 1, r);
      ++report.bridgedGaps;
      report.bridgedSamples += static_cast<int>(length);
      report.notes.push_back(std::string(kJointNames[static_cast<size_t>(j)]) + ": frames " +
                             std::to_string(start) + "-" + std::to_string(r - 1) + " interpolated");
    }
  }
  return report;
}

std::vector<bool> completeFrames(const Eigen::MatrixXd& m) {
  std::vector<bool> ok(static_cast<size_t>(m.rows()));
  for (Eigen::Index r = 0; r < m.rows(); ++r) ok[static_cast<size_t>(r)] = m.row(r).allFinite();
  return ok;
}

std::pair<int, int> longestRun(const std::vector<bool>& flags) {
  int bestBegin = 0, bestEnd = 0, i = 0;
  const int n = static_cast<int>(flags.size());
  while (i < n) {
    if (!flags[static_cast<size_t>(i)]) { ++i; continue; }
    int begin = i;
    while (i < n && flags[static_cast<size_t>(i)]) ++i;
    if (i - begin > bestEnd - bestBegin) { bestBegin = begin; bestEnd = i; }
  }
  return {bestBegin, bestEnd};
}

}  // namespace ew
