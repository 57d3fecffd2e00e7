#include "core/gait/steady_window.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/common/skeleton.h"
#include "core/common/statistics.h"
#include "core/gait/gaps.h"

namespace ew {
namespace {

double wrapPi(double a) { return std::remainder(a, 2.0 * M_PI); }

// Pelvis velocity (mm/s) at each frame from a central difference over ±half a window,
// clamped at the trial's ends so every frame has a value.
Eigen::MatrixXd strideAveragedVelocity(const Eigen::MatrixXd& m, double rateHz, double windowS) {
  const int frames = static_cast<int>(m.rows());
  const int half = std::max(
      1, std::min(static_cast<int>(std::lround(0.5 * windowS * rateHz)), (frames - 1) / 2));
  const auto pelvis = m.middleCols<2>(3 * index(Joint::Pelvis));
  Eigen::MatrixXd velocity(frames, 2);
  for (int r = 0; r < frames; ++r) {
    const int a = std::clamp(r - half, 0, frames - 1 - 2 * half);
    const int b = a + 2 * half;
    velocity.row(r) = (pelvis.row(b) - pelvis.row(a)) * rateHz / static_cast<double>(b - a);
  }
  return velocity;
}

// Splits the moving frames into runs of one heading: a run goes on while each frame's
// heading stays within the tolerance of the run's mean direction so far, so a turn
// (the heading sweeping through 180°) ends one run and, once straight again, starts another.
std::vector<StraightSegment> straightRuns(const Eigen::MatrixXd& velocity, double minSpeedMmS,
                                          double toleranceRad) {
  std::vector<StraightSegment> runs;
  const int frames = static_cast<int>(velocity.rows());
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // sum of unit headings in the run
  for (int r = 0; r < frames; ++r) {
    const Eigen::Vector2d v = velocity.row(r).transpose();
    const double speed = v.norm();
    const bool moving = std::isfinite(speed) && speed >= minSpeedMmS;
    const bool continues =
        moving && !runs.empty() && runs.back().end == r &&
        std::abs(wrapPi(std::atan2(v.y(), v.x()) - std::atan2(direction.y(), direction.x()))) <=
            toleranceRad;
    if (continues) {
      runs.back().end = r + 1;
      direction += v / speed;
    } else if (moving) {
      runs.push_back(StraightSegment{r, r + 1, r, r + 1, 0.0, 0.0});
      direction = v / speed;
    }
  }
  return runs;
}

// Fills the steady part, heading and median speed of a straight run.
void findSteadyPart(StraightSegment& s, const Eigen::MatrixXd& velocity, double tolerance) {
  std::vector<double> speed;
  for (int r = s.begin; r < s.end; ++r) speed.push_back(velocity.row(r).norm());
  const double medianSpeed = median(speed);
  std::vector<bool> steady(speed.size());
  for (size_t k = 0; k < speed.size(); ++k) {
    steady[k] = std::abs(speed[k] - medianSpeed) <= tolerance * medianSpeed;
  }
  const auto [begin, end] = longestRun(steady);
  s.steadyBegin = s.begin + begin;
  s.steadyEnd = s.begin + end;
  const Eigen::Vector2d sum = velocity.middleRows(s.begin, s.end - s.begin).colwise().sum();
  s.headingDeg = std::atan2(sum.y(), sum.x()) * 180.0 / M_PI;
  s.medianSpeedMps = medianSpeed / 1000.0;
}

int longestSteadySegment(const std::vector<StraightSegment>& segments) {
  int best = -1;
  for (int k = 0; k < static_cast<int>(segments.size()); ++k) {
    if (best < 0 || segments[static_cast<size_t>(k)].steadyFrames() >
                        segments[static_cast<size_t>(best)].steadyFrames()) {
      best = k;
    }
  }
  return best;
}

}  // namespace

std::string describeSegment(const StraightSegment& s) {
  std::ostringstream out;
  out << "frames " << s.begin << "-" << s.end - 1 << ", heading " << std::lround(s.headingDeg)
      << "°, " << std::round(s.medianSpeedMps * 100.0) / 100.0 << " m/s";
  return out.str();
}

SteadyWindow detectSteadyWindow(const Eigen::MatrixXd& m, double rateHz,
                                const SteadyWindowOptions& options) {
  SteadyWindow window;
  const int frames = static_cast<int>(m.rows());
  window.end = frames;
  if (frames < 3) return window;
  const Eigen::MatrixXd velocity = strideAveragedVelocity(m, rateHz, options.smoothingS);
  std::vector<double> speed(static_cast<size_t>(frames));
  for (int r = 0; r < frames; ++r) speed[static_cast<size_t>(r)] = velocity.row(r).norm();
  window.medianSpeedMps = median(speed) / 1000.0;
  if (!(window.medianSpeedMps >= options.treadmillSpeedMps)) {
    window.inPlace = true;
    return window;
  }
  window.segments = straightRuns(velocity, 1000.0 * options.treadmillSpeedMps,
                                 options.headingToleranceDeg * M_PI / 180.0);
  for (auto& s : window.segments) findSteadyPart(s, velocity, options.speedTolerance);
  window.segment = longestSteadySegment(window.segments);
  const StraightSegment& chosen = window.segments[static_cast<size_t>(window.segment)];
  window.begin = chosen.steadyBegin;
  window.end = chosen.steadyEnd;
  window.medianSpeedMps = chosen.medianSpeedMps;
  if (window.begin > 0 || window.end < frames) {
    window.note = "steady straight walking in frames " + std::to_string(window.begin) + "-" +
                  std::to_string(window.end - 1) + " of " + std::to_string(frames) +
                  " (speed or heading off elsewhere)";
  }
  return window;
}

}  // namespace ew
