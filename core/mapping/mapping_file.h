#pragma once
// A user's joint mapping file: which of a file's labels make each of the 15 joints, for
// marker sets the program does not know (docs/FORMATS.md, "Joint mapping file"):
//
//   {"eigenwalker_joint_mapping": 1,
//    "joints": {"pelvis": ["LASI", "RASI", "LPSI", "RPSI"],   <- mean of these markers
//               "l_hip": "LHJC",                              <- one marker
//               "head": null, ...}}                           <- absent: model-estimated
//
// Every one of the 15 joint names must appear (null for an absent joint), so a file says
// on its face what it measures. Labels match as in the marker-set tables: case-insensitive,
// "Subject:" prefixes ignored.

#include <array>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/skeleton.h"
#include "core/common/trial.h"

namespace ew {

inline constexpr int kJointMappingVersion = 1;

// One entry per joint (METHOD §1 order): the labels whose mean is the joint; empty = absent.
struct JointMapping {
  std::array<std::vector<std::string>, kJointCount> joints;
};

// Parses the text of a mapping file. Throws Error(Malformed) naming `file` and the key for:
// not JSON, not an object, missing/wrong "eigenwalker_joint_mapping" version, missing
// "joints", an unknown joint name, a joint left out, a value that is not a string / list of
// strings / null, an empty list or empty label, a label repeated within one joint.
JointMapping parseJointMapping(std::string_view text, const std::string& file);

// Reads and parses a mapping file (Error(Io) when it cannot be read).
JointMapping readJointMappingFile(const std::filesystem::path& file);

// The file text for a mapping (all 15 joints, null for absent ones), parseJointMapping's
// inverse.
std::string jointMappingToJson(const JointMapping& mapping);

// Writes jointMappingToJson(mapping) atomically; Error(Io) naming the file on failure.
void writeJointMappingFile(const std::filesystem::path& file, const JointMapping& mapping);

// What the viewer's Data window shows to let a user build a mapping: the trial's labels
// (as in the file, in file order) and a suggestion: the marker set the program recognises
// best, reduced to the markers it reads per joint (a joint built from a single marker or a
// mean keeps those markers; a joint built by a rule keeps the markers the rule reads,
// averaged, which the user should review), or by name (l_knee <- "LKnee") when no set fits.
struct LabelTable {
  std::vector<std::string> labels;
  JointMapping suggested;
  std::string suggestedFrom;  // marker-set name, or "label names" when matched by name
};
LabelTable labelTable(const RawTrial& raw);

// Applies a mapping to a trial's markers. Absent joints (and joints whose markers are NaN in
// every frame) become JointTrial::missing with NaN columns. Throws Error(BadArgument) naming
// `mappingFile` and the joint key when a label is not among the trial's labels, and
// Error(UnknownMarkerSet) when the mapping gives less than the minimum (marker_sets.h:
// kMinimumJointsMessage).
JointTrial applyJointMapping(const RawTrial& raw, const JointMapping& mapping,
                             const std::string& mappingFile);

}  // namespace ew
