#pragma once
// What the semantic axes (semantic_axes.h) are fitted to: one value per walker for each
// attribute the data has. Two kinds of source:
//   manifest  the manifest's optional columns (sex, age, height_m, mass_kg, condition, …; the
//             synthetic population writes its generating attributes there: height_m, female,
//             speed_mps, cadence_spm, …). A column whose every value is a number is numeric; a
//             column of text (or of 0 and 1 only) with exactly two classes is categorical.
//   measured  measured on the walker's own two-harmonic representation (w, ω), the way the
//             gait report measures any walker (core/gait/fourier_walker_gait.h): speed, cadence,
//             stride length, step width from the gait measures; height as the head joint above
//             the ankle joints; leg length as hip–knee + knee–ankle; arm swing as the range of
//             shoulder flexion; knee flexion range. Measured the same way on a recorded walker
//             and on one synthesised from the model, so a slider's effect can be checked.

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

#include "core/eigenwalker/walker_set.h"

namespace ew {

struct WalkerAttribute {
  std::string name;    // column: "speed_mps" (manifest), "measured_speed_mps"
  std::string label;   // "speed (m/s, measured)"
  std::string source;  // "manifest" or "measured"
  bool categorical = false;
  std::vector<std::string> classes;  // categorical: the class of value 0, then of value 1
  std::vector<double> values;        // one per walker; NaN: unknown for that walker
  std::string lowWord, highWord;     // the ends of its slider: "slower", "faster"
  int known() const;                 // walkers with a value
};

struct AttributeTable {
  std::vector<WalkerAttribute> attributes;
  std::vector<std::string> notes;  // columns left out, and why
  const WalkerAttribute* find(const std::string& name) const;
};

// The measured attributes of one walker (w: 225, phase origin 0; strideHz > 0), by name
// ("measured_speed_mps", …, in measuredAttributeNames() order); NaN where it cannot be
// measured (no complete stride).
std::map<std::string, double> measureWalkerAttributes(const Eigen::Ref<const Eigen::VectorXd>& w,
                                                      double strideHz, const std::string& name);
const std::vector<std::string>& measuredAttributeNames();

// Manifest columns and measured attributes of every walker. A manifest column is left out,
// with a note, when fewer than 3 walkers have a value, when its values are all equal, or when
// it is text with more than two classes or a class with a single walker.
AttributeTable walkerAttributes(const std::vector<Walker>& walkers);

}  // namespace ew
