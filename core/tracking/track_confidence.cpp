#include "core/tracking/track_confidence.h"

#include <algorithm>
#include <cstdlib>
#include <numeric>

namespace ew {

std::vector<int> leastSureFrames(const Eigen::Ref<const Eigen::MatrixXd>& confidence, int firstFrame,
                                 const std::vector<int>& keyframes, int count, int apart) {
  const Eigen::VectorXd means = confidence.rowwise().mean();
  std::vector<Eigen::Index> rows(static_cast<std::size_t>(means.size()));
  std::iota(rows.begin(), rows.end(), Eigen::Index{0});
  std::stable_sort(rows.begin(), rows.end(), [&](Eigen::Index a, Eigen::Index b) { return means(a) < means(b); });
  std::vector<int> chosen;
  for (const Eigen::Index row : rows) {
    if (static_cast<int>(chosen.size()) >= count) break;
    const int frame = firstFrame + static_cast<int>(row);
    if (std::find(keyframes.begin(), keyframes.end(), frame) != keyframes.end()) continue;
    const bool near = std::any_of(chosen.begin(), chosen.end(), [&](int f) { return std::abs(f - frame) < apart; });
    if (!near) chosen.push_back(frame);
  }
  return chosen;
}

}  // namespace ew
