#include "core/semantic/walker_attributes.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <utility>
#include <variant>

#include "core/common/skeleton.h"
#include "core/gait/fourier_walker_gait.h"

namespace ew {
namespace {

// An attribute's label and the words at its slider's ends.
struct AttributeWords {
  const char* name;  // the column; for a manifest column, the start of its name
  const char* label;
  const char* low;
  const char* high;
};

// [SECTION] Measured on the walker

const std::vector<AttributeWords>& measuredSpecs() {
  static const std::vector<AttributeWords> specs = {
      {"measured_speed_mps", "speed (m/s, measured)", "slower", "faster"},
      {"measured_cadence_spm", "cadence (steps/min, measured)", "fewer steps", "more steps"},
      {"measured_stride_length_m", "stride length (m, measured)", "shorter strides", "longer strides"},
      {"measured_step_width_m", "step width (m, measured)", "narrower", "wider"},
      {"measured_height_m", "head above ankles (m, measured)", "shorter", "taller"},
      {"measured_leg_length_m", "leg length (m, measured)", "shorter legs", "longer legs"},
      {"measured_arm_swing_deg", "arm swing (°, measured)", "less arm swing", "more arm swing"},
      {"measured_knee_flexion_range_deg", "knee flexion range (°, measured)", "stiffer knees", "more knee flexion"},
  };
  return specs;
}

Eigen::Vector3d joint(const Eigen::MatrixXd& frames, Eigen::Index f, Joint j) {
  return frames.row(f).segment<3>(3 * static_cast<int>(j)).transpose();
}

// Mean over frames of the head joint's height above the lower ankle joint, m.
double headAboveAnklesM(const Eigen::MatrixXd& frames) {
  double sum = 0.0;
  for (Eigen::Index f = 0; f < frames.rows(); ++f) {
    const double ankle = std::min(joint(frames, f, Joint::RAnkle).z(), joint(frames, f, Joint::LAnkle).z());
    sum += joint(frames, f, Joint::Head).z() - ankle;
  }
  return frames.rows() > 0 ? sum / static_cast<double>(frames.rows()) / 1000.0 : NAN;
}

// Mean over frames and both sides of thigh + shank length, m.
double legLengthM(const Eigen::MatrixXd& frames) {
  double sum = 0.0;
  for (Eigen::Index f = 0; f < frames.rows(); ++f) {
    sum += (joint(frames, f, Joint::RHip) - joint(frames, f, Joint::RKnee)).norm() +
           (joint(frames, f, Joint::RKnee) - joint(frames, f, Joint::RAnkle)).norm() +
           (joint(frames, f, Joint::LHip) - joint(frames, f, Joint::LKnee)).norm() +
           (joint(frames, f, Joint::LKnee) - joint(frames, f, Joint::LAnkle)).norm();
  }
  return frames.rows() > 0 ? sum / (2.0 * static_cast<double>(frames.rows())) / 1000.0 : NAN;
}

// [SECTION] Manifest columns

double parseNumber(const std::string& text) {
  if (text.empty()) return NAN;
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || !std::isfinite(v)) return NAN;
  return v;
}

std::string lowerCase(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// How tables write "no value": such a cell is unknown for that walker, not a class of its own.
bool isMissing(const std::string& cell) {
  const std::string c = lowerCase(cell);
  return c.empty() || c == "nan" || c == "na" || c == "n/a" || c == "-" || c == "?" || c == "null";
}

// "F" → "female", "m" → "male"; other class names as they are.
std::string classWord(const std::string& cls) {
  const std::string c = lowerCase(cls);
  if (c == "f" || c == "female" || c == "w" || c == "woman") return "female";
  if (c == "m" || c == "male" || c == "man") return "male";
  return cls;
}

// Slider words for the manifest columns the field uses (Troje 2002's BMLwalker axes and the
// synthetic population's attributes); any other column reads "lower NAME" ↔ "higher NAME".
const std::vector<AttributeWords>& numericWords() {
  static const std::vector<AttributeWords> words = {
      {"speed", "speed (m/s)", "slower", "faster"},
      {"height", "height (m)", "shorter", "taller"},
      {"stature", "stature (m)", "shorter", "taller"},
      {"leg_length", "leg length (m)", "shorter legs", "longer legs"},
      {"mass", "body mass (kg)", "lighter", "heavier"},
      {"weight", "body weight (kg)", "lighter", "heavier"},
      {"age", "age (years)", "younger", "older"},
      {"cadence", "cadence (steps/min)", "fewer steps", "more steps"},
      {"stride_length", "stride length (m)", "shorter strides", "longer strides"},
      {"step_width", "step width (mm)", "narrower", "wider"},
      {"arm_swing", "arm swing (°)", "less arm swing", "more arm swing"},
      {"hip_rom", "hip range of motion (°)", "less hip motion", "more hip motion"},
      {"knee_flexion", "knee flexion (°)", "straighter knees", "more knee flexion"},
      {"elbow_flexion", "elbow flexion (°)", "straighter elbows", "more bent elbows"},
      {"trunk_lean", "trunk lean (°)", "upright", "leaning forward"},
      {"lateral_sway", "lateral sway (mm)", "less sway", "more sway"},
      {"pelvis_rotation", "pelvis rotation (°)", "less pelvis rotation", "more pelvis rotation"},
      {"pelvis_obliquity", "pelvis obliquity (°)", "less pelvis tilt", "more pelvis tilt"},
      // The synthetic population's left arm's swing over the right's, less 1 (docs/SYNTHETIC.md).
      {"asymmetry_arm", "arm swing asymmetry (left ÷ right − 1)", "right arm swings more",
       "left arm swings more"},
  };
  return words;
}

// A column name's unit suffix and the unit's words in a label.
constexpr std::pair<const char*, const char*> kUnitSuffixes[] = {
    {"_mps", "m/s"}, {"_spm", "steps/min"}, {"_deg", "°"}, {"_pct", "%"}, {"_kg", "kg"},
    {"_mm", "mm"},   {"_cm", "cm"},         {"_m", "m"},   {"_s", "s"}};

void setNumericWords(WalkerAttribute& a) {
  for (const auto& w : numericWords()) {
    if (a.name.rfind(w.name, 0) == 0) {
      a.label = w.label;
      a.lowWord = w.low;
      a.highWord = w.high;
      return;
    }
  }
  // "knee_loading_deg" → "knee loading (°)", "less knee loading" ↔ "more knee loading".
  std::string words = a.name, unitWords;
  for (const auto& [suffix, unit] : kUnitSuffixes) {
    const std::string u = suffix;
    if (words.size() > u.size() && words.compare(words.size() - u.size(), u.size(), u) == 0) {
      words.resize(words.size() - u.size());
      unitWords = unit;
      break;
    }
  }
  std::replace(words.begin(), words.end(), '_', ' ');
  a.label = unitWords.empty() ? words : words + " (" + unitWords + ")";
  a.lowWord = "less " + words;
  a.highWord = "more " + words;
}

// A two-valued column (0/1, or text): categorical, class 0 the first in sorted order (for 0/1,
// the value 0).
void makeCategorical(WalkerAttribute& a, const std::vector<std::string>& text, const std::vector<std::string>& classes) {
  a.categorical = true;
  a.classes = classes;
  a.label = a.name;
  if (classes == std::vector<std::string>{"0", "1"}) {
    // A 0/1 flag: "female" = 1 reads male ↔ female.
    const std::string other = a.name == "female" ? "male" : a.name == "male" ? "female" : "not " + a.name;
    a.classes = {other, a.name};
  }
  a.lowWord = classWord(a.classes[0]);
  a.highWord = classWord(a.classes[1]);
  a.values.assign(text.size(), NAN);
  for (size_t i = 0; i < text.size(); ++i) {
    if (text[i] == classes[0]) a.values[i] = 0.0;
    if (text[i] == classes[1]) a.values[i] = 1.0;
  }
}

// The column `name` as an attribute, or the reason it is left out.
std::variant<WalkerAttribute, std::string> manifestAttribute(const std::string& name, const std::vector<Walker>& walkers) {
  std::vector<std::string> text;
  std::map<std::string, int> classCounts;
  bool allNumbers = true;
  for (const Walker& w : walkers) {
    const auto it = w.attributes.find(name);
    text.push_back(it == w.attributes.end() || isMissing(it->second) ? "" : it->second);
    if (text.back().empty()) continue;
    ++classCounts[text.back()];
    if (std::isnan(parseNumber(text.back()))) allNumbers = false;
  }
  int known = 0;
  for (const auto& [cls, n] : classCounts) known += n;
  if (known < 3) return name + ": fewer than 3 walkers have a value";
  if (classCounts.size() < 2) return name + ": every walker has the same value";
  WalkerAttribute a;
  a.name = name;
  a.source = "manifest";
  const bool flag = classCounts.size() == 2 && classCounts.count("0") && classCounts.count("1");
  if (allNumbers && !flag) {
    for (const auto& t : text) a.values.push_back(parseNumber(t));
    setNumericWords(a);
    return a;
  }
  if (classCounts.size() > 2)
    return name + ": " + std::to_string(classCounts.size()) + " classes (an axis runs between two)";
  for (const auto& [cls, n] : classCounts)
    if (n < 2) return name + ": class '" + cls + "' has a single walker";
  std::vector<std::string> classes;
  for (const auto& [cls, n] : classCounts) classes.push_back(cls);
  makeCategorical(a, text, classes);
  return a;
}

}  // namespace

int WalkerAttribute::known() const {
  return static_cast<int>(std::count_if(values.begin(), values.end(), [](double v) { return std::isfinite(v); }));
}

const WalkerAttribute* AttributeTable::find(const std::string& name) const {
  for (const auto& a : attributes)
    if (a.name == name) return &a;
  return nullptr;
}

const std::vector<std::string>& measuredAttributeNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& s : measuredSpecs()) n.push_back(s.name);
    return n;
  }();
  return names;
}

