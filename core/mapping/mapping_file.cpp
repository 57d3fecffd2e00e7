#include "core/mapping/mapping_file.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <set>

#include "core/common/errors.h"
#include "core/io/atomic_write.h"
#include "core/io/file_bytes.h"
#include "core/mapping/joint_mapping.h"
#include "core/mapping/marker_set_table.h"
#include "core/mapping/marker_sets.h"

namespace ew {
namespace {

using nlohmann::json;

constexpr const char* kVersionKey = "eigenwalker_joint_mapping";

int jointIndex(const std::string& name) {
  for (int j = 0; j < kJointCount; ++j) {
    if (kJointNames[static_cast<std::size_t>(j)] == name) return j;
  }
  return -1;
}

std::vector<std::string> parseJointValue(const json& v, const std::string& file,
                                         const std::string& key) {
  if (v.is_null()) return {};
  if (v.is_string()) {
    if (v.get<std::string>().empty()) throwMalformed(file, key, "empty label");
    return {v.get<std::string>()};
  }
  if (!v.is_array()) throwMalformed(file, key, "must be a label, a list of labels (their mean) or null");
  if (v.empty()) throwMalformed(file, key, "empty list: give at least one label, or null for absent");
  std::vector<std::string> labels;
  std::set<std::string> seen;
  for (const auto& item : v) {
    if (!item.is_string() || item.get<std::string>().empty())
      throwMalformed(file, key, "list items must be non-empty label strings");
    const std::string label = item.get<std::string>();
    if (!seen.insert(normaliseMarkerLabel(label)).second)
      throwMalformed(file, key, "label '" + label + "' given twice");
    labels.push_back(label);
  }
  return labels;
}

// The mapping as a marker-set table: each joint the mean of its labels.
MarkerSetTable tableFor(const JointMapping& mapping, const std::string& file) {
  MarkerSetTable t;
  t.name = "joint mapping " + file;
  t.file = file;
  for (std::size_t j = 0; j < mapping.joints.size(); ++j) {
    if (mapping.joints[j].empty()) continue;
    MarkerRule r;
    r.markers = mapping.joints[j];
    t.joints[j].push_back(r);
  }
  return t;
}

// A label that exists in the trial (normalised), or false.
bool trialHasLabel(const RawTrial& raw, const std::string& label) {
  const std::string n = normaliseMarkerLabel(label);
  return std::any_of(raw.labels.begin(), raw.labels.end(),
                     [&](const std::string& l) { return normaliseMarkerLabel(l) == n; });
}

// The markers a chosen rule reads, with "A|B" reduced to the alternative the file has and
// "X*" to the label it matched, so the suggestion is a plain list of the file's labels.
// What a rule's joint is closest to as a mean of markers: the markers of a mean, the
// lateral (and medial) marker of a joint centre, the acromion of a shoulder, the same
// side's ASIS for a Harrington hip (a rough stand-in the user should review).
std::vector<std::string> suggestionRefs(const MarkerRule& rule) {
  switch (rule.op) {
    case RuleOp::Mean:
      return rule.markers;
    case RuleOp::LateralMedial:
      return rule.medial.empty() ? std::vector<std::string>{rule.lateral}
                                 : std::vector<std::string>{rule.lateral, rule.medial};
    case RuleOp::ShoulderDrop:
      return {rule.acromion};
    case RuleOp::HarringtonHip:
      return {rule.side == Side::Left ? rule.leftAsis : rule.rightAsis};
    case RuleOp::FunctionalCentre:  // a fitted point no mean of markers stands for
    case RuleOp::FunctionalHip:
    case RuleOp::MidJoints:
    case RuleOp::HeadAboveSternum:
      return {};
  }
  return {};
}

std::vector<std::string> concreteLabels(const MarkerRule& rule, const RawTrial& raw) {
  std::vector<std::string> out;
  for (const auto& ref : suggestionRefs(rule)) {
    std::size_t start = 0;
    while (start <= ref.size()) {
      const std::size_t bar = std::min(ref.find('|', start), ref.size());
      std::string alt = normaliseMarkerLabel(ref.substr(start, bar - start));
      const bool variants = !alt.empty() && alt.back() == '*';
      if (variants) alt.pop_back();
      const auto it = std::find_if(raw.labels.begin(), raw.labels.end(), [&](const auto& l) {
        const std::string n = normaliseMarkerLabel(l);
        return n == alt || (variants && n.rfind(alt + "_", 0) == 0);
      });
      if (it != raw.labels.end()) {
        if (std::find(out.begin(), out.end(), *it) == out.end()) out.push_back(*it);
        break;
      }
      start = bar + 1;
    }
  }
  return out;
}

// By name: "l_knee" <- a label equal to LKNEE / L_KNEE / LEFTKNEE … (keypoint-style files).
JointMapping suggestByName(const RawTrial& raw) {
  JointMapping m;
  for (int j = 0; j < kJointCount; ++j) {
    std::string name(kJointNames[static_cast<std::size_t>(j)]);
    std::vector<std::string> forms = {name};
    if (name.size() > 2 && name[1] == '_') {
      const std::string part = name.substr(2);
      const std::string side = name.substr(0, 1);
      forms = {side + part, side + "_" + part, (side == "l" ? "left" : "right") + part,
               (side == "l" ? "left_" : "right_") + part};
    }
    for (const auto& label : raw.labels) {
      const std::string n = normaliseMarkerLabel(label);
      for (const auto& f : forms) {
        if (n == normaliseMarkerLabel(f) && m.joints[static_cast<std::size_t>(j)].empty())
          m.joints[static_cast<std::size_t>(j)] = {label};
      }
    }
  }
  return m;
}

}  // namespace

JointMapping parseJointMapping(std::string_view text, const std::string& file) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throwMalformed(file, "", std::string("not JSON: ") + e.what());
  }
  if (!doc.is_object()) throwMalformed(file, "", "a joint mapping file is a JSON object");
  if (!doc.contains(kVersionKey)) throwMalformed(file, kVersionKey, "missing (expected 1)");
  if (!doc[kVersionKey].is_number_integer() || doc[kVersionKey].get<int>() != kJointMappingVersion)
    throwMalformed(file, kVersionKey, "unsupported version " + doc[kVersionKey].dump() + " (expected 1)");
  if (!doc.contains("joints") || !doc["joints"].is_object())
    throwMalformed(file, "joints", "missing: an object with the 15 joint names as keys");
  JointMapping m;
  std::array<bool, kJointCount> given{};
  for (const auto& [name, value] : doc["joints"].items()) {
    const int j = jointIndex(name);
    if (j < 0) {
      throwMalformed(file, "joints." + name,
          "unknown joint name (expected one of " +
              listForMessage(std::vector<std::string>(kJointNames.begin(), kJointNames.end()), 15) +
              ")");
    }
    given[static_cast<std::size_t>(j)] = true;
    m.joints[static_cast<std::size_t>(j)] = parseJointValue(value, file, "joints." + name);
  }
  for (int j = 0; j < kJointCount; ++j) {
    if (!given[static_cast<std::size_t>(j)]) {
      throwMalformed(file, "joints." + std::string(kJointNames[static_cast<std::size_t>(j)]),
          "missing: every joint must be listed (null when the file does not measure it)");
    }
  }
  return m;
}

