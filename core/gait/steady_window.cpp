#include "core/gait/steady_window.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/common/skeleton.h"
#include "core/gait/gaps.h"

namespace ew {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

double wrapPi(double a) { return std::remainder(a, 2.0 * M_PI); }

// Pelvis velocity (mm/s) at each frame from a central difference over ±half a window,
// clamped at the trial's ends so every frame has a value.
Eigen::MatrixXd strideAveragedVelocity(const Eigen::MatrixXd& m, double rateHz, double windowS) {
  const int frames = static_cast<int>(m.rows());
  const int half = std::max(1, std::min(static_cast<int>(std::lround(0.5 * windowS * rateHz)),
                                        (frames - 1) / 2));
  const auto pelvis = m.middleCols<2>(3 * index(Joint::Pelvis));
  Eigen::MatrixXd velocity(frames, 2);
  for (int r = 0; r < frames; ++r) {
    const int a = std::clamp(r - half, 0, frames - 1 - 2 * half);
    const int b = a + 2 * half;
    velocity.row(r) = (pelvis.row(b) - pelvis.row(a)) * rateHz / static_cast<double>(b - a);
  }
  return velocity;
}

}  // namespace

SteadyWindow detectSteadyWindow(const Eigen::MatrixXd& m, double rateHz,
                                const SteadyWindowOptions& options) {
  SteadyWindow window;
  const int frames = static_cast<int>(m.rows());
  window.end = frames;
  if (frames < 3) return window;
  const Eigen::MatrixXd velocity = strideAveragedVelocity(m, rateHz, options.smoothingS);
  std::vector<double> speed(static_cast<size_t>(frames)), heading(static_cast<size_t>(frames));
  for (int r = 0; r < frames; ++r) {
    speed[static_cast<size_t>(r)] = velocity.row(r).norm();
    heading[static_cast<size_t>(r)] = std::atan2(velocity(r, 1), velocity(r, 0));
  }
  window.medianSpeedMps = median(speed) / 1000.0;
  if (window.medianSpeedMps < options.treadmillSpeedMps) {
    window.inPlace = true;
    return window;
  }
  // Median heading via the mean direction of the frames (robust to wrap-around).
  const double meanHeading = std::atan2(velocity.col(1).sum(), velocity.col(0).sum());
  const double tolerance = options.headingToleranceDeg * M_PI / 180.0;
  const double medianSpeed = median(speed);
  std::vector<bool> steady(static_cast<size_t>(frames));
  for (size_t r = 0; r < steady.size(); ++r) {
    steady[r] = std::abs(speed[r] - medianSpeed) <= options.speedTolerance * medianSpeed &&
                std::abs(wrapPi(heading[r] - meanHeading)) <= tolerance;
  }
  auto [begin, end] = longestRun(steady);
  window.begin = begin;
  window.end = end;
  if (begin > 0 || end < frames) {
    window.note = "steady straight walking in frames " + std::to_string(begin) + "-" +
                  std::to_string(end - 1) + " of " + std::to_string(frames) +
                  " (speed or heading off elsewhere)";
  }
  return window;
}

}  // namespace ew
