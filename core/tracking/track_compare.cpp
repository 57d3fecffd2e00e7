#include "core/tracking/track_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/common/statistics.h"

namespace ew {

TrackDistance compareTracks(const Eigen::Ref<const Eigen::MatrixXd>& trackPx, int firstFrame,
                            const Eigen::Ref<const Eigen::MatrixXd>& referencePx,
                            const std::array<bool, kJointCount>& joints, double withinPx) {
  TrackDistance d;
  d.withinPx = withinPx;
  std::vector<double> all;
  const auto shareWithin = [withinPx](const std::vector<double>& distances) {
    if (distances.empty()) return std::numeric_limits<double>::quiet_NaN();
    const auto near = std::count_if(distances.begin(), distances.end(), [&](double x) { return x <= withinPx; });
    return static_cast<double>(near) / static_cast<double>(distances.size());
  };
  for (int j = 0; j < kJointCount; ++j) {
    std::vector<double> distances;
    for (Eigen::Index row = 0; joints[j] && row < trackPx.rows(); ++row) {
      const Eigen::Index frame = firstFrame + row;
      if (frame < 0 || frame >= referencePx.rows()) continue;
      const double dx = trackPx(row, 2 * j) - referencePx(frame, 2 * j);
      const double dy = trackPx(row, 2 * j + 1) - referencePx(frame, 2 * j + 1);
      if (std::isnan(dx) || std::isnan(dy)) continue;
      distances.push_back(std::hypot(dx, dy));
    }
    d.frames[j] = static_cast<int>(distances.size());
    d.medianPx[j] = median(distances);
    d.p95Px[j] = percentile(distances, 0.95);
    d.shareWithin[j] = shareWithin(distances);
    all.insert(all.end(), distances.begin(), distances.end());
  }
  d.jointFrames = static_cast<int>(all.size());
  d.medianAllPx = median(all);
  d.p95AllPx = percentile(all, 0.95);
  d.shareWithinAll = all.empty() ? 0.0 : shareWithin(all);
  return d;
}

}  // namespace ew
