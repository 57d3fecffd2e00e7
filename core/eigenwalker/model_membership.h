#pragma once
// Whether a walker is one of a model's walkers, and the model without it (METHOD §4: a subject is
// never reconstructed by a model that has seen it). Shared by the viewer (ui/app/held_model.h)
// and `reconstruct`.

#include <Eigen/Core>
#include <string>

#include "core/eigenwalker/model.h"

namespace ew {

// The subject of `model` that a walker named `subject` with the 3D Fourier vector `w` (225, or
// empty when unknown) is, or "" when it is none of them: the same subject name, the name with a
// manifest's letter prefix ("SM2014001" for a file's "2014001", "CMU07" for "07"), or the same
// data (its coefficients within 1 mm RMS of a model walker's: the trial the model was built
// from, whatever it is called).
std::string subjectInModel(const EigenwalkerModel& model, const std::string& subject, const Eigen::VectorXd& w);

// The model rebuilt from its stored walkers without `subject`'s, every component kept
// (clamped to R' − 1).
EigenwalkerModel modelWithoutSubject(const EigenwalkerModel& model, const std::string& subject);

}  // namespace ew
