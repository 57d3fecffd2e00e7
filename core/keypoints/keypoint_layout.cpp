#include "core/keypoints/keypoint_layout.h"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <map>
#include <nlohmann/json.hpp>

#include "core/assets/embedded_assets.h"
#include "core/common/errors.h"

namespace ew {
namespace {

using nlohmann::json;

// A text field the file may leave out; there, anything but a string is named (json::value()
// would throw its own type_error, which no caller expects).
std::string optionalText(const json& doc, const char* key, const std::string& file) {
  const auto it = doc.find(key);
  if (it == doc.end() || it->is_null()) return "";
  if (!it->is_string()) throwMalformed(file, key, "must be a string");
  return it->get<std::string>();
}

// Lower case without '_', '-' or spaces: "BODY_25B", "body25b" and "Body-25B" are one name.
std::string nameKey(std::string_view s) {
  std::string out;
  for (char c : s) {
    if (c == '_' || c == '-' || c == ' ') continue;
    out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return out;
}

std::vector<std::string> pointNames(const json& doc, const std::string& file) {
  if (!doc.contains("points") || !doc["points"].is_array() || doc["points"].empty())
    throwMalformed(file, "points", "must be a non-empty list of point names");
  std::vector<std::string> points;
  for (const auto& p : doc["points"]) {
    if (!p.is_string() || p.get<std::string>().empty()) throwMalformed(file, "points", "names must be strings");
    if (std::find(points.begin(), points.end(), p.get<std::string>()) != points.end())
      throwMalformed(file, "points", "'" + p.get<std::string>() + "' appears twice");
    points.push_back(p.get<std::string>());
  }
  return points;
}

int jointIndex(const std::string& name, const std::string& file, const std::string& key) {
  for (int j = 0; j < kJointCount; ++j) {
    if (kJointNames[static_cast<std::size_t>(j)] == name) return j;
  }
  throwMalformed(file, key, "unknown joint name '" + name + "'");
}

std::vector<int> alternative(const json& a, const std::vector<std::string>& points,
                             const std::string& file, const std::string& key) {
  if (!a.is_array() || a.empty()) throwMalformed(file, key, "an alternative must be a non-empty list of point names");
  std::vector<int> out;
  for (const auto& p : a) {
    const auto it = p.is_string() ? std::find(points.begin(), points.end(), p.get<std::string>()) : points.end();
    if (it == points.end()) throwMalformed(file, key, "'" + p.dump() + "' is not one of the layout's points");
    out.push_back(static_cast<int>(it - points.begin()));
  }
  return out;
}

void parseFeet(const json& doc, const std::string& file, KeypointLayout& l) {
  if (!doc.contains("feet")) return;
  if (!doc["feet"].is_object()) throwMalformed(file, "feet", "must be an object foot point -> alternatives");
  for (const auto& [name, alternatives] : doc["feet"].items()) {
    const std::string key = "feet." + name;
    const auto p = std::find(kFootPointNames.begin(), kFootPointNames.end(), name);
    if (p == kFootPointNames.end()) throwMalformed(file, key, "unknown foot point (r_heel, r_toe, l_heel or l_toe)");
    if (!alternatives.is_array() || alternatives.empty())
      throwMalformed(file, key, "must be a list of alternatives (lists of point names)");
    for (std::size_t k = 0; k < alternatives.size(); ++k) {
      l.feet[static_cast<std::size_t>(p - kFootPointNames.begin())].push_back(
          alternative(alternatives[k], l.points, file, key + "[" + std::to_string(k) + "]"));
    }
  }
}

void parseDetectorOffsets(const json& doc, const std::string& file, KeypointLayout& l) {
  if (!doc.contains("detector_offsets_mm")) return;
  const json& offsets = doc["detector_offsets_mm"];
  if (!offsets.is_object()) throwMalformed(file, "detector_offsets_mm", "must be an object joint -> [x, y, z] mm");
  for (const auto& [name, v] : offsets.items()) {
    const std::string key = "detector_offsets_mm." + name;
    const int j = jointIndex(name, file, key);
    if (!v.is_array() || v.size() != 3) throwMalformed(file, key, "must be three numbers [x, y, z] in mm");
    for (std::size_t c = 0; c < 3; ++c) {
      if (!v[c].is_number() || !std::isfinite(v[c].get<double>()) || std::abs(v[c].get<double>()) > kMaxDetectorOffsetMm)
        throwMalformed(file, key, "each coordinate must be a finite number within ±" + std::to_string(static_cast<int>(kMaxDetectorOffsetMm)) + " mm");
      l.detectorOffsetMm[static_cast<std::size_t>(j)][c] = v[c].get<double>();
    }
  }
  l.detectorOffsetSource = optionalText(doc, "detector_offsets_source", file);
}

}  // namespace

bool anyOffset(const JointOffsetsMm& offsets) {
  for (const auto& o : offsets)
    if (o[0] != 0.0 || o[1] != 0.0 || o[2] != 0.0) return true;
  return false;
}

KeypointLayout parseKeypointLayout(std::string_view text, const std::string& file) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    throwMalformed(file, "", std::string("not JSON: ") + e.what());
  }
  if (!doc.is_object()) throwMalformed(file, "", "a keypoint layout must be a JSON object");
  KeypointLayout l;
  l.file = file;
  if (!doc.contains("name") || !doc["name"].is_string() || doc["name"].get<std::string>().empty())
    throwMalformed(file, "name", "must be a non-empty string");
  l.name = doc["name"].get<std::string>();
  l.about = optionalText(doc, "about", file);
  l.points = pointNames(doc, file);
  if (!doc.contains("joints") || !doc["joints"].is_object()) throwMalformed(file, "joints", "missing object");
  for (const auto& [name, alternatives] : doc["joints"].items()) {
    const std::string key = "joints." + name;
    const int j = jointIndex(name, file, key);
    if (!alternatives.is_array() || alternatives.empty())
      throwMalformed(file, key, "must be a list of alternatives (lists of point names)");
    for (std::size_t k = 0; k < alternatives.size(); ++k) {
      l.joints[static_cast<std::size_t>(j)].push_back(
          alternative(alternatives[k], l.points, file, key + "[" + std::to_string(k) + "]"));
    }
  }
  if (doc.contains("derived")) {
    if (!doc["derived"].is_object()) throwMalformed(file, "derived", "must be an object joint -> reason");
    for (const auto& [name, why] : doc["derived"].items()) {
      const int j = jointIndex(name, file, "derived." + name);
      if (!why.is_string()) throwMalformed(file, "derived." + name, "must be a string");
      l.derived[static_cast<std::size_t>(j)] = why.get<std::string>();
    }
  }
  parseDetectorOffsets(doc, file, l);
  parseFeet(doc, file, l);
  return l;
}

