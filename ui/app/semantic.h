#pragma once
// Semantic axes in the viewer (issue 18; core/semantic/semantic_axes.h): sliders that mean
// something ("slower ↔ faster", "shorter ↔ taller", "male ↔ female" where the data has it) for
// the explorer's walker, and, in reconstruct mode, the attributes predicted from the 2D view
// beside the walker's own. GL-free; the coefficients panel draws them.
//
// The axes are fitted to the reference walkers projected onto the explorer's model (the held
// model truncated to its N): the loaded population's, or, when the held model is not the
// population's own (the default model of real walkers, an opened .ewm), the model's own walkers
// as it stores them, with what can be measured on them (their manifests are not in the model).
// Their quality is the leave-one-subject-out R² or accuracy of those walkers' own models
// refitted with that N. An axis moves the walker's coefficients
// and its stride frequency together (ω matters for speed and cadence).

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/semantic/semantic_axes.h"
#include "core/semantic/walker_attributes.h"

namespace ew::ui {

struct Population;
struct ReconBase;

// The explorer's walker (Document::exploreSd and its ω offset), as a semantic slider's drag
// starts from it.
struct ExploreState {
  std::vector<double> sd;
  double omegaOffsetRadS = 0.0;
  bool operator==(const ExploreState&) const = default;
};

struct SemanticAxesKey {
  std::uint64_t generation = 0;
  int components = 0;                             // the explorer's N
  const EigenwalkerModel* heldOther = nullptr;    // heldModelOtherThanThePopulations
  bool operator==(const SemanticAxesKey&) const = default;
};

struct SemanticAxisView {
  SemanticAxis axis;
  AxisQuality quality;
  std::string source;  // "manifest" or "measured"
};

struct SemanticAxes {
  std::vector<SemanticAxisView> axes;   // the steerable ones, in the table's order
  std::string from;                     // "the loaded population's 50 walkers", for the panel
  std::vector<std::string> notes;       // attributes without an axis, and why
  double omegaMeanRadS = 0.0;           // the population's mean ω (the explorer's base)
  Eigen::MatrixXd walkersSd;            // 2 × R: each walker's k1, k2 in SD units (the arrows' plot)
  const SemanticAxisView* find(const std::string& attribute) const;
};

// The walkers the axes learn from, with their attributes (manifest columns and measured gait,
// measured once): `from` names them for the panel.
struct AxesWalkers {
  std::vector<Walker> walkers;
  AttributeTable table;
  std::string from;
};
AxesWalkers populationAxesWalkers(const Population& population);
// A model's stored walkers (storedWalkers): measured attributes only. `name` as heldModelPhrase.
AxesWalkers modelAxesWalkers(const EigenwalkerModel& model, const std::string& name);

// Axes for the explorer's model (the held model truncated to N components).
SemanticAxes fitAxes(const AxesWalkers& from, const EigenwalkerModel& exploreModel);

// "1.42 m/s", "0.72" (two classes), with the attribute's unit from its label.
std::string formatAttributeValue(const SemanticAxisView& a, double value);

// Reconstruct mode: an attribute predicted from the 2D view (the reconstruction's k), from the
// walker's own 3D w, and its true value — axes fitted in the reconstruction's model to the
// reference walkers (AxesWalkers) of the other subjects.
struct AttributeFromView {
  std::string attribute, label;
  bool categorical = false;
  std::vector<std::string> classes;
  double from2d = NAN, from3d = NAN, truth = NAN;
};
// The walker's own values of the reference's attributes, by name: a reference walker's from the
// table (`referenceIndex` ≥ 0), any other's measured on its own cycle (its manifest columns,
// if any, are not the reference's: NaN).
std::map<std::string, double> ownAttributeValues(const AxesWalkers& reference, int referenceIndex, const Walker& walker);
// The axes a walker's attributes are predicted with: fitted in its reconstruction's model to the
// reference walkers other than `withoutSubject`'s ("" for none), for the attributes the walker
// has a value of (they change with the walker and N, not with α).
struct ViewAxes {
  std::string from;     // the reference's `from`
  std::string without;  // the subject left out of it ("" for none)
  std::vector<SemanticAxis> axes;
  std::vector<double> truth;  // the walker's own value of each
};
ViewAxes fitViewAxes(const AxesWalkers& reference, const std::string& withoutSubject,
                     const std::map<std::string, double>& own, const EigenwalkerModel& model);
std::vector<AttributeFromView> attributesFromView(const ViewAxes& axes, double omegaRadS, const ReconBase& recon);

}  // namespace ew::ui
