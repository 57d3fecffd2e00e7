#include "core/eigenwalker/model.h"

#include <algorithm>
#include <cmath>

#include "core/common/errors.h"
#include "core/common/thin_svd.h"
#include "core/eigenwalker/fourier.h"

namespace ew {
namespace {

[[noreturn]] void modelError(const std::string& problem) {
  throw Error(ErrorKind::BadArgument, "", "", "model: " + problem);
}

void checkInputs(const Eigen::Ref<const Eigen::MatrixXd>& w, const std::vector<std::string>& ids,
                 size_t subjects, const Eigen::Ref<const Eigen::VectorXd>& omegas,
                 const ModelOptions& options) {
  const auto r = static_cast<size_t>(w.cols());
  if (w.rows() != kFourierDims3)
    modelError("W must have 225 rows, got " + std::to_string(w.rows()));
  if (r < 2) modelError("a model needs at least 2 walkers, got " + std::to_string(r));
  if (ids.size() != r || subjects != r || static_cast<size_t>(omegas.size()) != r)
    modelError("walker ids, subjects and frequencies must have one entry per column of W (" +
               std::to_string(r) + "), got " + std::to_string(ids.size()) + ", " +
               std::to_string(subjects) + " and " + std::to_string(omegas.size()));
  for (size_t c = 0; c < r; ++c) {
    const auto col = static_cast<Eigen::Index>(c);
    if (!w.col(col).allFinite())
      modelError("walker '" + ids[c] + "' has non-finite Fourier coefficients");
    if (!(std::isfinite(omegas(col)) && omegas(col) > 0.0))
      modelError("walker '" + ids[c] + "' has a non-positive or non-finite stride frequency (" +
                 std::to_string(omegas(col)) + " rad/s)");
  }
  if (!options.components && !(options.varianceThreshold > 0.0 && options.varianceThreshold <= 1.0))
    modelError("the variance threshold must be in (0, 1], got " +
               std::to_string(options.varianceThreshold));
}

int chooseComponents(const Eigen::VectorXd& spectrum, const ModelOptions& options) {
  const int maxN = static_cast<int>(spectrum.size());
  if (options.components) {
    if (*options.components < 1)
      modelError("the model needs at least one component, got " +
                 std::to_string(*options.components));
    return std::min(*options.components, maxN);
  }
  const double total = spectrum.sum();
  if (total <= 0.0) return 1;  // identical walkers: keep one (zero-variance) direction
  double cumulative = 0.0;
  for (int n = 0; n < maxN; ++n) {
    cumulative += spectrum(n);
    if (cumulative >= options.varianceThreshold * total * (1.0 - 1e-12)) return n + 1;
  }
  return maxN;
}

// Each eigenvector's sign is arbitrary; fix it so its largest-magnitude entry is positive.
void fixSigns(Eigen::MatrixXd& e) {
  for (Eigen::Index n = 0; n < e.cols(); ++n) {
    Eigen::Index i = 0;
    e.col(n).cwiseAbs().maxCoeff(&i);
    if (e(i, n) < 0.0) e.col(n) = -e.col(n);
  }
}

}  // namespace

double EigenwalkerModel::explainedVariance() const {
  const double total = spectrum.sum();
  return total > 0.0 ? eigenvalues.sum() / total : 1.0;
}

Eigen::MatrixXd storedWalkerVectors(const EigenwalkerModel& model) {
  Eigen::MatrixXd w = model.eigenwalkers * model.coefficients;
  w.colwise() += model.mean;
  return w;
}

double defaultSigma2Mm2(const EigenwalkerModel& model) {
  return model.sigma2Optimum ? model.sigma2Optimum->sigma2Mm2 : kPaperSigma2Mm2;
}

std::string defaultSigma2Source(const EigenwalkerModel& model) {
  if (!model.sigma2Optimum) return "the paper's 70 mm2 (the model records no optimum of its own)";
  return "the optimum measured on the model's " + std::to_string(model.walkerCount()) +
         " walkers (leave-one-subject-out sweep)";
}

EigenwalkerModel leadingComponents(const EigenwalkerModel& model, int components) {
  const int n = std::clamp(components, 1, std::max(1, model.componentCount()));
  if (n >= model.componentCount()) return model;
  EigenwalkerModel m = model;
  m.eigenwalkers = model.eigenwalkers.leftCols(n);
  m.eigenvalues = model.eigenvalues.head(n);
  m.coefficients = model.coefficients.topRows(n);
  return m;
}

EigenwalkerModel buildModel(const Eigen::Ref<const Eigen::MatrixXd>& w,
                            std::vector<std::string> walkerIds, std::vector<std::string> subjects,
                            const Eigen::Ref<const Eigen::VectorXd>& omegasRadS,
                            const ModelOptions& options) {
  checkInputs(w, walkerIds, subjects.size(), omegasRadS, options);
  const Eigen::Index r = w.cols();
  EigenwalkerModel model;
  model.mean = w.rowwise().mean();
  const Eigen::MatrixXd x = w.colwise() - model.mean;
  // Thin SVD; Jacobi (QR-preconditioned for this tall matrix) for accuracy on the small
  // singular values that decide N.
  const ThinSvd svd = thinSvd(x);
  const Eigen::Index rank = std::min<Eigen::Index>(r - 1, svd.singularValues.size());
  model.spectrum = svd.singularValues.head(rank).array().square() / static_cast<double>(r - 1);
  const int n = chooseComponents(model.spectrum, options);
  model.eigenwalkers = svd.u.leftCols(n);
  fixSigns(model.eigenwalkers);
  model.eigenvalues = model.spectrum.head(n);
  model.coefficients = model.eigenwalkers.transpose() * x;
  model.walkerIds = std::move(walkerIds);
  model.subjects = std::move(subjects);
  model.omegasRadS = omegasRadS;
  return model;
}

EigenwalkerModel buildModelWithoutSubject(const Eigen::Ref<const Eigen::MatrixXd>& w,
                                          const std::vector<std::string>& walkerIds,
                                          const std::vector<std::string>& subjects,
                                          const Eigen::Ref<const Eigen::VectorXd>& omegasRadS,
                                          const std::string& heldOutSubject,
                                          const ModelOptions& options) {
  checkInputs(w, walkerIds, subjects.size(), omegasRadS, options);
  std::vector<Eigen::Index> keep;
  for (size_t i = 0; i < subjects.size(); ++i) {
    if (subjects[i] != heldOutSubject) keep.push_back(static_cast<Eigen::Index>(i));
  }
  if (keep.size() == subjects.size()) modelError("no walker of subject '" + heldOutSubject + "'");
  if (keep.size() < 2)
    modelError("leaving out subject '" + heldOutSubject + "' leaves " +
               std::to_string(keep.size()) + " walker(s); a model needs at least 2");
  Eigen::MatrixXd kept(w.rows(), static_cast<Eigen::Index>(keep.size()));
  Eigen::VectorXd keptOmegas(kept.cols());
  std::vector<std::string> keptIds, keptSubjects;
  for (Eigen::Index c = 0; c < kept.cols(); ++c) {
    const auto src = keep[static_cast<size_t>(c)];
    kept.col(c) = w.col(src);
    keptOmegas(c) = omegasRadS(src);
    keptIds.push_back(walkerIds[static_cast<size_t>(src)]);
    keptSubjects.push_back(subjects[static_cast<size_t>(src)]);
  }
  auto model = buildModel(kept, std::move(keptIds), std::move(keptSubjects), keptOmegas, options);
  model.provenance.push_back("leave-one-subject-out: without " + heldOutSubject);
  return model;
}

namespace {

// O(1): the shapes every use of a model relies on.
void checkModelShape(const EigenwalkerModel& model, const std::string& stage) {
  const Eigen::Index n = model.eigenwalkers.cols();
  if (model.mean.size() != kFourierDims3 || model.eigenwalkers.rows() != kFourierDims3 || n < 1 ||
      model.eigenvalues.size() != n)
    throw Error(ErrorKind::BadArgument, "", "",
                stage + ": the model is empty or inconsistent (mean " +
                    std::to_string(model.mean.size()) + ", eigenwalkers " +
                    std::to_string(model.eigenwalkers.rows()) + " x " + std::to_string(n) +
                    ", eigenvalues " + std::to_string(model.eigenvalues.size()) +
                    "; expected 225, 225 x N, N with N ≥ 1)");
}

}  // namespace

void checkModel(const EigenwalkerModel& model, const std::string& stage) {
  checkModelShape(model, stage);
  const auto bad = [&](const std::string& problem) {
    throw Error(ErrorKind::BadArgument, "", "", stage + ": " + problem);
  };
  if (!model.mean.allFinite() || !model.eigenwalkers.allFinite() || !model.eigenvalues.allFinite())
    bad("the model has non-finite values");
  if ((model.eigenvalues.array() < 0.0).any()) bad("the model has a negative eigenvalue");
}

Eigen::VectorXd synthesizeWalker(const EigenwalkerModel& model,
                                 const Eigen::Ref<const Eigen::VectorXd>& k) {
  checkModelShape(model, "model synthesis");
  if (k.size() != model.componentCount())
    modelError("coefficient count " + std::to_string(k.size()) +
               " differs from the model's N = " + std::to_string(model.componentCount()));
  if (!k.allFinite()) modelError("the coefficients k have non-finite values");
  return model.mean + model.eigenwalkers * k;
}

Eigen::VectorXd projectOntoModel(const EigenwalkerModel& model,
                                 const Eigen::Ref<const Eigen::VectorXd>& w) {
  checkModelShape(model, "model projection");
  if (w.size() != model.mean.size())
    modelError("walker vector must have 225 values, got " + std::to_string(w.size()));
  if (!w.allFinite()) modelError("the walker vector has non-finite values");
  return model.eigenwalkers.transpose() * (w - model.mean);
}

Eigen::MatrixXd synthesizeWalkerFrames(const EigenwalkerModel& model,
                                       const Eigen::Ref<const Eigen::VectorXd>& k, double omegaRadS,
                                       double phaseRad,
                                       const Eigen::Ref<const Eigen::VectorXd>& timesS) {
  return synthesizeFrames(synthesizeWalker(model, k), omegaRadS, phaseRad, timesS);
}

}  // namespace ew
