#include "core/mapping/raw_motion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/common/statistics.h"

namespace ew {
namespace {

// Per-axis median of the markers seen in frame f; false when fewer than the minimum.
bool frameCentre(const RawTrial& raw, int f, Eigen::Vector3d& centre) {
  std::vector<double> axis[3];
  for (int p = 0; p < raw.pointCount(); ++p) {
    const Eigen::Vector3d x = raw.positionsMm.block<1, 3>(f, 3 * p).transpose();
    if (!x.allFinite()) continue;
    for (int a = 0; a < 3; ++a) axis[a].push_back(x[a]);
  }
  if (static_cast<int>(axis[0].size()) < kMinMarkersForCentre) return false;
  for (int a = 0; a < 3; ++a) centre[a] = median(axis[a]);
  return true;
}

std::string fixed(double v, int digits) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", digits, v);
  return buf;
}

}  // namespace

RawMotion measureRawMotion(const RawTrial& raw) {
  RawMotion m;
  std::vector<std::pair<int, Eigen::Vector3d>> centres;
  for (int f = 0; f < raw.frameCount(); ++f) {
    Eigen::Vector3d c;
    if (frameCentre(raw, f, c)) centres.emplace_back(f, c);
  }
  m.framesWithCentre = static_cast<int>(centres.size());
  if (centres.size() < 2 || raw.rateHz <= 0) return m;
  m.durationS = (centres.back().first - centres.front().first) / raw.rateHz;
  m.travelM = (centres.back().second - centres.front().second).norm() / 1000.0;
  // Path sampled every 0.5 s so marker jitter does not count as travel.
  const int step = std::max(1, static_cast<int>(std::lround(0.5 * raw.rateHz)));
  Eigen::Vector3d last = centres.front().second;
  int lastFrame = centres.front().first;
  for (const auto& [f, c] : centres) {
    if (f - lastFrame < step && f != centres.back().first) continue;
    m.pathM += (c - last).norm() / 1000.0;
    last = c;
    lastFrame = f;
  }
  return m;
}

std::optional<std::string> rawNotWalkingReason(const RawTrial& raw) {
  const RawMotion m = measureRawMotion(raw);
  if (m.framesWithCentre < 2) {
    return "no frame has " + std::to_string(kMinMarkersForCentre) +
           " markers with a position, so nothing moves";
  }
  const std::string travel = "the markers' median centre travels " + fixed(m.travelM, 2) +
                             " m in " + fixed(m.durationS, 1) + " s (" + fixed(m.speedMps(), 2) +
                             " m/s)";
  if (m.travelM < kWalkingMinTravelM || m.speedMps() < kWalkingMinSpeedMps) {
    return travel + "; walking covers at least " + fixed(kWalkingMinTravelM, 1) + " m at " +
           fixed(kWalkingMinSpeedMps, 2) + " m/s";
  }
  if (m.straightness() < kWalkingMinStraightness) {
    return travel + " along a path " + fixed(m.pathM, 2) +
           " m long: it wanders rather than walks steadily";
  }
  return std::nullopt;
}

}  // namespace ew
