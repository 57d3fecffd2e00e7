#pragma once
// The steady straight-walking part of an overground trial: trials start from standing,
// accelerate, turn or stop near the walkway's end; the method wants steady gait only.

#include <Eigen/Core>
#include <string>
#include <utility>

namespace ew {

struct SteadyWindowOptions {
  double smoothingS = 1.0;       // velocity averaged over about one stride
  double speedTolerance = 0.25;  // steady: within ±25 % of the trial's median speed
  double headingToleranceDeg = 20.0;
  double treadmillSpeedMps = 0.15;  // below this median speed the walker is in place
};

struct SteadyWindow {
  int begin = 0;
  int end = 0;                 // one past the last frame
  double medianSpeedMps = 0.0;
  bool inPlace = false;        // treadmill / walking on the spot
  std::string note;            // why it was cut, for the warnings list
};

// framesX45: z-up, gap-free. Returns the longest run of frames whose stride-averaged
// pelvis velocity is within the speed and heading tolerances of the median.
SteadyWindow detectSteadyWindow(const Eigen::MatrixXd& framesX45, double rateHz,
                                const SteadyWindowOptions& options = {});

}  // namespace ew
