#pragma once
// The models the viewer reconstructs with: the model of every walker (explorer mode) and,
// for each subject, the model built without that subject (METHOD §4 leave-one-subject-out),
// so a subject is never reconstructed by a model that has seen it. Each model keeps every
// component (R − 1, or R' − 1 without the subject); the N the user chooses is a
// truncation, exact for PCA, so changing N never rebuilds anything.

#include <functional>
#include <map>
#include <string>

#include "core/eigenwalker/model.h"
#include "ui/app/population.h"

namespace ew::ui {

struct ModelSet {
  EigenwalkerModel all;                                 // every walker
  std::map<std::string, EigenwalkerModel> withoutSubject;  // key: held-out subject
};

// Builds every model; progress(done, total, subject) after each. Throws on failure.
ModelSet buildModelSet(const Population& population,
                       const std::function<void(int, int, const std::string&)>& progress = {});

// The first `components` eigenwalkers of `model` (clamped to 1 … its count).
EigenwalkerModel truncateModel(const EigenwalkerModel& model, int components);

// Smallest N whose cumulative variance share reaches `threshold` (METHOD §4 default 95 %).
int autoComponentCount(const EigenwalkerModel& model, double threshold = 0.95);

// Share of the total variance in the first `components` eigenwalkers.
double explainedShare(const EigenwalkerModel& model, int components);

}  // namespace ew::ui
