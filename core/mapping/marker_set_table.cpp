#include "core/mapping/marker_set_table.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <tuple>

#include "core/assets/embedded_assets.h"
#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/mapping/functional_centre.h"
#include "core/mapping/joint_mapping.h"
#include "core/mapping/marker_sets.h"

namespace ew {
namespace {

using Eigen::Vector3d;
using nlohmann::json;

// Joints are built in this order so a rule only reads joints built before it: hips, then
// pelvis (mid-hips), legs, trunk, head (needs pelvis and sternum), arms.
constexpr std::array<Joint, kJointCount> kBuildOrder = {
    Joint::RHip,      Joint::LHip,   Joint::Pelvis,  Joint::RKnee,  Joint::LKnee,
    Joint::RAnkle,    Joint::LAnkle, Joint::Sternum, Joint::Head,   Joint::RShoulder,
    Joint::LShoulder, Joint::RElbow, Joint::LElbow,  Joint::RWrist, Joint::LWrist};

std::size_t at(Joint j) { return static_cast<std::size_t>(index(j)); }

// [SECTION] Marker lookup ---------------------------------------------------------------

// The trial's labels, normalised; first occurrence wins. `withData_` keeps those with a
// position in at least one frame: only they feed rules, while a set is identified by its
// labels alone (a file whose knee markers were never seen is still that set, short of knees).
class Markers {
 public:
  explicit Markers(const RawTrial& raw) : raw_(raw) {
    for (int i = 0; i < raw.pointCount(); ++i) {
      const std::string name = normaliseMarkerLabel(raw.labels[static_cast<std::size_t>(i)]);
      labels_.emplace(name, i);
      if (raw.positionsMm.middleCols(3 * i, 3).array().isFinite().any()) withData_.emplace(name, i);
    }
  }

  // Column block of the first alternative present with data, or -1.
  int resolve(std::string_view ref) const { return resolveIn(withData_, ref); }
  bool hasLabel(std::string_view ref) const { return resolveIn(labels_, ref) >= 0; }

  Vector3d at(int point, int frame) const {
    return raw_.positionsMm.block<1, 3>(frame, 3 * point).transpose();
  }

 private:
  using Index = std::map<std::string, int>;

  static int resolveIn(const Index& index, std::string_view ref) {
    std::size_t start = 0;
    while (start <= ref.size()) {
      const std::size_t bar = std::min(ref.find('|', start), ref.size());
      const int i = resolveOne(index, ref.substr(start, bar - start));
      if (i >= 0) return i;
      start = bar + 1;
    }
    return -1;
  }

  static int resolveOne(const Index& index, std::string_view ref) {
    std::string name = normaliseMarkerLabel(ref);
    const bool variants = !name.empty() && name.back() == '*';
    if (variants) name.pop_back();
    if (auto it = index.find(name); it != index.end()) return it->second;
    if (!variants) return -1;
    for (const auto& [label, i] : index) {
      if (label.rfind(name + "_", 0) == 0) return i;
    }
    return -1;
  }

