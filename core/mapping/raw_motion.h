#pragma once
// Is a marker trial a walk at all? Judged from the raw markers, before any marker set is
// recognised, so a golf swing with unknown labels says "not walking" before anything about
// markers (issue 12). The centre is the per-frame median of the markers (robust to a few
// mislabelled or flying markers); walking carries it steadily across the floor.

#include <optional>
#include <string>

#include "core/common/trial.h"

namespace ew {

struct RawMotion {
  int framesWithCentre = 0;  // frames with at least kMinMarkersForCentre markers
  double durationS = 0;      // first to last such frame
  double travelM = 0;        // straight-line distance between the centre at start and end
  double pathM = 0;          // length of the centre's path sampled every 0.5 s
  double speedMps() const { return durationS > 0 ? travelM / durationS : 0; }
  double straightness() const { return pathM > 0 ? travelM / pathM : 0; }
};

inline constexpr int kMinMarkersForCentre = 3;
// Thresholds (docs/JOINTS.md, "Not walking"), from the c3d-samples: the golf swing's
// centre travels 0.13 m in 4.8 s (0.03 m/s); the slowest walk, TESTBPI.c3d (leg clusters,
// a slow, probably pathological gait), 2.14 m in 9.0 s (0.24 m/s), steadily along one axis.
// 0.15 m/s and 0.5 m sit between the two, below the slowest walking speeds reported for
// pathological gait (~0.2 m/s); a path that wanders (straightness < 0.5) is not a walk.
inline constexpr double kWalkingMinSpeedMps = 0.15;
inline constexpr double kWalkingMinTravelM = 0.5;
inline constexpr double kWalkingMinStraightness = 0.5;

RawMotion measureRawMotion(const RawTrial& raw);

// The reason the trial is not a walk ("the markers' median centre travels 0.12 m in 4.8 s
// (0.03 m/s)"), or nullopt when it may be one. Treadmill walking (no travel) is called not
// walking too: the check is only used when the markers do not map, to order the message.
std::optional<std::string> rawNotWalkingReason(const RawTrial& raw);

}  // namespace ew
