#pragma once
// Experiment "semantic" (issue 18): the semantic axes of the walkers' attributes
// (core/semantic/semantic_axes.h) — how well each attribute is predicted from the walker
// (leave one subject out), whether moving a walker along an axis changes what is measured on
// it by what the axis says, and how well each attribute is predicted from one 2D view alone
// (Zhang & Troje 2007's suggested application: view-independent gait characterisation).
//
//   axes       one row per attribute: LOO R² and RMSE (numeric) or accuracy beside chance
//              (two classes); the axis's gain; and for a measured attribute the slider check:
//              the model's mean walker (k = 0, ω̄) moved by +1 SD of the attribute along its
//              axis, synthesised and measured again (walker_attributes.h) — the measured change
//              over the SD should be 1.
//   from view  per held-out subject (model refitted without it), its walker projected
//              orthographically at each angle, reconstructed by MAP at the known view and at
//              the view the search finds, and every attribute predicted from the reconstructed
//              k and the walker's ω (a 2D Fourier fit gives ω whatever the view), beside the
//              prediction from its 3D w and its true value.

#include <string>
#include <vector>

#include "core/eigenwalker/model.h"
#include "core/eigenwalker/walker_set.h"
#include "core/semantic/semantic_axes.h"

namespace ew {

struct SemanticExperimentOptions {
  ModelOptions model;
  std::vector<double> anglesDeg{0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0};
  double sigma2Mm2 = 1000.0;  // MAP σ² (the project's sweep optimum on the shared walkers)
  bool unknownView = true;    // also reconstruct with the view searched for
  int threads = 1;
};

struct SemanticAxisRow {
  std::string attribute, label, source;
  bool categorical = false;
  int walkers = 0;
  double mean = NAN, sd = NAN;
  double looR2 = NAN, looRmse = NAN;          // numeric
  double looAccuracy = NAN, chance = NAN;     // two classes
  double gain = NAN;                          // cᵀg of the axis fitted on every walker
  bool steerable = false;
  double sliderMeasuredChange = NAN;          // measured: change at +1 SD (attribute units)
  double sliderRatio = NAN;                   // … over the SD
};

struct SemanticViewRow {
  std::string subject, walker, attribute;
  std::string view;         // "known" or "unknown"
  double angleDeg = 0.0;    // the true view
  double alphaHatDeg = NAN; // the view found ("unknown")
  double truth = NAN, from3d = NAN, from2d = NAN;
  bool categorical = false;
  int class3d = -1, class2d = -1;  // two classes: the predicted class (truth: 1 when > 0.5)
};

struct SemanticViewSummaryRow {
  std::string attribute, view;
  bool categorical = false;
  double angleDeg = 0.0;
  int walkers = 0;
  double sd = NAN;                    // of the truth over these walkers
  double rmse3d = NAN, rmse2d = NAN;  // numeric
  double r2From2d = NAN;
  double accuracy3d = NAN, accuracy2d = NAN;  // two classes
};

struct SemanticExperimentResults {
  int components = 0;  // N of the model of every walker
  std::vector<SemanticAxisRow> axes;
  std::vector<SemanticViewRow> views;
  std::vector<SemanticViewSummaryRow> viewSummary;
  std::vector<std::string> notes;  // attributes left out, and why
};

// Throws Error(BadData) for fewer than 3 subjects or no attribute with an axis.
SemanticExperimentResults semanticExperiment(const std::vector<Walker>& walkers, const SemanticExperimentOptions& options);

// Grouped by attribute, view and angle, in the order first seen.
std::vector<SemanticViewSummaryRow> summarizeSemanticViews(const std::vector<SemanticViewRow>& rows);

}  // namespace ew