std::map<std::string, double> measureWalkerAttributes(const Eigen::Ref<const Eigen::VectorXd>& w, double strideHz,
                                                      const std::string& name) {
  std::map<std::string, double> out;
  for (const auto& n : measuredAttributeNames()) out[n] = NAN;
  const FourierWalkerGait g = measureFourierWalker(w, strideHz, std::nullopt, name);
  if (g.framesMm.rows() > 0) {
    out["measured_height_m"] = headAboveAnklesM(g.framesMm);
    out["measured_leg_length_m"] = legLengthM(g.framesMm);
  }
  if (std::isfinite(strideHz) && strideHz > 0) out["measured_cadence_spm"] = 120.0 * strideHz;
  if (!g.measures) return out;
  out["measured_speed_mps"] = g.measures->speedMps;
  out["measured_stride_length_m"] = g.measures->strideLengthM;
  out["measured_step_width_m"] = g.measures->stepWidthM;
  out["measured_arm_swing_deg"] = flexionRangeDeg(g.curves, "arm_flex");
  out["measured_knee_flexion_range_deg"] = flexionRangeDeg(g.curves, "knee_angle");
  return out;
}

AttributeTable walkerAttributes(const std::vector<Walker>& walkers) {
  AttributeTable table;
  std::set<std::string> columns;
  for (const Walker& w : walkers)
    for (const auto& [name, value] : w.attributes) columns.insert(name);
  for (const auto& name : columns) {
    auto a = manifestAttribute(name, walkers);
    if (auto* attribute = std::get_if<WalkerAttribute>(&a)) {
      table.attributes.push_back(std::move(*attribute));
    } else {
      table.notes.push_back(std::get<std::string>(a));
    }
  }
  std::vector<std::map<std::string, double>> measured;
  for (const Walker& w : walkers)
    measured.push_back(measureWalkerAttributes(w.fit.w, w.fit.omegaRadS / (2.0 * std::numbers::pi), w.id));
  for (const auto& spec : measuredSpecs()) {
    WalkerAttribute a;
    a.name = spec.name;
    a.label = spec.label;
    a.source = "measured";
    a.lowWord = spec.low;
    a.highWord = spec.high;
    for (const auto& m : measured) a.values.push_back(m.at(spec.name));
    if (a.known() < 3) {
      table.notes.push_back(a.name + ": measured on fewer than 3 walkers");
      continue;
    }
    table.attributes.push_back(std::move(a));
  }
  return table;
}

}  // namespace ew