  const RawTrial& raw_;
  Index labels_, withData_;
};

// [SECTION] Parsing -----------------------------------------------------------------------

Joint jointFromName(const std::string& name, const std::string& file, const std::string& key) {
  for (int j = 0; j < kJointCount; ++j) {
    if (kJointNames[static_cast<std::size_t>(j)] == name) return static_cast<Joint>(j);
  }
  throwMalformed(file, key, "unknown joint name '" + name + "'");
}

std::string str(const json& o, const char* name, const std::string& file, const std::string& key,
                bool optional = false) {
  if (!o.contains(name)) {
    if (optional) return {};
    throwMalformed(file, key + "." + name, "missing");
  }
  if (!o[name].is_string() || o[name].get<std::string>().empty())
    throwMalformed(file, key + "." + name, "must be a non-empty string");
  return o[name].get<std::string>();
}

std::vector<std::string> strings(const json& o, const char* name, const std::string& file,
                                 const std::string& key) {
  const std::string k = key + "." + name;
  if (!o.contains(name) || !o[name].is_array() || o[name].empty())
    throwMalformed(file, k, "must be a non-empty list of labels");
  std::vector<std::string> out;
  for (const auto& v : o[name]) {
    if (!v.is_string() || v.get<std::string>().empty()) throwMalformed(file, k, "labels must be strings");
    out.push_back(v.get<std::string>());
  }
  return out;
}

std::vector<Joint> jointList(const json& o, const char* name, std::size_t count,
                             const std::string& file, const std::string& key) {
  std::vector<Joint> out;
  for (const auto& s : strings(o, name, file, key)) out.push_back(jointFromName(s, file, key));
  if (count && out.size() != count)
    throwMalformed(file, key + "." + name, "needs " + std::to_string(count) + " joint names");
  return out;
}

HalfWidth halfWidthFrom(const std::string& s, const std::string& file, const std::string& key) {
  if (s == "knee") return HalfWidth::Knee;
  if (s == "ankle") return HalfWidth::Ankle;
  if (s == "elbow") return HalfWidth::Elbow;
  throwMalformed(file, key + ".half_width", "must be knee, ankle or elbow, not '" + s + "'");
}

Side sideFrom(const json& o, const std::string& file, const std::string& key) {
  const std::string side = str(o, "side", file, key);
  if (side != "left" && side != "right") throwMalformed(file, key + ".side", "must be left or right");
  return side == "left" ? Side::Left : Side::Right;
}

// A human inter-hip distance: anything outside is a unit or typing mistake.
constexpr double kMinHipWidthMm = 80, kMaxHipWidthMm = 400;

void parseFunctionalHip(const json& o, const std::string& file, const std::string& key,
                        MarkerRule& r) {
  r.op = RuleOp::FunctionalHip;
  r.side = sideFrom(o, file, key);
  r.markers = strings(o, "pelvis", file, key);
  r.distal = strings(o, "thigh", file, key);
  r.otherDistal = strings(o, "other_thigh", file, key);
  if (r.markers.size() < 3 || r.distal.size() < 3 || r.otherDistal.size() < 3)
    throwMalformed(file, key, "a functional hip needs 3 or more markers in each cluster");
  if (!o.contains("width_mm") || !o["width_mm"].is_number())
    throwMalformed(file, key + ".width_mm", "must be a number (mm between the hip centres)");
  r.widthMm = o["width_mm"].get<double>();
  if (!(r.widthMm >= kMinHipWidthMm && r.widthMm <= kMaxHipWidthMm))
    throwMalformed(file, key + ".width_mm", "must be between 80 and 400 mm");
}

MarkerRule parseRule(const json& o, const std::string& file, const std::string& key) {
  if (!o.is_object()) throwMalformed(file, key, "a rule must be an object with \"op\"");
  MarkerRule r;
  const std::string op = str(o, "op", file, key);
  r.estimated = str(o, "estimated", file, key, true);
  if (op == "mean") {
    r.markers = strings(o, "markers", file, key);
  } else if (op == "harrington_hip") {
    r.op = RuleOp::HarringtonHip;
    r.side = sideFrom(o, file, key);
    r.leftAsis = str(o, "l_asis", file, key);
    r.rightAsis = str(o, "r_asis", file, key);
    r.markers = strings(o, "psis", file, key);
  } else if (op == "mid_joints") {
    r.op = RuleOp::MidJoints;
    r.joints = jointList(o, "joints", 0, file, key);
  } else if (op == "lateral_medial") {
    r.op = RuleOp::LateralMedial;
    r.lateral = str(o, "lateral", file, key);
    r.medial = str(o, "medial", file, key, true);
    r.joints = {jointFromName(str(o, "proximal", file, key), file, key + ".proximal")};
    for (Joint j : jointList(o, "midline", 2, file, key)) r.joints.push_back(j);
    r.halfWidth = halfWidthFrom(str(o, "half_width", file, key), file, key);
  } else if (op == "shoulder_drop") {
    r.op = RuleOp::ShoulderDrop;
    r.acromion = str(o, "acromion", file, key);
    r.otherAcromion = str(o, "other_acromion", file, key);
  } else if (op == "head_above_sternum") {
    r.op = RuleOp::HeadAboveSternum;
  } else if (op == "functional_centre") {
    r.op = RuleOp::FunctionalCentre;
    r.markers = strings(o, "proximal", file, key);
    r.distal = strings(o, "distal", file, key);
    if (r.markers.size() < 3 || r.distal.size() < 3)
      throwMalformed(file, key, "a functional centre needs 3 or more markers in each cluster");
    const std::string anchor = str(o, "anchor", file, key, true);
    if (!anchor.empty()) r.anchor = jointFromName(anchor, file, key + ".anchor");
  } else if (op == "functional_hip") {
    parseFunctionalHip(o, file, key, r);
  } else {
    throwMalformed(file, key + ".op", "unknown rule '" + op + "'");
  }
  return r;
}

std::size_t footPointFromName(const std::string& name, const std::string& file, const std::string& key) {
  for (std::size_t p = 0; p < kFootPointNames.size(); ++p) {
    if (kFootPointNames[p] == name) return p;
  }
  throwMalformed(file, key, "unknown foot point '" + name + "' (r_heel, r_toe, l_heel or l_toe)");
}

void parseFeet(const json& feet, const std::string& file, MarkerSetTable& t) {
  if (!feet.is_object()) throwMalformed(file, "feet", "must be an object with foot point names as keys");
  for (const auto& [name, rules] : feet.items()) {
    const std::string key = "feet." + name;
    const std::size_t p = footPointFromName(name, file, key);
    if (!rules.is_array()) throwMalformed(file, key, "must be a list of rules (tried in order)");
    for (std::size_t k = 0; k < rules.size(); ++k) {
      const std::string ruleKey = key + "[" + std::to_string(k) + "]";
      MarkerRule r = parseRule(rules[k], file, ruleKey);
      if (r.op != RuleOp::Mean) throwMalformed(file, ruleKey + ".op", "a foot point takes \"mean\" rules only");
      t.feet[p].push_back(std::move(r));
    }
  }
}

// [SECTION] Rule inputs and planning -------------------------------------------------------

std::vector<Joint> jointsRead(const MarkerRule& r) {
  switch (r.op) {
    case RuleOp::MidJoints:
    case RuleOp::LateralMedial:
      return r.joints;
    case RuleOp::ShoulderDrop:
    case RuleOp::HeadAboveSternum:
      return {Joint::Pelvis, Joint::Sternum};
    case RuleOp::FunctionalCentre:
      return r.anchor ? std::vector<Joint>{*r.anchor} : std::vector<Joint>{};
    default:
      return {};
  }
}

// Markers the rule cannot do without (the medial marker of LateralMedial is optional).
std::vector<std::string> requiredMarkers(const MarkerRule& r) {
  std::vector<std::string> m = r.markers;
  m.insert(m.end(), r.distal.begin(), r.distal.end());
  m.insert(m.end(), r.otherDistal.begin(), r.otherDistal.end());
  for (const std::string* s :
       {&r.leftAsis, &r.rightAsis, &r.lateral, &r.acromion, &r.otherAcromion}) {
    if (!s->empty()) m.push_back(*s);
  }
  return m;
}

bool usable(const MarkerRule& r, const Markers& m, const std::array<int, kJointCount>& plan) {
  for (const auto& name : requiredMarkers(r)) {
    if (m.resolve(name) < 0) return false;
  }
  for (Joint j : jointsRead(r)) {
    if (plan[at(j)] < 0) return false;
  }
  return true;
}

// [SECTION] Rule evaluation -------------------------------------------------------------------

double halfWidthMm(HalfWidth h) {
  switch (h) {
    case HalfWidth::Knee:
      return kKneeHalfWidthMm;
    case HalfWidth::Ankle:
      return kAnkleHalfWidthMm;
    case HalfWidth::Elbow:
      return kElbowHalfWidthMm;
  }
  return kKneeHalfWidthMm;
}

struct FrameContext {
  const Markers& m;
  const Eigen::MatrixXd& joints;  // built so far
  int f;
  Vector3d marker(const std::string& ref) const { return m.at(m.resolve(ref), f); }
  Vector3d joint(Joint j) const { return jointAt(joints, f, j); }
  Vector3d mean(const std::vector<std::string>& refs) const {
    Vector3d sum = Vector3d::Zero();
    for (const auto& r : refs) sum += marker(r);
    return sum / static_cast<double>(refs.size());
  }
};

// Joint centre from a lateral marker alone: half-width towards the body's midline,
// perpendicular to the segment's long axis (proximal joint -> lateral marker). The midline
// direction is the pelvis's (or shoulder girdle's) left-right line, which the knee, ankle
// and elbow flexion axes follow within a few degrees in walking.
Vector3d lateralMedial(const MarkerRule& r, const FrameContext& c) {
  const Vector3d lateral = c.marker(r.lateral);
  if (!r.medial.empty() && c.m.resolve(r.medial) >= 0) return 0.5 * (lateral + c.marker(r.medial));
  const Vector3d axis = unitOrNaN(lateral - c.joint(r.joints[0]));
  const Vector3d toward = c.joint(r.joints[2]) - c.joint(r.joints[1]);
  const Vector3d medial = unitOrNaN(toward - toward.dot(axis) * axis);
  return lateral + halfWidthMm(r.halfWidth) * medial;
}

Vector3d evaluate(const MarkerRule& r, const FrameContext& c) {
  switch (r.op) {
    case RuleOp::Mean:
      return c.mean(r.markers);
    case RuleOp::HarringtonHip: {
      const HipCentres h =
          harringtonHipCentres(c.marker(r.leftAsis), c.marker(r.rightAsis), c.mean(r.markers));
      return r.side == Side::Left ? h.left : h.right;
    }
    case RuleOp::MidJoints: {
      Vector3d sum = Vector3d::Zero();
      for (Joint j : r.joints) sum += c.joint(j);
      return sum / static_cast<double>(r.joints.size());
    }
    case RuleOp::LateralMedial:
      return lateralMedial(r, c);
    case RuleOp::ShoulderDrop: {
      const Vector3d acromion = c.marker(r.acromion);
      const double biacromial = (acromion - c.marker(r.otherAcromion)).norm();
      const Vector3d down = unitOrNaN(c.joint(Joint::Pelvis) - c.joint(Joint::Sternum));
      return acromion + kShoulderDropFraction * biacromial * down;
    }
    case RuleOp::HeadAboveSternum:
      return estimateHead(c.joint(Joint::Pelvis), c.joint(Joint::Sternum));
    case RuleOp::FunctionalCentre:
    case RuleOp::FunctionalHip:
      break;  // a whole-trial fit: functionalTrack
  }
  return Vector3d::Constant(kNaN);
}

MarkerTrack functionalTrack(const MarkerRule& r, const Markers& m, const Eigen::MatrixXd& joints,
                            int frames) {
  const auto tracks = [&](const std::vector<std::string>& refs) {
    std::vector<MarkerTrack> out;
    for (const auto& ref : refs) {
      MarkerTrack t(frames, 3);
      for (int f = 0; f < frames; ++f) t.row(f) = m.at(m.resolve(ref), f).transpose();
      out.push_back(t);
    }
    return out;
  };
  if (r.op == RuleOp::FunctionalHip) {
    const bool left = r.side == Side::Left;
    const HipPair h = symmetricFunctionalHips(tracks(r.markers), tracks(left ? r.distal : r.otherDistal),
                                              tracks(left ? r.otherDistal : r.distal), r.widthMm);
    return left ? h.left : h.right;
  }
  if (!r.anchor) return functionalJointCentre(tracks(r.markers), tracks(r.distal));
  const MarkerTrack anchor = joints.middleCols(3 * index(*r.anchor), 3);
  return functionalJointCentre(tracks(r.markers), tracks(r.distal), &anchor);
}

bool isFunctional(const MarkerRule& r) {
  return r.op == RuleOp::FunctionalCentre || r.op == RuleOp::FunctionalHip;
}

double meanDistanceMm(const Eigen::MatrixXd& joints, Joint a, Joint b) {
  double sum = 0;
  int n = 0;
  for (Eigen::Index f = 0; f < joints.rows(); ++f) {
    const double d = (jointAt(joints, static_cast<int>(f), a) - jointAt(joints, static_cast<int>(f), b)).norm();
    if (std::isfinite(d)) sum += d, ++n;
  }
  return n ? sum / n : kNaN;
}

// Left and right thighs and shanks of one person differ by a few percent, and a shank is
// about as long as its thigh (0.89-1.21 on the 24 shared walkers' trials); functional
// centres fitted on too little joint motion are not (TESTBPI.c3d: shanks 0.75 of thighs).
constexpr double kMaxLegAsymmetry = 0.10;
constexpr double kMinShankToThigh = 0.80, kMaxShankToThigh = 1.35;

struct LegLengths {
  double leftThigh, rightThigh, leftShank, rightShank;
};

LegLengths legLengths(const Eigen::MatrixXd& p) {
  return {meanDistanceMm(p, Joint::LHip, Joint::LKnee), meanDistanceMm(p, Joint::RHip, Joint::RKnee),
          meanDistanceMm(p, Joint::LKnee, Joint::LAnkle), meanDistanceMm(p, Joint::RKnee, Joint::RAnkle)};
}

[[noreturn]] void implausibleLegs(const JointTrial& t, const std::string& what) {
  throw Error(ErrorKind::BadData, t.file, "",
              "the functional joint centres fitted on the marker clusters are implausible (" +
                  what +
                  "): the trial moves its joints too little to locate them, and the file has "
                  "no anatomical markers to place them instead");
}

// Throws Error(BadData) saying which proportion fails when legs built with functional
// centres are not a person's: left and right apart by more than kMaxLegAsymmetry, or shank
// to thigh outside [kMinShankToThigh, kMaxShankToThigh].
void checkFunctionalLegs(const JointTrial& t) {
  const LegLengths g = legLengths(t.positionsMm);
  std::ostringstream what;
  what.precision(0);
  what << std::fixed;
  for (const auto& [name, l, r] : {std::tuple{"thigh", g.leftThigh, g.rightThigh},
                                   std::tuple{"shank", g.leftShank, g.rightShank}}) {
    const double asymmetry = std::abs(l - r) / (0.5 * (l + r));
    if (!(asymmetry > kMaxLegAsymmetry)) continue;
    what << "left " << name << " " << l << " mm, right " << r << " mm: " << 100 * asymmetry
         << " % apart, more than " << 100 * kMaxLegAsymmetry << " %";
    implausibleLegs(t, what.str());
  }
  const double ratio = (g.leftShank + g.rightShank) / (g.leftThigh + g.rightThigh);
  if (!std::isfinite(ratio) || (ratio >= kMinShankToThigh && ratio <= kMaxShankToThigh)) return;
  what.precision(2);
  what << "shanks " << ratio << " of the thighs' length, outside " << kMinShankToThigh << "-"
       << kMaxShankToThigh;
  implausibleLegs(t, what.str());
}

// The estimate flag and warning a rule carries for this trial.
void flagRule(JointTrial& out, Joint j, const MarkerRule& r, const Markers& m) {
  std::string why = r.estimated;
  if (r.op == RuleOp::LateralMedial && (r.medial.empty() || m.resolve(r.medial) < 0)) {
    std::ostringstream w;
    w << "no medial marker" << (r.medial.empty() ? std::string() : " (" + r.medial + ")")
      << ", placed " << halfWidthMm(r.halfWidth) << " mm medial of " << r.lateral;
    why = w.str();
  }
  if (why.empty()) return;
  out.estimated[at(j)] = true;
  out.warnings.push_back(std::string(jointName(j)) + " estimated: " + why);
}

// The feet's points the plan has, into out.feetMm; nothing when it has none.
void buildFeet(const MarkerSetTable& table, const TablePlan& plan, const Markers& m, JointTrial& out) {
  std::vector<std::string> missing;
  for (std::size_t p = 0; p < plan.feet.size(); ++p) {
    if (plan.feet[p] < 0) missing.emplace_back(kFootPointNames[p]);
  }
  if (missing.size() == plan.feet.size()) return;
  const int frames = static_cast<int>(out.positionsMm.rows());
  out.feetMm.setConstant(frames, kFootDims3, kNaN);
  for (std::size_t p = 0; p < plan.feet.size(); ++p) {
    if (plan.feet[p] < 0) continue;
    const MarkerRule& r = table.feet[p][static_cast<std::size_t>(plan.feet[p])];
    for (int f = 0; f < frames; ++f) {
      const FrameContext c{m, out.positionsMm, f};
      out.feetMm.block<1, 3>(f, 3 * static_cast<int>(p)) = evaluate(r, c).transpose();
    }
  }
  if (!missing.empty())
    out.warnings.push_back("foot points not measured by " + table.name + ": " + listForMessage(missing, 4));
}

}  // namespace

// [SECTION] Public API ----------------------------------------------------------------------

MarkerSetTable parseMarkerSetTable(std::string_view text, const std::string& file) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throwMalformed(file, "", std::string("not JSON: ") + e.what());
  }
  if (!doc.is_object()) throwMalformed(file, "", "a marker-set table must be a JSON object");
  MarkerSetTable t;
  t.file = file;
  t.name = str(doc, "name", file, "");
  t.identify = strings(doc, "identify", file, "");
  if (!doc.contains("joints") || !doc["joints"].is_object()) throwMalformed(file, "joints", "missing object");
  for (const auto& [name, rules] : doc["joints"].items()) {
    const std::string key = "joints." + name;
    const Joint j = jointFromName(name, file, key);
    if (!rules.is_array()) throwMalformed(file, key, "must be a list of rules (tried in order)");
    for (std::size_t k = 0; k < rules.size(); ++k) {
      t.joints[at(j)].push_back(parseRule(rules[k], file, key + "[" + std::to_string(k) + "]"));
    }
  }
  if (doc.contains("feet")) parseFeet(doc["feet"], file, t);
  return t;
}

