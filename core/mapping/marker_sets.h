#pragma once
// Skin-marker sets -> the 15 joints of SPEC §1. Entry point: mapMarkerSet (declared in
// joint_mapping.h). The rules, formulas and citations are in docs/JOINTS.md; this header
// exposes the pieces the tests and the docs refer to.
//
// Known sets (matched on labels, case-insensitive, "Subject:" prefixes ignored):
//   ISB (Schreiber-Moissenet)  L_IAS R_IAS L_IPS R_IPS, L_FLE/L_FME, L_FAL/L_TAM, L_SAA,
//                              L_HLE/L_HME, L_RSP/L_UHE, CV7, SJN (no head markers)
//   Plug-in Gait / Helen Hayes LASI RASI + LPSI/RPSI or SACR/VSAC, LKNE, LANK, LSHO, LELB,
//                              LWRA+LWRB or LWRI; C7 CLAV and head markers when present;
//                              the model's LHJC/LKJC/LAJC outputs win when present
//   CMU 41-marker              LFWT RFWT LBWT RBWT, LKNE, LANK, LSHO, LELB, LWRA LWRB,
//                              C7 CLAV, LFHD RFHD LBHD RBHD

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/trial.h"

namespace ew {

// A marker set and the markers it cannot do without ("A|B": either label will do).
struct MarkerSetInfo {
  std::string name;  // becomes JointTrial::source
  std::vector<std::string> required;
};
const std::vector<MarkerSetInfo>& knownMarkerSets();

// "Subject:LASI " -> "LASI": drops a subject prefix up to the last ':', trims, upper case.
std::string normaliseMarkerLabel(std::string_view label);

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
