#include "core/tracking/track_confidence.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace ew {
namespace {

// Sums of distances along the track's motion, each O(log frames) from prefix sums: the cost
// of a stretch of frames is how far (px of motion) each lies from the keyframe that serves it.
class MotionDistances {
 public:
  explicit MotionDistances(const Eigen::VectorXd& cumulative) : c_(cumulative), prefix_(c_.size() + 1) {
    prefix_(0) = 0.0;
    for (Eigen::Index i = 0; i < c_.size(); ++i) prefix_(i + 1) = prefix_(i) + c_(i);
  }
  Eigen::Index frames() const { return c_.size(); }
  // Frames before row b, served by b.
  double before(Eigen::Index b) const { return static_cast<double>(b) * c_(b) - sum(0, b); }
  // Frames after row a, served by a.
  double after(Eigen::Index a) const {
    return sum(a + 1, frames()) - static_cast<double>(frames() - 1 - a) * c_(a);
  }
  // Frames strictly between rows a < b, each served by the nearer of the two.
  double between(Eigen::Index a, Eigen::Index b) const {
    const double middle = 0.5 * (c_(a) + c_(b));
    const auto split = static_cast<Eigen::Index>(
        std::upper_bound(c_.data() + a + 1, c_.data() + b, middle) - c_.data());
    return sum(a + 1, split) - static_cast<double>(split - 1 - a) * c_(a) +
           static_cast<double>(b - split) * c_(b) - sum(split, b);
  }

 private:
  double sum(Eigen::Index from, Eigen::Index to) const { return prefix_(to) - prefix_(from); }  // [from, to)
  Eigen::VectorXd c_, prefix_;
};

// The row whose marks cut the summed distance most, given the keyframes' rows (sorted); -1
// when none cuts it (no motion anywhere).
Eigen::Index bestNewKeyframeRow(const MotionDistances& d, const std::vector<Eigen::Index>& rows) {
  Eigen::Index best = -1;
  double bestGain = 0.0;
  const auto consider = [&](Eigen::Index row, double gain) {
    if (gain > bestGain * (1.0 + 1e-12) + 1e-9) best = row, bestGain = gain;
  };
  const Eigen::Index n = d.frames();
  if (rows.empty()) {
    const double all = d.after(0);
    for (Eigen::Index x = 0; x < n; ++x) consider(x, all - (d.before(x) + d.after(x)));
    return best;
  }
  for (Eigen::Index x = 0; x < rows.front(); ++x)
    consider(x, d.before(rows.front()) - (d.before(x) + d.between(x, rows.front())));
  for (size_t i = 0; i + 1 < rows.size(); ++i) {
    const Eigen::Index a = rows[i], b = rows[i + 1];
    const double now = d.between(a, b);
    for (Eigen::Index x = a + 1; x < b; ++x) consider(x, now - (d.between(a, x) + d.between(x, b)));
  }
  for (Eigen::Index x = rows.back() + 1; x < n; ++x)
    consider(x, d.after(rows.back()) - (d.between(rows.back(), x) + d.after(x)));
  return best;
}

}  // namespace

std::vector<int> leastSureFrames(const Eigen::Ref<const Eigen::VectorXd>& meanConfidence, int firstFrame,
                                 std::vector<int> keyframes, int count, int apart) {
  std::sort(keyframes.begin(), keyframes.end());
  std::vector<int> chosen;
  const auto eligible = [&](int frame) {
    return !std::binary_search(keyframes.begin(), keyframes.end(), frame) &&
           std::none_of(chosen.begin(), chosen.end(), [&](int f) { return std::abs(f - frame) < apart; });
  };
  while (static_cast<int>(chosen.size()) < count) {
    int least = -1;
    double lowest = std::numeric_limits<double>::infinity();
    for (Eigen::Index row = 0; row < meanConfidence.size(); ++row) {
      const int frame = firstFrame + static_cast<int>(row);
      if (meanConfidence(row) < lowest && eligible(frame)) least = frame, lowest = meanConfidence(row);
    }
    if (least < 0) break;
    chosen.push_back(least);
  }
  return chosen;
}

Eigen::VectorXd cumulativeMotionPx(const Eigen::Ref<const Eigen::MatrixXd>& trackPx) {
  Eigen::VectorXd cumulative = Eigen::VectorXd::Zero(trackPx.rows());
  for (Eigen::Index r = 1; r < trackPx.rows(); ++r) {
    double moved = 0.0;
    int seen = 0;
    for (Eigen::Index j = 0; j + 1 < trackPx.cols(); j += 2) {
      const double du = trackPx(r, j) - trackPx(r - 1, j), dv = trackPx(r, j + 1) - trackPx(r - 1, j + 1);
      if (!std::isfinite(du) || !std::isfinite(dv)) continue;
      moved += std::hypot(du, dv);
      ++seen;
    }
    cumulative(r) = cumulative(r - 1) + (seen > 0 ? moved / seen : 0.0);
  }
  return cumulative;
}

std::vector<int> framesToMarkNext(const Eigen::Ref<const Eigen::MatrixXd>& trackPx, int firstFrame,
                                  const std::vector<int>& keyframes, int count) {
  return framesToMarkNextAlong(cumulativeMotionPx(trackPx), firstFrame, keyframes, count);
}

std::vector<int> framesToMarkNextAlong(const Eigen::VectorXd& cumulativeMotion, int firstFrame,
                                       const std::vector<int>& keyframes, int count) {
  if (cumulativeMotion.size() == 0) return {};
  const MotionDistances distances(cumulativeMotion);
  std::vector<Eigen::Index> rows;
  for (const int k : keyframes)
    if (k >= firstFrame && k - firstFrame < cumulativeMotion.size()) rows.push_back(k - firstFrame);
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  std::vector<int> chosen;
  while (static_cast<int>(chosen.size()) < count) {
    const Eigen::Index row = bestNewKeyframeRow(distances, rows);
    if (row < 0) break;
    chosen.push_back(firstFrame + static_cast<int>(row));
    rows.insert(std::upper_bound(rows.begin(), rows.end(), row), row);
  }
  return chosen;
}

}  // namespace ew
