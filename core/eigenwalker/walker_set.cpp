#include "core/eigenwalker/walker_set.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/gait/missing_joints.h"

namespace ew {
namespace {

struct Group {
  std::string subject, condition;
  std::vector<const DatasetTrial*> trials;
};

std::vector<Group> groupTrials(const Dataset& dataset) {
  std::vector<Group> groups;
  for (const auto& t : dataset.trials) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const Group& g) {
      return g.subject == t.info.subject && g.condition == t.info.condition;
    });
    if (it == groups.end()) {
      groups.push_back({t.info.subject, t.info.condition, {}});
      it = groups.end() - 1;
    }
    it->trials.push_back(&t);
  }
  return groups;
}

FourierFit fitTrial(const DatasetTrial& t) {
  FourierFitOptions options;
  options.file = t.info.file;
  // A walker averages 3D fits (225 values each); a 2D trial here would break the mean.
  if (t.trial.joints.positionsMm.cols() != kDims3)
    throw Error(ErrorKind::BadData, t.info.file, "",
                "walkers: the trial's joints have " +
                    std::to_string(t.trial.joints.positionsMm.cols()) +
                    " columns, 45 (3D) expected");
  // A model is not built from its own estimates: a trial that lacks joints (a lower-body
  // marker set) can be completed by a model (joint_completion.h) but is no walker of one.
  const JointMask missing = missingJointsOf(t.trial.joints);
  if (anyJoint(missing))
    throw Error(ErrorKind::BadData, t.info.file, "",
                "walkers: joints not measured (" + jointList(missing) +
                    "): a model is built from complete walkers only");
  // A hint only when gait events gave a usable frequency (fitFourier rejects others).
  if (std::isfinite(t.trial.cycles.strideHz) && t.trial.cycles.strideHz > 0.0)
    options.omegaHintRadS = 2.0 * std::numbers::pi * t.trial.cycles.strideHz;
  return fitFourier(t.trial.joints.positionsMm, t.trial.joints.rateHz, options);
}

// The mean of several phase-aligned fits of one subject and condition.
FourierFit averageFits(const std::vector<FourierFit>& fits) {
  if (fits.size() == 1) return fits.front();
  FourierFit mean = fits.front();
  const auto n = static_cast<double>(fits.size());
  mean.w.setZero();
  mean.omegaRadS = mean.h1Share = mean.h2Share = mean.residualShare = mean.cycles = 0.0;
  mean.scanOmegaRadS = 0.0;
  mean.framesUsed = mean.framesDropped = 0;
  mean.warnings.clear();
  for (const auto& f : fits) {
    mean.w += f.w / n;
    mean.omegaRadS += f.omegaRadS / n;
    mean.scanOmegaRadS += f.scanOmegaRadS / n;
    mean.h1Share += f.h1Share / n;
    mean.h2Share += f.h2Share / n;
    mean.residualShare += f.residualShare / n;
    mean.cycles += f.cycles;
    mean.framesUsed += f.framesUsed;
    mean.framesDropped += f.framesDropped;
    mean.warnings.insert(mean.warnings.end(), f.warnings.begin(), f.warnings.end());
  }
  mean.phaseRad = 0.0;
  mean.omegaSource = "mean of " + std::to_string(fits.size()) + " trials";
  return mean;
}

}  // namespace

bool isTrialOf(const Walker& walker, const TrialInfo& trial) {
  return trial.subject == walker.subject && trial.condition == walker.condition &&
         std::find(walker.files.begin(), walker.files.end(), trial.file) != walker.files.end();
}

std::optional<double> walkerSpeedMps(const Dataset& dataset, const Walker& walker) {
  double sum = 0.0;
  int count = 0;
  for (const auto& t : dataset.trials) {
    if (!isTrialOf(walker, t.info) || !(t.trial.speedMps > 0.0)) continue;
    sum += t.trial.speedMps;
    ++count;
  }
  if (count == 0) return std::nullopt;
  return sum / count;
}

