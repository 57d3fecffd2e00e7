#include "core/tracking/track_confidence.h"

#include <algorithm>
#include <cstdlib>
#include <limits>

namespace ew {

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

}  // namespace ew
