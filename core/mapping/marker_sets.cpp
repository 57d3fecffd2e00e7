#include "core/mapping/marker_sets.h"

#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "core/common/errors.h"
#include "core/mapping/joint_mapping.h"

namespace ew {
namespace {

using Eigen::Vector3d;
using Track = Eigen::MatrixX3d;  // frames x 3, millimetres, NaN = missing

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// [SECTION] Marker lookup ---------------------------------------------------------------

class MarkerLookup {
 public:
  explicit MarkerLookup(const RawTrial& raw) : raw_(raw) {
    for (int i = 0; i < raw.pointCount(); ++i) {
      index_.emplace(normaliseMarkerLabel(raw.labels[static_cast<std::size_t>(i)]), i);
    }
  }

  bool has(std::string_view name) const { return index_.count(std::string(name)) > 0; }

  // "A|B": true when any alternative is present.
  bool hasAny(std::string_view alternatives) const { return !firstOf(alternatives).empty(); }

  std::string firstOf(std::string_view alternatives) const {
    std::size_t start = 0;
    while (start <= alternatives.size()) {
      const std::size_t bar = std::min(alternatives.find('|', start), alternatives.size());
      const std::string name(alternatives.substr(start, bar - start));
      if (has(name)) return name;
      start = bar + 1;
    }
    return {};
  }

  // The marker's trajectory; all NaN when the label is absent.
  Track track(std::string_view name) const {
    auto it = index_.find(std::string(name));
    if (it == index_.end()) return Track::Constant(raw_.frameCount(), 3, kNaN);
    return raw_.positionsMm.middleCols(3 * it->second, 3);
  }

  std::optional<Track> optionalTrack(std::string_view alternatives) const {
    const std::string name = firstOf(alternatives);
    if (name.empty()) return std::nullopt;
    return track(name);
  }

  // A marker that may also be given as the midpoint of a pair (PSIS: LPSI+RPSI or SACR).
  Track midOrSingle(std::string_view a, std::string_view b, std::string_view single) const {
    if (has(a) && has(b)) return 0.5 * (track(a) + track(b));
    return track(firstOf(single));
  }