std::vector<Walker> storedWalkers(const EigenwalkerModel& model, const std::string& source) {
  const Eigen::MatrixXd stored = storedWalkerVectors(model);
  std::vector<Walker> walkers(static_cast<std::size_t>(model.walkerCount()));
  for (int r = 0; r < model.walkerCount(); ++r) {
    Walker& w = walkers[static_cast<std::size_t>(r)];
    w.id = model.walkerIds[static_cast<std::size_t>(r)];
    w.subject = model.subjects[static_cast<std::size_t>(r)];
    w.source = source;
    w.condition = kUnspecifiedCondition;
    w.fit.w = stored.col(r);
    w.fit.omegaRadS = model.omegasRadS[r];
  }
  return walkers;
}

std::vector<Walker> makeWalkers(const Dataset& dataset, std::vector<std::string>* warnings) {
  std::vector<Walker> walkers;
  for (const auto& group : groupTrials(dataset)) {
    Walker walker;
    walker.subject = group.subject;
    walker.condition = group.condition;
    walker.id = group.subject + "/" + group.condition;
    std::vector<FourierFit> fits;
    for (const DatasetTrial* t : group.trials) {
      try {
        FourierFit fit = fitTrial(*t);
        for (auto& w : fit.warnings) w = t->info.file + ": " + w;
        fits.push_back(std::move(fit));
        walker.files.push_back(t->info.file);
        if (walker.source.empty()) {
          walker.source = t->info.source;
          walker.attributes = t->info.attributes;
        }
      } catch (const Error& e) {
        if (warnings) warnings->push_back(std::string(e.what()) + " (trial left out)");
      }
    }
    if (fits.empty()) {
      if (warnings) warnings->push_back(walker.id + ": no usable trial, walker left out");
      continue;
    }
    walker.fit = averageFits(fits);
    walkers.push_back(std::move(walker));
  }
  return walkers;
}

Eigen::MatrixXd walkerMatrix(const std::vector<Walker>& walkers) {
  Eigen::MatrixXd w(kFourierDims3, static_cast<Eigen::Index>(walkers.size()));
  for (size_t r = 0; r < walkers.size(); ++r) {
    if (walkers[r].fit.w.size() != kFourierDims3)
      throw Error(ErrorKind::BadArgument, "", "",
                  "model: walker '" + walkers[r].id + "' is not a 3D fit (" +
                      std::to_string(walkers[r].fit.w.size()) + " values, 225 expected)");
    w.col(static_cast<Eigen::Index>(r)) = walkers[r].fit.w;
  }
  return w;
}

namespace {

struct WalkerColumns {
  std::vector<std::string> ids, subjects;
  Eigen::VectorXd omegas;
};

WalkerColumns walkerColumns(const std::vector<Walker>& walkers) {
  WalkerColumns c;
  c.omegas.resize(static_cast<Eigen::Index>(walkers.size()));
  for (size_t r = 0; r < walkers.size(); ++r) {
    c.ids.push_back(walkers[r].id);
    c.subjects.push_back(walkers[r].subject);
    c.omegas(static_cast<Eigen::Index>(r)) = walkers[r].fit.omegaRadS;
  }
  return c;
}

std::string provenanceLine(const Walker& w) {
  std::string line = w.id + " (" + w.source + "):";
  for (const auto& f : w.files) line += " " + f;
  return line;
}

void addProvenance(EigenwalkerModel& model, const std::vector<Walker>& walkers,
                   const std::string& heldOut) {
  for (const auto& w : walkers) {
    if (w.subject != heldOut) model.provenance.push_back(provenanceLine(w));
  }
}

}  // namespace

EigenwalkerModel buildModel(const std::vector<Walker>& walkers, const ModelOptions& options) {
  auto c = walkerColumns(walkers);
  auto model = buildModel(walkerMatrix(walkers), std::move(c.ids), std::move(c.subjects),
                          c.omegas, options);
  addProvenance(model, walkers, "");
  return model;
}

EigenwalkerModel buildModelWithoutSubject(const std::vector<Walker>& walkers,
                                          const std::string& subject,
                                          const ModelOptions& options) {
  const auto c = walkerColumns(walkers);
  auto model = buildModelWithoutSubject(walkerMatrix(walkers), c.ids, c.subjects, c.omegas,
                                        subject, options);
  addProvenance(model, walkers, subject);
  return model;
}

}  // namespace ew
