#pragma once
// Pose-estimator keypoint layouts as data: each table under assets/keypoint-layouts/ (one
// JSON file per skeleton: BODY_25, BODY_25B, COCO-18, COCO-17, Halpe-26, MediaPipe-33)
// names its points in the order a file writes them and, for each of the 15 joints of
// METHOD §1, the points whose mean is the joint, as alternatives tried in order
// (docs/KEYPOINTS.md). A joint a layout builds from other points (the head from the ears,
// the sternum from the shoulders) is flagged derived, with the reason.

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/skeleton.h"
#include "core/common/trial.h"

namespace ew {

// Per joint, a displacement in the walker's canonical frame (METHOD §2), mm.
using JointOffsetsMm = std::array<std::array<double, 3>, kJointCount>;
bool anyOffset(const JointOffsetsMm& offsets);

struct KeypointLayout {
  std::string name;                 // "BODY_25B"
  std::string about;                // what writes it, where it is defined
  std::string file;                 // "assets/keypoint-layouts/….json"
  std::vector<std::string> points;  // in file order
  // Per joint: alternatives, each a list of point indices whose mean is the joint.
  std::array<std::vector<std::vector<int>>, kJointCount> joints;
  std::array<std::string, kJointCount> derived;  // non-empty: how the joint is derived
  // Where the detector puts a joint relative to motion capture's joint centre, in the walker's
  // canonical frame (METHOD §2: x right, y forward, z up), mm; zero where the two agree. Only
  // the hips have one in the shipped tables (docs/KEYPOINTS.md, "Detector hips").
  JointOffsetsMm detectorOffsetMm{};
  std::string detectorOffsetSource;  // where the offsets come from, for the user
  // The feet's heel and toe (FootPoint order; the table's optional "feet": r_heel, r_toe,
  // l_heel, l_toe), alternatives as for joints, each tried per frame. Empty: no foot points.
  std::array<std::vector<std::vector<int>>, kFootPointCount> feet;
  bool hasFeet() const;
};

// The largest detector offset a table may state, mm per coordinate.
inline constexpr double kMaxDetectorOffsetMm = 200.0;

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

// A layout for a file that names its own points (DeepLabCut body parts), built in
// custom_layout.cpp. With a joint mapping file (core/mapping/mapping_file.h) each joint is
// the mean of the points the mapping lists for it (Error(BadArgument) naming the mapping file
// and the joint key for a name not among `names`). Without one: the embedded layout whose
// point names are `names` (case-insensitive, in any order), else Error(BadData) naming
// `file`, listing its points and asking for a mapping file.
struct PointNamesLayout {
  std::shared_ptr<const KeypointLayout> layout;  // an embedded layout, or one built here
  std::string source;                            // how it was decided, for the user
};
PointNamesLayout layoutForPointNames(const std::vector<std::string>& names, const std::string& file,
                                     const std::optional<std::filesystem::path>& mappingFile);

}  // namespace ew