const std::vector<MarkerSetTable>& markerSetTables() {
  static const std::vector<MarkerSetTable> tables = [] {
    std::vector<MarkerSetTable> out;
    for (const auto& name : embeddedAssetNames("marker-sets/")) {
      if (!name.ends_with(".json")) continue;
      out.push_back(parseMarkerSetTable(embeddedAsset(name), "assets/" + name));
    }
    if (out.empty()) throw Error(ErrorKind::Io, "assets/marker-sets", "", "no tables embedded");
    return out;
  }();
  return tables;
}

int TablePlan::jointCount() const {
  return static_cast<int>(std::count_if(rule.begin(), rule.end(), [](int r) { return r >= 0; }));
}

TablePlan planMarkerSetTable(const MarkerSetTable& table, const RawTrial& raw) {
  const Markers m(raw);
  TablePlan plan;
  plan.rule.fill(-1);
  for (const auto& id : table.identify) {
    if (!m.hasLabel(id)) plan.identifyMissing.push_back(id);
  }
  plan.identified = plan.identifyMissing.empty();
  plan.feet.fill(-1);
  for (std::size_t p = 0; p < table.feet.size(); ++p) {
    const auto& rules = table.feet[p];
    for (std::size_t k = 0; k < rules.size() && plan.feet[p] < 0; ++k) {
      if (usable(rules[k], m, plan.rule)) plan.feet[p] = static_cast<int>(k);
    }
  }
  for (Joint j : kBuildOrder) {
    const auto& rules = table.joints[at(j)];
    for (std::size_t k = 0; k < rules.size(); ++k) {
      if (!usable(rules[k], m, plan.rule)) continue;
      plan.rule[at(j)] = static_cast<int>(k);
      break;
    }
  }
  return plan;
}

