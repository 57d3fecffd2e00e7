#pragma once
// Pose-estimator keypoint layouts as data: each table under assets/keypoint-layouts/ (one
// JSON file per skeleton: BODY_25, BODY_25B, COCO-18, COCO-17, Halpe-26, MediaPipe-33)
// names its points in the order a file writes them and, for each of the 15 joints of
// SPEC §1, the points whose mean is the joint, as alternatives tried in order
// (docs/KEYPOINTS.md). A joint a layout builds from other points (the head from the ears,
// the sternum from the shoulders) is flagged derived, with the reason.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/skeleton.h"

namespace ew {

struct KeypointLayout {
  std::string name;                 // "BODY_25B"
  std::string about;                // what writes it, where it is defined
  std::string file;                 // "assets/keypoint-layouts/….json"
  std::vector<std::string> points;  // in file order
  // Per joint: alternatives, each a list of point indices whose mean is the joint.
  std::array<std::vector<std::vector<int>>, kJointCount> joints;
  std::array<std::string, kJointCount> derived;  // non-empty: how the joint is derived
};

// Parses one layout table; Error(Malformed) naming `file` and the key on any problem
// (unknown joint, a point not among "points", a repeated point name, an empty list).
KeypointLayout parseKeypointLayout(std::string_view json, const std::string& file);

// The embedded layouts, in file-name order.
const std::vector<KeypointLayout>& keypointLayouts();

// The layout of that name (case-insensitive; "body25b" and "BODY_25B" both work). Throws
// Error(BadArgument) listing the known names.
const KeypointLayout& keypointLayoutNamed(std::string_view name);

// The layouts with exactly `pointCount` points (BODY_25 and BODY_25B share 25).
std::vector<const KeypointLayout*> keypointLayoutsWithPoints(int pointCount);

}  // namespace ew
