#pragma once
// Skin-marker sets -> the 15 joints of METHOD §1. Entry point: mapMarkerSet (declared in
// joint_mapping.h). The sets are data: assets/marker-sets/*.json, read by
// core/mapping/marker_set_table.h, whose named rules use the formulas below. Among the
// tables whose identifying labels the file has, the one that builds the most joints wins
// (the earlier file on a tie); joints it cannot build are JointTrial::missing, and below
// the minimum (pelvis, both knees, both ankles) the mapping fails naming what is missing.
// A trial that does not map and does not walk says "not walking: …" first (raw_motion.h).
// Labels match case-insensitively, "Subject:" prefixes ignored. Rules and citations:
// docs/JOINTS.md.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/trial.h"

namespace ew {

// A marker set and the labels that identify it ("A|B": either label will do).
struct MarkerSetInfo {
  std::string name;  // becomes JointTrial::source
  std::vector<std::string> required;
};
const std::vector<MarkerSetInfo>& knownMarkerSets();

// "Subject:LASI " -> "LASI": drops a subject prefix up to the last ':', trims, upper case
// (ASCII letters), as UTF-8 (labelAsUtf8), so a Latin-1 label in a C3D file and the same
// label in a UTF-8 mapping file compare equal.
std::string normaliseMarkerLabel(std::string_view label);

// A label's bytes as UTF-8: unchanged when they already are, else read as Latin-1 (C3D
// files from European labs carry labels such as "GENOU_\xE9"), so they can go into JSON.
std::string labelAsUtf8(std::string_view label);

// Glenohumeral centre below the acromion marker, as a fraction of the acromion-acromion
// distance, along the trunk's downward axis (Rab, Petuskey & Bagley 2002).
inline constexpr double kShoulderDropFraction = 0.17;

// Marker-centre to joint-centre distances used when only the lateral marker of a joint
// exists (PiG/CMU sets, the two 48-marker Schreiber trials): half the lateral-medial
// marker distance (skin markers on their bases), averaged over both sides and all frames
// of the 16 complete Schreiber-Moissenet C4 trials. Per-trial ranges: knee 60-82 mm,
// ankle 42-52 mm, elbow 37-50 mm (docs/JOINTS.md).
inline constexpr double kKneeHalfWidthMm = 66.0;
inline constexpr double kAnkleHalfWidthMm = 47.0;
inline constexpr double kElbowHalfWidthMm = 43.0;

// Harrington et al. (2007) hip joint centres, one frame, millimetres. Pelvis frame (ISB):
// origin mid-ASIS, z from left to right ASIS, x anterior (towards mid-ASIS from mid-PSIS,
// made orthogonal to z), y = z x x superior. PW = ASIS distance, PD = mid-ASIS to mid-PSIS.
//   x = -0.24 PD - 9.9,  y = -0.30 PW - 10.9,  z = +/-(0.33 PW + 7.3)  (right +, left -)
// NaN in, NaN out.
struct HipCentres {
  Eigen::Vector3d left, right;
};
HipCentres harringtonHipCentres(const Eigen::Vector3d& leftAsis, const Eigen::Vector3d& rightAsis,
                                const Eigen::Vector3d& midPsis);

}  // namespace ew