JointMapping readJointMappingFile(const std::filesystem::path& file) {
  return parseJointMapping(readFileText(file), file.string());
}

std::string jointMappingToJson(const JointMapping& mapping) {
  json joints = json::object();
  for (int j = 0; j < kJointCount; ++j) {
    const auto& labels = mapping.joints[static_cast<std::size_t>(j)];
    const std::string name(kJointNames[static_cast<std::size_t>(j)]);
    std::vector<std::string> utf8;
    for (const auto& l : labels) utf8.push_back(labelAsUtf8(l));
    if (utf8.empty())
      joints[name] = nullptr;
    else if (utf8.size() == 1)
      joints[name] = utf8.front();
    else
      joints[name] = utf8;
  }
  json doc = {{kVersionKey, kJointMappingVersion}, {"joints", joints}};
  // Labels are UTF-8 by now (labelAsUtf8); a malformed sequence that slipped through is
  // replaced rather than thrown on.
  return doc.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

void writeJointMappingFile(const std::filesystem::path& file, const JointMapping& mapping) {
  const std::string text = jointMappingToJson(mapping);
  writeFileAtomically(file, [&](std::ostream& out) { out << text; });
}

LabelTable labelTable(const RawTrial& raw) {
  LabelTable t;
  t.labels = raw.labels;
  const MarkerSetTable* best = nullptr;
  TablePlan bestPlan;
  for (const auto& table : markerSetTables()) {
    const TablePlan plan = planMarkerSetTable(table, raw);
    if (plan.identified && (!best || plan.jointCount() > bestPlan.jointCount())) {
      best = &table;
      bestPlan = plan;
    }
  }
  if (!best) {
    t.suggested = suggestByName(raw);
    t.suggestedFrom = "label names";
    return t;
  }
  t.suggestedFrom = best->name;
  for (std::size_t j = 0; j < best->joints.size(); ++j) {
    const int k = bestPlan.rule[j];
    if (k < 0) continue;
    t.suggested.joints[j] = concreteLabels(best->joints[j][static_cast<std::size_t>(k)], raw);
  }
  // A joint made from other joints (the pelvis from the hips) gets their markers.
  for (std::size_t j = 0; j < best->joints.size(); ++j) {
    const int k = bestPlan.rule[j];
    if (k < 0) continue;
    const MarkerRule& rule = best->joints[j][static_cast<std::size_t>(k)];
    if (rule.op != RuleOp::MidJoints) continue;
    for (Joint from : rule.joints) {
      for (const auto& label : t.suggested.joints[static_cast<std::size_t>(index(from))]) {
        auto& into = t.suggested.joints[j];
        if (std::find(into.begin(), into.end(), label) == into.end()) into.push_back(label);
      }
    }
  }
  return t;
}

JointTrial applyJointMapping(const RawTrial& raw, const JointMapping& mapping,
                             const std::string& mappingFile) {
  for (int j = 0; j < kJointCount; ++j) {
    for (const auto& label : mapping.joints[static_cast<std::size_t>(j)]) {
      if (trialHasLabel(raw, label)) continue;
      throw Error(ErrorKind::BadArgument, mappingFile,
                  "joints." + std::string(kJointNames[static_cast<std::size_t>(j)]),
                  "label '" + label + "' is not in " + raw.file +
                      " (its labels: " + listForMessage(raw.labels, 40, " ") + ")");
    }
  }
  const MarkerSetTable table = tableFor(mapping, mappingFile);
  const TablePlan plan = planMarkerSetTable(table, raw);
  const auto lacking = missingMinimumJoints(plan);
  if (!lacking.empty()) {
    throw Error(ErrorKind::UnknownMarkerSet, raw.file, "",
                "the joint mapping " + mappingFile + " gives too few joints: at least pelvis, " +
                    "both knees and both ankles must be measured (missing " +
                    listForMessage(lacking, 15) +
                    "; a joint whose markers have no position in any frame counts as missing)");
  }
  return applyMarkerSetTable(table, plan, raw);
}

}  // namespace ew
