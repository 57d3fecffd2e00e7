#include "core/experiments/semantic_experiment.h"

#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "core/engines/request.h"
#include "core/common/errors.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/experiments/leave_one_out.h"

namespace ew {
namespace {

// [SECTION] The axes and their slider check

// The model's mean walker moved by +1 SD along the axis, measured again.
void checkSlider(const SemanticAxis& axis, const EigenwalkerModel& model, double meanOmega, SemanticAxisRow& row) {
  if (!axis.steerable || !(axis.sd > 0)) return;
  const double baseHz = meanOmega / (2.0 * std::numbers::pi);
  const double movedHz = (meanOmega + axis.directionOmega * axis.sd) / (2.0 * std::numbers::pi);
  const Eigen::VectorXd k = axis.directionK * axis.sd;
  const auto before = measureWalkerAttributes(model.mean, baseHz, "mean walker");
  const auto after = measureWalkerAttributes(synthesizeWalker(model, k), movedHz, "mean walker + 1 SD " + axis.attribute);
  row.sliderMeasuredChange = after.at(axis.attribute) - before.at(axis.attribute);
  row.sliderRatio = row.sliderMeasuredChange / axis.sd;
}

SemanticAxisRow axisRow(const WalkerAttribute& a, const AxisQuality& q, const EigenwalkerModel& full,
                        const AxisWalkers& fullWalkers) {
  SemanticAxisRow row;
  row.attribute = a.name;
  row.label = a.label;
  row.source = a.source;
  row.categorical = a.categorical;
  const SemanticAxis axis = fitSemanticAxis(a, full.eigenvalues, fullWalkers);
  row.walkers = axis.walkers;
  row.mean = axis.mean;
  row.sd = axis.sd;
  row.gain = axis.gain;
  row.steerable = axis.steerable;
  row.looR2 = q.r2;
  row.looRmse = q.rmse;
  row.looAccuracy = q.accuracy;
  row.chance = q.chance;
  if (a.source == "measured") checkSlider(axis, full, fullWalkers.omegaRadS.mean(), row);
  return row;
}

// [SECTION] From one view

// The axes of every attribute fitted in one fold (those with enough training values), used for
// both the held-out walkers' own cycles (the axes' quality) and their 2D views.
struct FoldAxes {
  std::vector<const WalkerAttribute*> attributes;
  std::vector<SemanticAxis> axes;
  const SemanticAxis* of(const WalkerAttribute& a) const {
    for (size_t i = 0; i < attributes.size(); ++i)
      if (attributes[i] == &a) return &axes[i];
    return nullptr;
  }
};

FoldAxes fitFoldAxes(const AttributeTable& table, const AxisFold& fold) {
  FoldAxes out;
  for (const auto& a : table.attributes) {
    try {
      out.axes.push_back(fitSemanticAxis(trainingAttribute(a, fold.train), fold.model.eigenvalues, fold.trainWalkers));
      out.attributes.push_back(&a);
    } catch (const Error&) {
      // Too few values without this subject: its walkers are not predicted for this attribute.
    }
  }
  return out;
}

// Leave one subject out from the folds' axes: each held-out walker predicted from its own cycle
// (heldOutK: its coefficients in its fold's model).
AxisQuality heldOutQuality(const WalkerAttribute& a, const std::vector<Walker>& walkers, const std::vector<AxisFold>& folds,
                           const std::vector<FoldAxes>& foldAxes, const std::vector<Eigen::VectorXd>& heldOutK) {
  std::vector<double> predictions(walkers.size(), NAN);
  std::vector<int> classes(walkers.size(), -1);
  for (size_t f = 0; f < folds.size(); ++f) {
    const SemanticAxis* axis = foldAxes[f].of(a);
    if (!axis) continue;
    for (int r : folds[f].test) {
      const auto i = static_cast<size_t>(r);
      if (!std::isfinite(a.values[i])) continue;
      predictions[i] = predictAttribute(*axis, heldOutK[i], walkers[i].fit.omegaRadS);
      classes[i] = predictedClass(*axis, predictions[i]);
    }
  }
  return scorePredictions(a, std::move(predictions), classes);
}

void addPredictions(const FoldAxes& fa, const Walker& w, const Eigen::VectorXd& k3d, const Eigen::VectorXd& k2d,
                    double angle, double alphaHat, const std::string& view, size_t r, std::vector<SemanticViewRow>& out) {
  for (size_t i = 0; i < fa.axes.size(); ++i) {
    const double truth = fa.attributes[i]->values[r];
    if (!std::isfinite(truth)) continue;
    SemanticViewRow row;
    row.subject = w.subject;
    row.walker = w.id;
    row.attribute = fa.axes[i].attribute;
    row.view = view;
    row.angleDeg = angle;
    row.alphaHatDeg = alphaHat;
    row.truth = truth;
    row.from3d = predictAttribute(fa.axes[i], k3d, w.fit.omegaRadS);
    row.from2d = predictAttribute(fa.axes[i], k2d, w.fit.omegaRadS);
    row.categorical = fa.axes[i].categorical;
    if (row.categorical) {
      row.class3d = predictedClass(fa.axes[i], row.from3d);
      row.class2d = predictedClass(fa.axes[i], row.from2d);
    }
    out.push_back(row);
  }
}

std::vector<SemanticViewRow> foldViewRows(const FoldAxes& fa, const std::vector<Walker>& walkers, const AxisFold& fold,
                                          const std::vector<Eigen::VectorXd>& heldOutK,
                                          const SemanticExperimentOptions& options) {
  std::vector<SemanticViewRow> out;
  if (fa.axes.empty()) return out;
  const ModelGram gram = precomputeModelGram(fold.model);
  const EstimatorOptions map{Estimator::Map, options.sigma2Mm2};
  for (int r : fold.test) {
    const Walker& w = walkers[static_cast<size_t>(r)];
    const Eigen::VectorXd& k3d = heldOutK[static_cast<size_t>(r)];
    for (double angle : options.anglesDeg) {
      const Eigen::VectorXd observed = projectToView(w.fit.w, angle);
      const Reconstruction known = reconstructFourierView(gram, observed, angle, map).reconstruction;
      addPredictions(fa, w, k3d, known.k, angle, angle, "known", static_cast<size_t>(r), out);
      if (!options.unknownView) continue;
      const ViewSearch search = *reconstructFourierView(gram, observed, std::nullopt, map).search;
      addPredictions(fa, w, k3d, search.best.k, angle, search.best.alphaDeg, "unknown", static_cast<size_t>(r), out);
    }
  }
  return out;
}

}  // namespace

SemanticExperimentResults semanticExperiment(const std::vector<Walker>& walkers, const SemanticExperimentOptions& options) {
  std::set<std::string> subjects;
  for (const Walker& w : walkers) subjects.insert(w.subject);
  if (subjects.size() < 3)
    throw Error(ErrorKind::BadData, "", "",
                "semantic axes: leave one subject out needs at least 3 subjects, got " + std::to_string(subjects.size()));
  SemanticExperimentResults res;
  const AttributeTable table = walkerAttributes(walkers);
  res.notes = table.notes;
  const EigenwalkerModel full = buildModel(walkers, options.model);
  res.components = full.componentCount();
  const AxisWalkers fullWalkers = axisWalkers(full, walkers);
  const std::vector<AxisFold> folds = axisFolds(walkers, options.model, options.threads);
  // Each fold's axes once, for the quality and the views alike.
  std::vector<FoldAxes> foldAxes(folds.size());
  std::vector<Eigen::VectorXd> heldOutK(walkers.size());
  std::vector<std::vector<SemanticViewRow>> parts(folds.size());
  parallelFor(static_cast<int>(folds.size()), options.threads, [&](int f) {
    const AxisFold& fold = folds[static_cast<size_t>(f)];
    foldAxes[static_cast<size_t>(f)] = fitFoldAxes(table, fold);
    for (int r : fold.test) heldOutK[static_cast<size_t>(r)] = projectOntoModel(fold.model, walkers[static_cast<size_t>(r)].fit.w);
    parts[static_cast<size_t>(f)] = foldViewRows(foldAxes[static_cast<size_t>(f)], walkers, fold, heldOutK, options);
  });
  for (const auto& a : table.attributes) {
    try {
      res.axes.push_back(axisRow(a, heldOutQuality(a, walkers, folds, foldAxes, heldOutK), full, fullWalkers));
    } catch (const Error& e) {
      res.notes.push_back(e.problem());
    }
  }
  if (res.axes.empty()) throw Error(ErrorKind::BadData, "", "", "semantic axes: no attribute of the walkers has an axis");
  for (auto& p : parts) res.views.insert(res.views.end(), p.begin(), p.end());
  res.viewSummary = summarizeSemanticViews(res.views);
  return res;
}

std::vector<SemanticViewSummaryRow> summarizeSemanticViews(const std::vector<SemanticViewRow>& rows) {
  std::vector<SemanticViewSummaryRow> out;
  std::map<std::tuple<std::string, std::string, double>, std::vector<const SemanticViewRow*>> groups;
  std::vector<std::tuple<std::string, std::string, double>> order;
  for (const auto& r : rows) {
    const auto key = std::make_tuple(r.attribute, r.view, r.angleDeg);
    if (!groups.count(key)) order.push_back(key);
    groups[key].push_back(&r);
  }
  for (const auto& key : order) {
    const auto& g = groups[key];
    SemanticViewSummaryRow s;
    std::tie(s.attribute, s.view, s.angleDeg) = key;
    s.categorical = g.front()->categorical;
    s.walkers = static_cast<int>(g.size());
    double mean = 0.0;
    for (const auto* r : g) mean += r->truth;
    mean /= static_cast<double>(g.size());
    double ssTot = 0.0, ss3 = 0.0, ss2 = 0.0;
    int right3 = 0, right2 = 0;
    for (const auto* r : g) {
      ssTot += (r->truth - mean) * (r->truth - mean);
      ss3 += (r->from3d - r->truth) * (r->from3d - r->truth);
      ss2 += (r->from2d - r->truth) * (r->from2d - r->truth);
      const int truthClass = r->truth > 0.5 ? 1 : 0;
      right3 += r->class3d == truthClass;
      right2 += r->class2d == truthClass;
    }
    const double n = static_cast<double>(g.size());
    s.sd = n > 1 ? std::sqrt(ssTot / (n - 1.0)) : NAN;
    if (s.categorical) {
      s.accuracy3d = right3 / n;
      s.accuracy2d = right2 / n;
    } else {
      s.rmse3d = std::sqrt(ss3 / n);
      s.rmse2d = std::sqrt(ss2 / n);
      s.r2From2d = ssTot > 0 ? 1.0 - ss2 / ssTot : NAN;
    }
    out.push_back(s);
  }
  return out;
}

}  // namespace ew
