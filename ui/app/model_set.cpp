#include "ui/app/model_set.h"

#include <algorithm>

namespace ew::ui {

ModelSet buildModelSet(const Population& population,
                       const std::function<void(int, int, const std::string&)>& progress) {
  ModelOptions everything;
  everything.components = population.walkerCount();  // clamped to R − 1 by the engine
  ModelSet set;
  std::vector<std::string> subjects;
  for (const auto& w : population.walkers)
    if (std::find(subjects.begin(), subjects.end(), w.subject) == subjects.end())
      subjects.push_back(w.subject);
  const int total = static_cast<int>(subjects.size()) + 1;
  set.all = buildModel(population.walkers, everything);
  if (progress) progress(1, total, "all walkers");
  int done = 1;
  for (const auto& s : subjects) {
    set.withoutSubject.emplace(s, buildModelWithoutSubject(population.walkers, s, everything));
    if (progress) progress(++done, total, s + " held out");
  }
  return set;
}

EigenwalkerModel truncateModel(const EigenwalkerModel& model, int components) {
  const int n = std::clamp(components, 1, model.componentCount());
  if (n == model.componentCount()) return model;
  EigenwalkerModel m = model;
  m.eigenwalkers = model.eigenwalkers.leftCols(n);
  m.eigenvalues = model.eigenvalues.head(n);
  m.coefficients = model.coefficients.topRows(n);
  return m;
}

double explainedShare(const EigenwalkerModel& model, int components) {
  const double total = model.spectrum.sum();
  if (total <= 0.0) return 0.0;
  const int n = std::clamp(components, 0, static_cast<int>(model.spectrum.size()));
  return model.spectrum.head(n).sum() / total;
}

int autoComponentCount(const EigenwalkerModel& model, double threshold) {
  const int maxN = model.componentCount();
  for (int n = 1; n <= maxN; ++n)
    if (explainedShare(model, n) >= threshold) return n;
  return std::max(1, maxN);
}

}  // namespace ew::ui
