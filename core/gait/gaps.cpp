#include "core/gait/gaps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

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

// Median of the finite values of coordinate `col` in rows r-2..r+2 (NaN when fewer than
// three of them are finite: no majority to judge the sample against).
double neighbourhoodMedian(const Eigen::MatrixXd& m, Eigen::Index r, Eigen::Index col) {
  std::array<double, 5> v{};
  int n = 0;
  for (Eigen::Index k = std::max<Eigen::Index>(0, r - 2); k <= std::min(m.rows() - 1, r + 2); ++k) {
    const double x = m(k, col);
    if (!std::isfinite(x)) continue;
    int i = n++;  // insertion into the sorted prefix
    for (; i > 0 && v[static_cast<size_t>(i - 1)] > x; --i)
      v[static_cast<size_t>(i)] = v[static_cast<size_t>(i - 1)];
    v[static_cast<size_t>(i)] = x;
  }
  if (n < 3) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = static_cast<size_t>(n / 2);
  return n % 2 ? v[mid] : 0.5 * (v[mid - 1] + v[mid]);
}

// Distance of a joint sample from its neighbourhood's median (0 when that is unknown).
double deviationFromNeighbours(const Eigen::MatrixXd& m, Eigen::Index r, int joint) {
  double sum2 = 0.0;
  for (int c = 0; c < 3; ++c) {
    const double med = neighbourhoodMedian(m, r, 3 * joint + c);
    if (!std::isfinite(med)) return 0.0;
    sum2 += (m(r, 3 * joint + c) - med) * (m(r, 3 * joint + c) - med);
  }
  return std::sqrt(sum2);
}

// The named points the matrix holds (3 columns each): never more than it has columns for.
int pointCountOf(const Eigen::MatrixXd& m, PointNames names) {
  return static_cast<int>(std::min<Eigen::Index>(static_cast<Eigen::Index>(names.size()), m.cols() / 3));
}

void markMissing(Eigen::MatrixXd& m, Eigen::Index r, int joint) {
  m.block<1, 3>(r, 3 * joint).setConstant(std::numeric_limits<double>::quiet_NaN());
}

std::string distanceText(double mm) {
  std::ostringstream out;
  out.precision(3);
  if (mm >= 1e4)
    out << mm / 1000.0 << " m";
  else
    out << std::lround(mm) << " mm";
  return out.str();
}

}  // namespace

double outlierThresholdMm(double rateHz) { return 500.0 + 2.0 * 10000.0 / rateHz; }

OutlierReport rejectOutlierSamples(Eigen::MatrixXd& m, double thresholdMm) {
  return rejectOutlierSamples(m, thresholdMm, kJointNames);
}

OutlierReport rejectOutlierSamples(Eigen::MatrixXd& m, double thresholdMm, PointNames names) {
  OutlierReport report;
  const Eigen::MatrixXd original = m;  // judge every sample against the data as read
  for (int j = 0; j < pointCountOf(m, names); ++j) {
    for (Eigen::Index r = 0; r < m.rows(); ++r) {
      const auto sample = original.block<1, 3>(r, 3 * j);
      if (!sample.allFinite()) {
        markMissing(m, r, j);
        continue;
      }
      const double offLimits = sample.cwiseAbs().maxCoeff();
      const double deviation = deviationFromNeighbours(original, r, j);
      if (offLimits <= kMaxPlausibleCoordinateMm && deviation <= thresholdMm) continue;
      markMissing(m, r, j);
      ++report.rejectedSamples;
      report.notes.push_back(std::string(names[static_cast<size_t>(j)]) + ": frame " +
                             std::to_string(r) + ", " +
                             (offLimits > kMaxPlausibleCoordinateMm
                                  ? "coordinate " + distanceText(offLimits) + " from the origin"
                                  : distanceText(deviation) + " from its neighbours"));
    }
  }
  return report;
}

GapReport bridgeShortGaps(Eigen::MatrixXd& m, int maxGapFrames) {
  return bridgeShortGaps(m, maxGapFrames, kJointNames);
}

GapReport bridgeShortGaps(Eigen::MatrixXd& m, int maxGapFrames, PointNames names) {
  GapReport report;
  const Eigen::Index frames = m.rows();
  for (int j = 0; j < pointCountOf(m, names); ++j) {
    Eigen::Index r = 0;
    while (r < frames) {
      if (!jointMissing(m, r, j)) {
        ++r;
        continue;
      }
      Eigen::Index start = r;
      while (r < frames && jointMissing(m, r, j)) ++r;
      const Eigen::Index length = r - start;
      if (start == 0 || r == frames || length > maxGapFrames) continue;
      interpolateJoint(m, j, start - 1, r);
      ++report.bridgedGaps;
      report.bridgedSamples += static_cast<int>(length);
      report.notes.push_back(std::string(names[static_cast<size_t>(j)]) + ": frames " +
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
    if (!flags[static_cast<size_t>(i)]) {
      ++i;
      continue;
    }
    int begin = i;
    while (i < n && flags[static_cast<size_t>(i)]) ++i;
    if (i - begin > bestEnd - bestBegin) {
      bestBegin = begin;
      bestEnd = i;
    }
  }
  return {bestBegin, bestEnd};
}

void fillAllGapsLinearly(Eigen::Ref<Eigen::VectorXd> x) {
  Eigen::Index last = -1;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) continue;
    if (last < 0) x.head(i).setConstant(x[i]);
    for (Eigen::Index k = last + 1; last >= 0 && k < i; ++k)
      x[k] = x[last] + (x[i] - x[last]) * static_cast<double>(k - last) / static_cast<double>(i - last);
    last = i;
  }
  if (last >= 0) x.tail(x.size() - last - 1).setConstant(x[last]);
}

}  // namespace ew
