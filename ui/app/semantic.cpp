#include "ui/app/semantic.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/common/errors.h"
#include "ui/app/derived.h"
#include "ui/app/population.h"

namespace ew::ui {
namespace {

// The unit inside a label's parentheses: "speed (m/s, measured)" → "m/s".
std::string unitOf(const std::string& label) {
  const auto open = label.find('(');
  if (open == std::string::npos) return "";
  const auto end = label.find_first_of(",)", open);
  return end == std::string::npos ? "" : label.substr(open + 1, end - open - 1);
}

std::vector<Walker> walkersExcept(const std::vector<Walker>& walkers, const std::string& subject, std::vector<int>& kept) {
  std::vector<Walker> out;
  for (size_t r = 0; r < walkers.size(); ++r) {
    if (walkers[r].subject == subject) continue;
    out.push_back(walkers[r]);
    kept.push_back(static_cast<int>(r));
  }
  return out;
}

}  // namespace

const SemanticAxisView* SemanticAxes::find(const std::string& attribute) const {
  for (const auto& a : axes)
    if (a.axis.attribute == attribute) return &a;
  return nullptr;
}

AxesWalkers populationAxesWalkers(const Population& population) {
  return {population.walkers, walkerAttributes(population.walkers),
          "the loaded population's " + std::to_string(population.walkerCount()) + " walkers"};
}

AxesWalkers modelAxesWalkers(const EigenwalkerModel& model, const std::string& name) {
  std::vector<Walker> walkers = storedWalkers(model, name);
  AttributeTable table = walkerAttributes(walkers);
  return {std::move(walkers), std::move(table), name + "'s " + std::to_string(model.walkerCount()) + " walkers"};
}

SemanticAxes fitAxes(const AxesWalkers& from, const EigenwalkerModel& exploreModel) {
  const AttributeTable& table = from.table;
  const std::vector<Walker>& reference = from.walkers;
  SemanticAxes out;
  out.from = from.from;
  out.notes = table.notes;
  const AxisWalkers walkers = axisWalkers(exploreModel, reference);
  out.omegaMeanRadS = walkers.omegaRadS.mean();
  out.walkersSd.resize(2, walkers.k.cols());
  for (Eigen::Index r = 0; r < walkers.k.cols(); ++r)
    for (Eigen::Index i = 0; i < 2; ++i)
      out.walkersSd(i, r) = i < walkers.k.rows() ? walkers.k(i, r) / std::sqrt(std::max(exploreModel.eigenvalues(i), 1e-12)) : 0.0;
  ModelOptions options;
  options.components = exploreModel.componentCount();
  std::vector<AxisFold> folds;
  try {
    folds = axisFolds(reference, options);
  } catch (const Error& e) {
    out.notes.push_back("no leave-one-subject-out quality: " + e.problem());
  }
  for (const auto& a : table.attributes) {
    try {
      SemanticAxisView v;
      v.axis = fitSemanticAxis(a, exploreModel.eigenvalues, walkers);
      v.source = a.source;
      if (!v.axis.steerable) {
        out.notes.push_back(a.name + ": not predictable from the walker (gain " + std::to_string(v.axis.gain).substr(0, 4) + ")");
        continue;
      }
      if (!folds.empty()) v.quality = leaveOneSubjectOut(a, reference, folds);
      out.axes.push_back(std::move(v));
    } catch (const Error& e) {
      out.notes.push_back(e.problem());
    }
  }
  return out;
}

std::string formatAttributeValue(const SemanticAxisView& a, double value) {
  char text[64];
  if (a.axis.categorical) {
    std::snprintf(text, sizeof text, "%.2f", value);
    return text;
  }
  const double magnitude = std::max(std::abs(a.axis.mean), a.axis.sd);
  const int decimals = magnitude >= 100 ? 0 : magnitude >= 10 ? 1 : 2;
  const std::string unit = unitOf(a.axis.label);
  std::snprintf(text, sizeof text, "%.*f%s%s", decimals, value, unit.empty() ? "" : " ", unit.c_str());
  return text;
}

std::map<std::string, double> ownAttributeValues(const AxesWalkers& reference, int referenceIndex, const Walker& walker) {
  std::map<std::string, double> own;
  if (referenceIndex >= 0) {
    for (const auto& a : reference.table.attributes) own[a.name] = a.values[static_cast<size_t>(referenceIndex)];
    return own;
  }
  const auto measured = measureWalkerAttributes(walker.fit.w, walker.fit.omegaRadS / (2.0 * std::numbers::pi), walker.id);
  for (const auto& a : reference.table.attributes) {
    const auto it = measured.find(a.name);
    own[a.name] = a.source == "measured" && it != measured.end() ? it->second : NAN;
  }
  return own;
}

ViewAxes fitViewAxes(const AxesWalkers& reference, const std::string& withoutSubject,
                     const std::map<std::string, double>& own, const EigenwalkerModel& model) {
  ViewAxes out;
  out.from = reference.from;
  out.without = withoutSubject;
  std::vector<int> kept;
  const std::vector<Walker> train = walkersExcept(reference.walkers, withoutSubject, kept);
  if (train.size() < 3) return out;
  const AxisWalkers trainWalkers = axisWalkers(model, train);
  for (const auto& a : reference.table.attributes) {
    const auto value = own.find(a.name);
    if (value == own.end() || !std::isfinite(value->second)) continue;
    try {
      SemanticAxis axis = fitSemanticAxis(trainingAttribute(a, kept), model.eigenvalues, trainWalkers);
      if (!axis.steerable) continue;
      out.axes.push_back(std::move(axis));
      out.truth.push_back(value->second);
    } catch (const Error&) {
      // Too few values among the other subjects: no prediction for this attribute.
    }
  }
  return out;
}

std::vector<AttributeFromView> attributesFromView(const ViewAxes& axes, double omegaRadS, const ReconBase& recon) {
  std::vector<AttributeFromView> out;
  if (recon.engine != EngineKind::Eigenwalker) return out;
  const Eigen::VectorXd k3d = projectOntoModel(recon.model, recon.wTrue);
  for (size_t i = 0; i < axes.axes.size(); ++i) {
    const SemanticAxis& a = axes.axes[i];
    AttributeFromView v;
    v.attribute = a.attribute;
    v.label = a.label;
    v.categorical = a.categorical;
    v.classes = a.classes;
    v.truth = axes.truth[i];
    v.from2d = predictAttribute(a, recon.estimate.k, omegaRadS);
    v.from3d = predictAttribute(a, k3d, omegaRadS);
    out.push_back(v);
  }
  return out;
}

}  // namespace ew::ui
