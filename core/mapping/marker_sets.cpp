#include "core/mapping/marker_sets.h"

#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include "core/common/errors.h"
#include "core/mapping/joint_mapping.h"
#include "core/mapping/marker_set_table.h"
#include "core/mapping/raw_motion.h"

namespace ew {
namespace {

using Eigen::Vector3d;

// [SECTION] Set choice and errors -------------------------------------------------------------

struct Candidate {
  const MarkerSetTable* table = nullptr;
  TablePlan plan;
};

// Among the identified tables, the one that builds the most joints; the earlier on a tie.
std::optional<Candidate> bestTable(const RawTrial& raw, std::vector<Candidate>& all) {
  std::optional<Candidate> best;
  for (const auto& table : markerSetTables()) {
    Candidate c{&table, planMarkerSetTable(table, raw)};
    all.push_back(c);
    if (!c.plan.identified) continue;
    if (!best || c.plan.jointCount() > best->plan.jointCount()) best = c;
  }
  return best;
}

// "not walking: …" comes first: a golf swing with unknown labels is not a marker problem.
std::string notWalkingPrefix(const RawTrial& raw) {
  const auto reason = rawNotWalkingReason(raw);
  return reason ? "not walking: " + *reason + "; and " : std::string();
}

[[noreturn]] void throwUnknownSet(const RawTrial& raw, const std::vector<Candidate>& all) {
  std::string msg = notWalkingPrefix(raw) + "no known marker set matches the " +
                    std::to_string(raw.pointCount()) + " labels [" +
                    listForMessage(raw.labels, 60, " ") + "].";
  for (const auto& c : all) {
    msg += " " + c.table->name + " needs " + listForMessage(c.table->identify, 100, " ") +
           " (missing " + listForMessage(c.plan.identifyMissing, 100, " ") + ").";
  }
  msg += " A joint mapping file (--mapping, docs/FORMATS.md) can name the markers.";
  throw Error(ErrorKind::UnknownMarkerSet, raw.file, "", msg);
}

[[noreturn]] void throwTooFewJoints(const RawTrial& raw, const Candidate& c) {
  std::vector<std::string> built;
  for (int j = 0; j < kJointCount; ++j) {
    if (c.plan.rule[static_cast<std::size_t>(j)] >= 0)
      built.emplace_back(kJointNames[static_cast<std::size_t>(j)]);
  }
  const std::string msg =
      notWalkingPrefix(raw) + "the labels look like " + c.table->name + ", but its markers give " +
      (built.empty() ? std::string("no joint") : listForMessage(built, 15)) +
      "; at least pelvis, both knees and both ankles must be measured (missing " +
      listForMessage(missingMinimumJoints(c.plan), 15) +
      "; a marker with a label but no position in any frame counts as absent). A joint "
      "mapping file (--mapping, docs/FORMATS.md) can name the markers.";
  throw Error(ErrorKind::UnknownMarkerSet, raw.file, "", msg);
}

}  // namespace

// [SECTION] Public API ----------------------------------------------------------------------

namespace {

// Well-formed UTF-8 sequences by their lead bytes (overlong forms are left to the JSON
// writer's replacement, jointMappingToJson).
bool isUtf8(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::size_t extra = 0;
    if (c >= 0x80) {
      if ((c >> 5) == 0x6)
        extra = 1;
      else if ((c >> 4) == 0xE)
        extra = 2;
      else if ((c >> 3) == 0x1E)
        extra = 3;
      else
        return false;
    }
    if (i + extra >= text.size() && extra > 0) return false;
    for (std::size_t k = 1; k <= extra; ++k) {
      if ((static_cast<unsigned char>(text[i + k]) >> 6) != 0x2) return false;
    }
    i += extra + 1;
  }
  return true;
}

}  // namespace

std::string labelAsUtf8(std::string_view label) {
  if (isUtf8(label)) return std::string(label);
  std::string out;
  for (const char ch : label) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x80) {
      out += ch;
    } else {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

std::string normaliseMarkerLabel(std::string_view label) {
  const std::size_t colon = label.rfind(':');
  if (colon != std::string_view::npos) label.remove_prefix(colon + 1);
  while (!label.empty() && std::isspace(static_cast<unsigned char>(label.front())))
    label.remove_prefix(1);
  while (!label.empty() && std::isspace(static_cast<unsigned char>(label.back())))
    label.remove_suffix(1);
  std::string out = labelAsUtf8(label);
  for (char& c : out) {
    if (static_cast<unsigned char>(c) < 0x80) c = static_cast<char>(std::toupper(c));
  }
  return out;
}

const std::vector<MarkerSetInfo>& knownMarkerSets() {
  static const std::vector<MarkerSetInfo> sets = [] {
    std::vector<MarkerSetInfo> out;
    for (const auto& t : markerSetTables()) out.push_back({t.name, t.identify});
    return out;
  }();
  return sets;
}

HipCentres harringtonHipCentres(const Vector3d& leftAsis, const Vector3d& rightAsis,
                                const Vector3d& midPsis) {
  const Vector3d origin = 0.5 * (leftAsis + rightAsis);
  const Vector3d z = unitOrNaN(rightAsis - leftAsis);
  const Vector3d back = origin - midPsis;
  const Vector3d x = unitOrNaN(back - back.dot(z) * z);
  const Vector3d y = z.cross(x);
  const double pw = (rightAsis - leftAsis).norm();
  const double pd = back.norm();
  const Vector3d common = origin + (-0.24 * pd - 9.9) * x + (-0.30 * pw - 10.9) * y;
  const double lateral = 0.33 * pw + 7.3;
  return {common - lateral * z, common + lateral * z};
}

JointTrial mapMarkerSet(const RawTrial& raw) {
  std::vector<Candidate> all;
  const auto best = bestTable(raw, all);
  if (!best) throwUnknownSet(raw, all);
  if (!missingMinimumJoints(best->plan).empty()) throwTooFewJoints(raw, *best);
  return applyMarkerSetTable(*best->table, best->plan, raw);
}

}  // namespace ew
