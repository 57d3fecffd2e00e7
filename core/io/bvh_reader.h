#pragma once
// BVH reader: hierarchy (any channel order, 3 or 6 channels on any joint, End Sites,
// CRLF or LF), motion block, forward kinematics to global joint positions. Several roots
// are rejected. The CMU conversion's synthetic T-pose first frame is detected and dropped.
//
// Conventions:
// - Points: one per JOINT (its name) and one per End Site, named "<parent>_End"
//   (made unique with "#2", "#3", … if the file already has such a name).
// - Rotation channels compose in the order listed: R = R(ch1)·R(ch2)·R(ch3), so a point
//   p in a joint's frame is at G_parent · (t + R p) globally (BVH convention, degrees).
// - Position channels, on any joint, replace the matching OFFSET component (the file's
//   translation of that joint relative to its parent); OFFSET fills components without
//   a channel. This is what exporters that write 6 channels on every joint expect.
// - Units: BVH states none. LoadOptions::unitsOverride wins; else the unit is guessed
//   from the standing hip height of the rest pose (guessBvhLengthUnit) with a warning.
// - Axes: +Y up (RawTrial::upAxis = {1, +1}), as the format's convention.

#include <filesystem>
#include <string>
#include <string_view>

#include "core/common/trial.h"
#include "core/io/load_trial.h"

namespace ew {

RawTrial readBvh(const std::filesystem::path& file, const LoadOptions& options = {});
RawTrial parseBvh(std::string_view text, const std::string& name, const LoadOptions& options = {});

// The length unit a BVH skeleton most plausibly uses, from the height of its root above
// its lowest point in the rest pose (a standing adult's hip is 0.5-1.2 m above the floor):
//   < 3 -> "m";  3-28 -> "cmu" (CMU ASF units, 1/0.45 in = 56.444 mm; CMU hips are
//   15-18 units);  28-300 -> "cm";  >= 300 -> "mm". `plausible` is false when the height
// is outside the band that unit implies for an adult (then the guess is a fallback).
struct BvhUnitGuess {
  std::string unit;
  bool plausible = true;
};
BvhUnitGuess guessBvhLengthUnit(double hipHeightUnits);

}  // namespace ew