bool KeypointLayout::hasFeet() const {
  return std::any_of(feet.begin(), feet.end(), [](const auto& alternatives) { return !alternatives.empty(); });
}

const std::vector<KeypointLayout>& keypointLayouts() {
  static const std::vector<KeypointLayout> layouts = [] {
    std::vector<KeypointLayout> out;
    for (const auto& name : embeddedAssetNames("keypoint-layouts/")) {
      if (name.ends_with(".json")) out.push_back(parseKeypointLayout(embeddedAsset(name), "assets/" + name));
    }
    if (out.empty()) throw Error(ErrorKind::Io, "assets/keypoint-layouts", "", "no layouts embedded");
    return out;
  }();
  return layouts;
}

const KeypointLayout& keypointLayoutNamed(std::string_view name) {
  std::string known;
  for (const auto& l : keypointLayouts()) {
    if (nameKey(l.name) == nameKey(name)) return l;
    known += (known.empty() ? "" : ", ") + l.name;
  }
  throw Error(ErrorKind::BadArgument, "", "--layout",
              "unknown keypoint layout '" + std::string(name) + "' (known: " + known + ")");
}

std::vector<const KeypointLayout*> keypointLayoutsWithPoints(int pointCount) {
  std::vector<const KeypointLayout*> out;
  for (const auto& l : keypointLayouts()) {
    if (static_cast<int>(l.points.size()) == pointCount) out.push_back(&l);
  }
  return out;
}

}  // namespace ew