JointTrial applyMarkerSetTable(const MarkerSetTable& table, const TablePlan& plan,
                               const RawTrial& raw) {
  const Markers m(raw);
  JointTrial out = jointTrialShell(raw, table.name, raw.frameCount());
  for (Joint j : kBuildOrder) {
    const int k = plan.rule[at(j)];
    if (k < 0) {
      out.missing[at(j)] = true;
      continue;
    }
    const MarkerRule& r = table.joints[at(j)][static_cast<std::size_t>(k)];
    if (isFunctional(r)) {
      out.positionsMm.middleCols(3 * index(j), 3) =
          functionalTrack(r, m, out.positionsMm, raw.frameCount());
      continue;
    }
    for (int f = 0; f < raw.frameCount(); ++f) {
      const FrameContext c{m, out.positionsMm, f};
      out.positionsMm.block<1, 3>(f, 3 * index(j)) = evaluate(r, c).transpose();
    }
  }
  // Warnings in joint order (METHOD §1), as the readers and tests list joints.
  for (int j = 0; j < kJointCount; ++j) {
    const int k = plan.rule[static_cast<std::size_t>(j)];
    if (k >= 0)
      flagRule(out, static_cast<Joint>(j),
               table.joints[static_cast<std::size_t>(j)][static_cast<std::size_t>(k)], m);
  }
  buildFeet(table, plan, m, out);
  for (Joint j : {Joint::LHip, Joint::RHip, Joint::LKnee, Joint::RKnee, Joint::LAnkle, Joint::RAnkle}) {
    const int k = plan.rule[at(j)];
    if (k >= 0 && isFunctional(table.joints[at(j)][static_cast<std::size_t>(k)])) {
      checkFunctionalLegs(out);
      break;
    }
  }
  std::vector<std::string> missing;
  for (int j = 0; j < kJointCount; ++j) {
    if (out.missing[static_cast<std::size_t>(j)])
      missing.emplace_back(kJointNames[static_cast<std::size_t>(j)]);
  }
  if (!missing.empty()) {
    out.warnings.push_back("not measured by " + table.name + ": " + listForMessage(missing, 15) +
                           " (to be estimated from a model)");
  }
  return out;
}

std::vector<std::string> missingMinimumJoints(const TablePlan& plan) {
  std::vector<std::string> out;
  for (Joint j : kMinimumJoints) {
    if (plan.rule[at(j)] < 0) out.emplace_back(jointName(j));
  }
  return out;
}

Vector3d unitOrNaN(const Vector3d& v) {
  const double n = v.norm();
  return n > 1e-9 ? Vector3d(v / n) : Vector3d::Constant(kNaN);
}

}  // namespace ew