 private:
  const RawTrial& raw_;
  std::map<std::string, int> index_;  // first occurrence of a label wins
};

// [SECTION] Geometry --------------------------------------------------------------------

Vector3d nanVector() { return Vector3d::Constant(kNaN); }

// Unit vector, NaN for a (near) zero or NaN input so a bad frame stays visibly bad.
Vector3d unit(const Vector3d& v) {
  const double n = v.norm();
  return n > 1e-9 ? Vector3d(v / n) : nanVector();
}

Vector3d row(const Track& t, int f) { return t.row(f).transpose(); }

// Joint centre from a lateral marker alone: `halfWidth` towards the body's midline,
// perpendicular to the segment's long axis (proximal joint -> lateral marker). The midline
// direction is the pelvis's (or shoulder girdle's) left-right line, which the knee, ankle
// and elbow flexion axes follow within a few degrees in walking.
Vector3d medialShift(const Vector3d& lateral, const Vector3d& proximal,
                     const Vector3d& towardMidline, double halfWidth) {
  const Vector3d axis = unit(lateral - proximal);
  const Vector3d medial = unit(towardMidline - towardMidline.dot(axis) * axis);
  return lateral + halfWidth * medial;
}

// [SECTION] Landmarks: what every marker set is reduced to ---------------------------------

// A lateral marker and, when the set has one, the medial marker of the same joint.
struct PairedLandmark {
  Track lateral;
  std::optional<Track> medial;
  std::string lateralName, medialName;  // for warnings
};

struct SideLandmarks {
  Track asis;
  PairedLandmark knee, ankle, elbow;
  Track acromion;
  Track wristA;
  std::optional<Track> wristB;  // single-marker wrists (LWRI) have none
  std::optional<Track> hipCentre, kneeCentre, ankleCentre;  // model outputs (PiG/CGM)
};

struct Landmarks {
  std::string source;
  SideLandmarks left, right;
  Track midPsis;
  std::optional<Track> neckBack, neckFront;  // C7/CV7 and CLAV/SJN
  std::vector<Track> head;                   // empty when the set has no head markers
};

PairedLandmark paired(const MarkerLookup& m, const std::string& lateral,
                      const std::string& medialAlternatives) {
  PairedLandmark p;
  p.lateralName = lateral;
  p.lateral = m.track(lateral);
  p.medialName = medialAlternatives;
  p.medial = m.optionalTrack(medialAlternatives);
  return p;
}

// Model joint-centre outputs: "LHJC", or a suffixed variant such as "LHJC_CGM_2.4".
std::optional<Track> modelCentre(const MarkerLookup& m, const RawTrial& raw,
                                 const std::string& name) {
  if (m.has(name)) return m.track(name);
  for (const auto& label : raw.labels) {
    const std::string n = normaliseMarkerLabel(label);
    if (n.rfind(name + "_", 0) == 0) return m.track(n);
  }
  return std::nullopt;
}

Landmarks isbLandmarks(const MarkerLookup& m) {
  Landmarks lm;
  lm.source = "ISB (Schreiber-Moissenet)";
  for (const char* s : {"L_", "R_"}) {
    const std::string p = s;
    SideLandmarks& side = p == "L_" ? lm.left : lm.right;
    side.asis = m.track(p + "IAS");
    side.knee = paired(m, p + "FLE", p + "FME");
    side.ankle = paired(m, p + "FAL", p + "TAM");
    side.elbow = paired(m, p + "HLE", p + "HME");
    side.acromion = m.track(p + "SAA");
    side.wristA = m.track(p + "RSP");
    side.wristB = m.track(p + "UHE");
  }
  lm.midPsis = 0.5 * (m.track("L_IPS") + m.track("R_IPS"));
  lm.neckBack = m.track("CV7");
  lm.neckFront = m.track("SJN");
  return lm;
}

// Plug-in Gait and the older Helen Hayes sets share the lateral-marker layout.
Landmarks plugInGaitLandmarks(const MarkerLookup& m, const RawTrial& raw) {
  Landmarks lm;
  lm.source = "Plug-in Gait / Helen Hayes";
  for (const char* s : {"L", "R"}) {
    const std::string p = s;
    SideLandmarks& side = p == "L" ? lm.left : lm.right;
    side.asis = m.track(p + "ASI");
    side.knee = paired(m, p + "KNE", p + "KNM|" + p + "MKNE|" + p + "MFC");
    side.ankle = paired(m, p + "ANK", p + "MED|" + p + "MMA");
    side.elbow = paired(m, p + "ELB", p + "MEP|" + p + "MELB");
    side.acromion = m.track(p + "SHO");
    side.wristA = m.track(m.firstOf(p + "WRA|" + p + "WRI"));
    if (m.has(p + "WRA") && m.has(p + "WRB")) side.wristB = m.track(p + "WRB");
    side.hipCentre = modelCentre(m, raw, p + "HJC");
    side.kneeCentre = modelCentre(m, raw, p + "KJC");
    side.ankleCentre = modelCentre(m, raw, p + "AJC");
  }
  lm.midPsis = m.midOrSingle("LPSI", "RPSI", "SACR|VSAC|SACRUM");
  if (m.has("C7") && m.has("CLAV")) {
    lm.neckBack = m.track("C7");
    lm.neckFront = m.track("CLAV");
  }
  if (m.has("LFHD") && m.has("RFHD") && m.has("LBHD") && m.has("RBHD")) {
    lm.head = {m.track("LFHD"), m.track("RFHD"), m.track("LBHD"), m.track("RBHD")};
  }
  return lm;
}

// CMU: the waist markers sit on the iliac crest rather than on the ASIS/PSIS, so the
// Harrington regression run on them is an approximation (docs/JOINTS.md).
Landmarks cmuLandmarks(const MarkerLookup& m) {
  Landmarks lm;
  lm.source = "CMU 41-marker";
  for (const char* s : {"L", "R"}) {
    const std::string p = s;
    SideLandmarks& side = p == "L" ? lm.left : lm.right;
    side.asis = m.track(p + "FWT");
    side.knee = paired(m, p + "KNE", "");
    side.ankle = paired(m, p + "ANK", "");
    side.elbow = paired(m, p + "ELB", "");
    side.acromion = m.track(p + "SHO");
    side.wristA = m.track(p + "WRA");
    side.wristB = m.track(p + "WRB");
  }
  lm.midPsis = 0.5 * (m.track("LBWT") + m.track("RBWT"));
  lm.neckBack = m.track("C7");
  lm.neckFront = m.track("CLAV");
  lm.head = {m.track("LFHD"), m.track("RFHD"), m.track("LBHD"), m.track("RBHD")};
  return lm;
}

// [SECTION] Joint rules -------------------------------------------------------------------

void setJoint(JointTrial& out, int f, Joint j, const Vector3d& p) {
  out.positionsMm.block<1, 3>(f, 3 * index(j)) = p.transpose();
}

// Lateral+medial midpoint, or the lateral marker shifted medially (flagged and warned
// about once per trial by flagEstimates).
Vector3d pairedCentre(const PairedLandmark& p, int f, const Vector3d& proximal,
                      const Vector3d& towardMidline, double halfWidth) {
  if (p.medial) return 0.5 * (row(p.lateral, f) + row(*p.medial, f));
  return medialShift(row(p.lateral, f), proximal, towardMidline, halfWidth);
}

void warnLateralOnly(JointTrial& out, const PairedLandmark& p, Joint j, double halfWidth) {
  if (p.medial) return;
  out.estimated[static_cast<std::size_t>(index(j))] = true;
  std::ostringstream w;
  w << jointName(j) << " estimated: no medial marker"
    << (p.medialName.empty() ? std::string() : " (" + p.medialName + ")") << ", placed "
    << halfWidth << " mm medial of " << p.lateralName;
  out.warnings.push_back(w.str());
}

struct SideJoints {
  Joint shoulder, elbow, wrist, hip, knee, ankle;
};
constexpr SideJoints kLeft{Joint::LShoulder, Joint::LElbow, Joint::LWrist,
                           Joint::LHip,      Joint::LKnee,  Joint::LAnkle};
constexpr SideJoints kRight{Joint::RShoulder, Joint::RElbow, Joint::RWrist,
                            Joint::RHip,      Joint::RKnee,  Joint::RAnkle};

// Legs of one side, one frame. `hip` and `otherHip` come from the pelvis rule.
void legJoints(JointTrial& out, int f, const SideLandmarks& s, const SideJoints& j,
               const Vector3d& hip, const Vector3d& otherHip) {
  const Vector3d medial = otherHip - hip;
  const Vector3d knee = s.kneeCentre ? row(*s.kneeCentre, f)
                                     : pairedCentre(s.knee, f, hip, medial, kKneeHalfWidthMm);
  const Vector3d ankle = s.ankleCentre
                             ? row(*s.ankleCentre, f)
                             : pairedCentre(s.ankle, f, knee, medial, kAnkleHalfWidthMm);
  setJoint(out, f, j.hip, hip);
  setJoint(out, f, j.knee, knee);
  setJoint(out, f, j.ankle, ankle);
}

void armJoints(JointTrial& out, int f, const SideLandmarks& s, const SideLandmarks& other,
               const SideJoints& j, const Vector3d& down) {
  const Vector3d acromion = row(s.acromion, f);
  const Vector3d otherAcromion = row(other.acromion, f);
  const double biacromial = (acromion - otherAcromion).norm();
  const Vector3d shoulder = acromion + kShoulderDropFraction * biacromial * down;
  const Vector3d elbow =
      pairedCentre(s.elbow, f, shoulder, otherAcromion - acromion, kElbowHalfWidthMm);
  const Vector3d wrist = s.wristB ? Vector3d(0.5 * (row(s.wristA, f) + row(*s.wristB, f)))
                                  : row(s.wristA, f);
  setJoint(out, f, j.shoulder, shoulder);
  setJoint(out, f, j.elbow, elbow);
  setJoint(out, f, j.wrist, wrist);
}

Vector3d meanOf(const std::vector<Track>& tracks, int f) {
  Vector3d sum = Vector3d::Zero();
  for (const auto& t : tracks) sum += row(t, f);
  return sum / static_cast<double>(tracks.size());
}

void frameJoints(JointTrial& out, int f, const Landmarks& lm) {
  HipCentres hips = harringtonHipCentres(row(lm.left.asis, f), row(lm.right.asis, f),
                                         row(lm.midPsis, f));
  if (lm.left.hipCentre && lm.right.hipCentre) {
    hips = {row(*lm.left.hipCentre, f), row(*lm.right.hipCentre, f)};
  }
  const Vector3d pelvis = 0.5 * (hips.left + hips.right);
  // Neck base: midway between the spinous process of C7 and the jugular notch, inside the
  // body; without trunk markers, the midpoint of the acromion markers.
  const Vector3d sternum =
      lm.neckBack ? Vector3d(0.5 * (row(*lm.neckBack, f) + row(*lm.neckFront, f)))
                  : Vector3d(0.5 * (row(lm.left.acromion, f) + row(lm.right.acromion, f)));
  const Vector3d down = unit(pelvis - sternum);
  setJoint(out, f, Joint::Pelvis, pelvis);
  setJoint(out, f, Joint::Sternum, sternum);
  setJoint(out, f, Joint::Head, lm.head.empty() ? estimateHead(pelvis, sternum) : meanOf(lm.head, f));
  legJoints(out, f, lm.left, kLeft, hips.left, hips.right);
  legJoints(out, f, lm.right, kRight, hips.right, hips.left);
  armJoints(out, f, lm.left, lm.right, kLeft, down);
  armJoints(out, f, lm.right, lm.left, kRight, down);
}

void flagEstimates(JointTrial& out, const Landmarks& lm) {
  auto flag = [&](Joint j) { out.estimated[static_cast<std::size_t>(index(j))] = true; };
  if (lm.head.empty()) {
    flag(Joint::Head);
    out.warnings.push_back("head estimated: the marker set has no head markers (SPEC §1 rule: "
                           "on the pelvis->sternum axis above the sternum)");
  }
  if (!lm.neckBack) {
    flag(Joint::Sternum);
    out.warnings.push_back("sternum estimated: no C7/CLAV markers, using the midpoint of the "
                           "acromion markers");
  }
  for (const auto& [s, j] : {std::pair{&lm.left, kLeft}, std::pair{&lm.right, kRight}}) {
    if (!s->kneeCentre) warnLateralOnly(out, s->knee, j.knee, kKneeHalfWidthMm);
    if (!s->ankleCentre) warnLateralOnly(out, s->ankle, j.ankle, kAnkleHalfWidthMm);
    warnLateralOnly(out, s->elbow, j.elbow, kElbowHalfWidthMm);
    if (!s->wristB) {
      flag(j.wrist);
      out.warnings.push_back(std::string(jointName(j.wrist)) +
                             " estimated: a single wrist marker, taken as the joint centre");
    }
  }
}

JointTrial buildJoints(const RawTrial& raw, const Landmarks& lm) {
  JointTrial out = jointTrialShell(raw, lm.source, raw.frameCount());
  for (int f = 0; f < raw.frameCount(); ++f) frameJoints(out, f, lm);
  flagEstimates(out, lm);
  return out;
}

// [SECTION] Set detection -------------------------------------------------------------------

std::vector<std::string> missingMarkers(const MarkerLookup& m, const MarkerSetInfo& set) {
  std::vector<std::string> missing;
  for (const auto& r : set.required) {
    if (!m.hasAny(r)) missing.push_back(r);
  }
  return missing;
}

[[noreturn]] void throwUnknownSet(const RawTrial& raw, const MarkerLookup& m) {
  std::string msg = "no known marker set matches the " + std::to_string(raw.pointCount()) +
                    " labels [" + listForMessage(raw.labels, 60, " ") + "].";
  for (const auto& set : knownMarkerSets()) {
    msg += " " + set.name + " needs " + listForMessage(set.required, 100, " ") + " (missing " +
           listForMessage(missingMarkers(m, set), 100, " ") + ").";
  }
  throw Error(ErrorKind::UnknownMarkerSet, raw.file, "", msg);
}

}  // namespace

// [SECTION] Public API ----------------------------------------------------------------------

std::string normaliseMarkerLabel(std::string_view label) {
  const std::size_t colon = label.rfind(':');
  if (colon != std::string_view::npos) label.remove_prefix(colon + 1);
  while (!label.empty() && std::isspace(static_cast<unsigned char>(label.front()))) label.remove_prefix(1);
  while (!label.empty() && std::isspace(static_cast<unsigned char>(label.back()))) label.remove_suffix(1);
  std::string out(label);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

const std::vector<MarkerSetInfo>& knownMarkerSets() {
  static const std::vector<MarkerSetInfo> sets = {
      {"ISB (Schreiber-Moissenet)",
       {"L_IAS", "R_IAS", "L_IPS", "R_IPS", "L_FLE", "R_FLE", "L_FAL", "R_FAL", "CV7", "SJN",
        "L_SAA", "R_SAA", "L_HLE", "R_HLE", "L_RSP", "R_RSP", "L_UHE", "R_UHE"}},
      {"Plug-in Gait / Helen Hayes",
       {"LASI", "RASI", "LPSI|SACR|VSAC|SACRUM", "RPSI|SACR|VSAC|SACRUM", "LKNE", "RKNE", "LANK",
        "RANK", "LSHO", "RSHO", "LELB", "RELB", "LWRA|LWRI", "RWRA|RWRI"}},
      {"CMU 41-marker",
       {"LFWT", "RFWT", "LBWT", "RBWT", "LKNE", "RKNE", "LANK", "RANK", "LSHO", "RSHO", "LELB",
        "RELB", "LWRA", "RWRA", "LWRB", "RWRB", "C7", "CLAV", "LFHD", "RFHD", "LBHD", "RBHD"}},
  };
  return sets;
}

HipCentres harringtonHipCentres(const Vector3d& leftAsis, const Vector3d& rightAsis,
                                const Vector3d& midPsis) {
  const Vector3d origin = 0.5 * (leftAsis + rightAsis);
  const Vector3d z = unit(rightAsis - leftAsis);
  const Vector3d back = origin - midPsis;
  const Vector3d x = unit(back - back.dot(z) * z);
  const Vector3d y = z.cross(x);
  const double pw = (rightAsis - leftAsis).norm();
  const double pd = back.norm();
  const Vector3d common = origin + (-0.24 * pd - 9.9) * x + (-0.30 * pw - 10.9) * y;
  const double lateral = 0.33 * pw + 7.3;
  return {common - lateral * z, common + lateral * z};
}

JointTrial mapMarkerSet(const RawTrial& raw) {
  const MarkerLookup m(raw);
  const auto& sets = knownMarkerSets();
  if (missingMarkers(m, sets[0]).empty()) return buildJoints(raw, isbLandmarks(m));
  if (missingMarkers(m, sets[1]).empty()) return buildJoints(raw, plugInGaitLandmarks(m, raw));
  if (missingMarkers(m, sets[2]).empty()) return buildJoints(raw, cmuLandmarks(m));
  throwUnknownSet(raw, m);
}

}  // namespace ew
