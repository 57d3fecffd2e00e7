#pragma once
// The steady straight-walking parts of an overground trial: trials start from standing,
// accelerate, turn round at the walkway's end and come back, or stop; the method wants
// steady straight gait only. A trial is cut into straight segments (the walker keeps one
// heading), and in each the steady part (speed near the segment's median) is found.

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace ew {

struct SteadyWindowOptions {
  double smoothingS = 1.0;            // velocity averaged over about one stride
  double speedTolerance = 0.25;       // steady: within ±25 % of the segment's median speed
  double headingToleranceDeg = 20.0;  // straight: within ±20° of the segment's heading
  double treadmillSpeedMps = 0.15;    // below this median speed the walker is in place
};

// Frames [begin, end) where the walker keeps one heading, moving faster than
// treadmillSpeedMps; [steadyBegin, steadyEnd) is its longest run at steady speed.
struct StraightSegment {
  int begin = 0;
  int end = 0;
  int steadyBegin = 0;
  int steadyEnd = 0;
  double headingDeg = 0.0;  // direction of travel in the horizontal plane (atan2(y, x))
  double medianSpeedMps = 0.0;
  int steadyFrames() const { return steadyEnd - steadyBegin; }
};

struct SteadyWindow {
  int begin = 0;
  int end = 0;  // one past the last frame
  double medianSpeedMps = 0.0;
  bool inPlace = false;                   // treadmill / walking on the spot
  std::string note;                       // why it was cut, for the warnings list
  std::vector<StraightSegment> segments;  // in time order (none when in place)
  int segment = -1;                       // the segment the window lies in (-1: the whole trial)
};

// framesX45: z-up, gap-free, finite. The window is the longest steady run among the
// straight segments; the whole trial when in place or shorter than three frames.
SteadyWindow detectSteadyWindow(const Eigen::MatrixXd& framesX45, double rateHz,
                                const SteadyWindowOptions& options = {});

// "frames 12-340, heading 90°, 1.32 m/s" (for warnings and `info`).
std::string describeSegment(const StraightSegment& segment);

}  // namespace ew
