#pragma once
// Walkers from a dataset (METHOD §4): a walker is one trial, or the mean Fourier vector of
// several trials of one subject in one condition. Builds the eigenwalker model from them.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/model.h"
#include "core/gait/dataset.h"

namespace ew {

struct Walker {
  std::string id;         // subject + "/" + condition
  std::string subject;
  std::string source;
  std::string condition;
  std::map<std::string, std::string> attributes;  // the first trial's manifest extras
  std::vector<std::string> files;                 // trials averaged into this walker
  FourierFit fit;  // 3D fit; for several trials: w, ω and the shares averaged, cycles and
                   // frames summed, φ = 0 (w is already phase-aligned; no one time base)
};

// Groups trials by (subject, condition) in first-seen order and fits each trial with the
// stride frequency of its gait cycles as the ω hint (METHOD §3). A trial whose fit fails is
// left out with a warning "file: reason" (as is a walker left with no trial); fit warnings
// are kept on the walker, prefixed with the file. A trial whose joints are not 3D (45
// columns) is left out the same way; a stride frequency that is not positive and finite is
// no hint (the scan alone decides ω). A trial with joints missing throughout
// (missing_joints.h) is left out the same way: a model is not built from its own estimates.
std::vector<Walker> makeWalkers(const Dataset& dataset, std::vector<std::string>* warnings = nullptr);

// Whether `trial` is one of the trials averaged into `walker` (its subject, condition and file).
bool isTrialOf(const Walker& walker, const TrialInfo& trial);

// The mean overground speed (m/s) of the walker's trials in `dataset` that have one (a
// treadmill trial has none); nullopt when none has.
std::optional<double> walkerSpeedMps(const Dataset& dataset, const Walker& walker);

// The walkers a model was built from, as it stores them (storedWalkerVectors, their ω; ids and
// subjects as it names them, `source` as given, condition unspecified): no files, no manifest
// attributes. What the viewer's axes and analysis learn from when the model held is not the
// loaded population's own.
std::vector<Walker> storedWalkers(const EigenwalkerModel& model, const std::string& source);

// W = [w_1 … w_R] (225 × R).
Eigen::MatrixXd walkerMatrix(const std::vector<Walker>& walkers);

// The model of these walkers, with one provenance line per walker (id, source, files).
// Fewer than 2 walkers, or a walker without a finite 3D fit, is Error(BadArgument)
// "model: …" naming the walker.
EigenwalkerModel buildModel(const std::vector<Walker>& walkers, const ModelOptions& options = {});

// Leave-one-subject-out model (METHOD §4, §8): every walker of `subject` left out.
EigenwalkerModel buildModelWithoutSubject(const std::vector<Walker>& walkers,
                                          const std::string& subject,
                                          const ModelOptions& options = {});

}  // namespace ew
