#pragma once
// One marker's track from a raw trial, and the mean distance between two tracks, for the
// tests that compare joint centres against landmarks on real trials.

#include <cmath>
#include <limits>
#include <string>

#include "core/common/trial.h"
#include "core/mapping/functional_centre.h"

namespace ew::test {

// frames × 3 of the marker labelled `label`; NaN throughout when the trial has none.
inline MarkerTrack markerTrack(const RawTrial& r, const std::string& label) {
  for (std::size_t k = 0; k < r.labels.size(); ++k) {
    if (r.labels[k] == label) return r.positionsMm.middleCols(3 * static_cast<Eigen::Index>(k), 3);
  }
  return MarkerTrack::Constant(r.frameCount(), 3, std::numeric_limits<double>::quiet_NaN());
}

// Mean distance over the frames where both are finite, mm; NaN when there is none.
inline double meanTrackDistanceMm(const MarkerTrack& a, const MarkerTrack& b) {
  double sum = 0;
  int n = 0;
  for (Eigen::Index f = 0; f < a.rows(); ++f) {
    const double d = (a.row(f) - b.row(f)).norm();
    if (std::isfinite(d)) sum += d, ++n;
  }
  return n ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace ew::test
