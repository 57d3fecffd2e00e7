#include "core/engine/model.h"

#include <Eigen/SVD>
#include <algorithm>

#include "core/common/errors.h"
#include "core/engine/fourier.h"

namespace ew {
namespace {

void checkInputs(const Eigen::Ref<const Eigen::MatrixXd>& w, size_t ids, size_t subjects,
                 Eigen::Index omegas) {
  const auto r = static_cast<size_t>(w.cols());
  if (w.rows() != kFourierDims3)
    throw Error(ErrorKind::BadArgument, "", "", "W must have 225 rows, got " + std::to_string(w.rows()));
  if (r < 2) throw Error(ErrorKind::BadArgument, "", "", "a model needs at least 2 walkers");
  if (ids != r || subjects != r || static_cast<size_t>(omegas) != r)
    throw Error(ErrorKind::BadArgument, "", "",
                "walker ids, subjects and frequencies must have one entry per column of W");
  if (!w.allFinite()) throw Error(ErrorKind::BadArgument, "", "", "W has non-finite values");
}

int chooseComponents(const Eigen::VectorXd& spectrum, const ModelOptions& options) {
  const int maxN = static_cast<int>(spectrum.size());
  if (options.components) {
    if (*options.components < 1)
      throw Error(ErrorKind::BadArgument, "", "", "the model needs at least one component");
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

EigenwalkerModel buildModel(const Eigen::Ref<const Eigen::MatrixXd>& w,
                            std::vector<std::string> walkerIds, std::vector<std::string> subjects,
                            const Eigen::Ref<const Eigen::VectorXd>& omegasRadS,
                            const ModelOptions& options) {
  checkInputs(w, walkerIds.size(), subjects.size(), omegasRadS.size());
  const Eigen::Index r = w.cols();
  EigenwalkerModel model;
  model.mean = w.rowwise().mean();
  const Eigen::MatrixXd x = w.colwise() - model.mean;
  // Thin SVD; Jacobi (QR-preconditioned for this tall matrix) for accuracy on the small
  // singular values that decide N.
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(x, Eigen::ComputeThinU);
  const Eigen::Index rank = std::min<Eigen::Index>(r - 1, svd.singularValues().size());
  model.spectrum = svd.singularValues().head(rank).array().square() / static_cast<double>(r - 1);
  const int n = chooseComponents(model.spectrum, options);
  model.eigenwalkers = svd.matrixU().leftCols(n);
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
  checkInputs(w, walkerIds.size(), subjects.size(), omegasRadS.size());
  std::vector<Eigen::Index> keep;
  for (size_t i = 0; i < subjects.size(); ++i) {
    if (subjects[i] != heldOutSubject) keep.push_back(static_cast<Eigen::Index>(i));
  }
  if (keep.size() == subjects.size())
    throw Error(ErrorKind::BadArgument, "", "", "no walker of subject '" + heldOutSubject + "'");
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

Eigen::VectorXd synthesizeWalker(const EigenwalkerModel& model,
                                 const Eigen::Ref<const Eigen::VectorXd>& k) {
  if (k.size() != model.componentCount())
    throw Error(ErrorKind::BadArgument, "", "", "coefficient count differs from the model's N");
  return model.mean + model.eigenwalkers * k;
}

Eigen::VectorXd projectOntoModel(const EigenwalkerModel& model,
                                 const Eigen::Ref<const Eigen::VectorXd>& w) {
  if (w.size() != model.mean.size())
    throw Error(ErrorKind::BadArgument, "", "", "walker vector must have 225 values");
  return model.eigenwalkers.transpose() * (w - model.mean);
}

Eigen::MatrixXd synthesizeWalkerFrames(const EigenwalkerModel& model,
                                       const Eigen::Ref<const Eigen::VectorXd>& k, double omegaRadS,
                                       double phaseRad,
                                       const Eigen::Ref<const Eigen::VectorXd>& timesS) {
  return synthesizeFrames(synthesizeWalker(model, k), omegaRadS, phaseRad, timesS);
}

}  // namespace ew
