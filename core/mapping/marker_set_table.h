#pragma once
// Marker sets as data: each table under assets/marker-sets/ (one JSON file per set) names
// the set, the labels that identify it, and for each of the 15 joints the rules that build
// it, tried in order (docs/JOINTS.md, "Marker-set tables"). The rules are the named
// operations below, implemented in marker_set_table.cpp; a table only says which markers
// feed which rule. A user mapping file (mapping_file.h) is turned into a table too.
//
// Marker references: "LASI" one label; "LPSI|SACR" the first of these the file has;
// "LHJC*" the label LHJC or any LHJC_<suffix> (model outputs such as LHJC_CGM_2.4). Labels
// compare case-insensitively with "Subject:" prefixes dropped (normaliseMarkerLabel). A
// marker counts as present only when it has a position in at least one frame.

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/common/skeleton.h"
#include "core/common/trial.h"

namespace ew {

enum class RuleOp {
  Mean,           // mean of `markers` (one marker: that marker)
  HarringtonHip,  // Harrington (2007) hip of `side` from l_asis, r_asis, mean of `markers` (PSIS)
  MidJoints,      // mean of `joints` built before
  LateralMedial,  // mid lateral/medial; without the medial marker, lateral shifted medially
  ShoulderDrop,   // acromion lowered along the trunk (Rab 2002), needs pelvis and sternum
  HeadAboveSternum,  // METHOD §1 head rule from pelvis and sternum
  FunctionalCentre,  // SCoRE centre of two clusters: `markers` proximal, `distal` (3+ each)
  FunctionalHip,     // hip of `side` from pelvis cluster `markers`, thighs `distal` (this side)
                     // and `otherDistal`, the pair set `widthMm` apart (symmetricFunctionalHips)
};

// Which of the measured half-widths (marker_sets.h) a lateral-only joint is shifted by.
enum class HalfWidth { Knee, Ankle, Elbow };

struct MarkerRule {
  RuleOp op = RuleOp::Mean;
  std::vector<std::string> markers;  // Mean; HarringtonHip: the PSIS markers (mean)
  std::string leftAsis, rightAsis;   // HarringtonHip
  Side side = Side::Left;            // HarringtonHip, FunctionalHip
  std::string lateral, medial;       // LateralMedial (medial may be empty)
  std::vector<Joint> joints;         // MidJoints; LateralMedial: proximal, midline from, to
  HalfWidth halfWidth = HalfWidth::Knee;
  std::string acromion, otherAcromion;  // ShoulderDrop
  std::vector<std::string> distal;      // FunctionalCentre: the distal segment's cluster
  std::vector<std::string> otherDistal; // FunctionalHip: the other side's thigh cluster
  double widthMm = 0;                   // FunctionalHip: distance between the hip centres
  std::optional<Joint> anchor;          // FunctionalCentre: joint a hinge's axis point is nearest
  std::string estimated;  // non-empty: joint flagged estimated, warning "<joint> estimated: …"
};

struct MarkerSetTable {
  std::string name;                   // becomes JointTrial::source
  std::string file;                   // "assets/marker-sets/…json" or the user's mapping file
  std::vector<std::string> identify;  // all present (each may be "A|B") for the set to apply
  std::array<std::vector<MarkerRule>, kJointCount> joints;  // alternatives, first usable wins
  // The feet's heel and toe (FootPoint order; the table's optional "feet" object, keys
  // r_heel, r_toe, l_heel, l_toe): "mean" rules only, alternatives as for joints. A point no
  // rule builds is NaN in JointTrial::feetMm; none built leaves feetMm empty.
  std::array<std::vector<MarkerRule>, kFootPointCount> feet;
};

// Parses one table; Error(Malformed) naming `file` and the key on any problem.
MarkerSetTable parseMarkerSetTable(std::string_view json, const std::string& file);

// The embedded tables (assets/marker-sets/*.json), in file-name order: on a tie in joints
// built, the earlier table wins.
const std::vector<MarkerSetTable>& markerSetTables();

// What a table makes of a trial's labels: per joint the index of the rule used, -1 when
// no rule can be applied (the joint is missing).
struct TablePlan {
  bool identified = false;
  std::vector<std::string> identifyMissing;
  std::array<int, kJointCount> rule{};
  std::array<int, kFootPointCount> feet{};  // per foot point, the rule used or -1
  int jointCount() const;
};
TablePlan planMarkerSetTable(const MarkerSetTable& table, const RawTrial& raw);

// Builds the joints: missing joints are NaN and flagged JointTrial::missing. The feet's
// points the plan has go to JointTrial::feetMm (a warning names those missing when some are).
JointTrial applyMarkerSetTable(const MarkerSetTable& table, const TablePlan& plan,
                               const RawTrial& raw);

// The minimum a mapping must give: pelvis, both knees, both ankles (the hips follow from
// the pelvis and the legs in every set we read; the rest a model can estimate).
inline constexpr std::array<Joint, 5> kMinimumJoints = {Joint::Pelvis, Joint::LKnee, Joint::RKnee,
                                                        Joint::LAnkle, Joint::RAnkle};
// Names of the minimum joints the plan lacks (empty: enough).
std::vector<std::string> missingMinimumJoints(const TablePlan& plan);

// v / |v|, or NaN where v is too short to have a direction (two markers on one spot).
Eigen::Vector3d unitOrNaN(const Eigen::Vector3d& v);

}  // namespace ew
