#include "core/tracking/track_compare.h"

#include <cmath>
#include <limits>
#include <vector>

#include "core/common/statistics.h"

namespace ew {

TrackDistance compareTracks(const Eigen::Ref<const Eigen::MatrixXd>& trackPx, int firstFrame,
                            const Eigen::Ref<const Eigen::MatrixXd>& referencePx,
                            const std::array<bool, kJointCount>& joints) {
  TrackDistance d;
  std::vector<double> all;
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
    all.insert(all.end(), distances.begin(), distances.end());
  }
  d.jointFrames = static_cast<int>(all.size());
  d.medianAllPx = median(all);
  d.p95AllPx = percentile(all, 0.95);
  return d;
}

}  // namespace ew
