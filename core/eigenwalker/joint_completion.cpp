#include "core/eigenwalker/joint_completion.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <numbers>

#include "core/common/errors.h"
#include "core/eigenwalker/reconstruction.h"

namespace ew {
namespace {

[[noreturn]] void completionError(ErrorKind kind, const std::string& problem) {
  throw Error(kind, "", "", "joint completion: " + problem);
}

// Indices into w (225) of the measured joints' entries: block-major, then joint, then x,y,z.
std::vector<Eigen::Index> measuredEntries(const JointMask& missing) {
  std::vector<Eigen::Index> rows;
  for (int block = 0; block < kFourierBlocks; ++block) {
    for (int j = 0; j < kJointCount; ++j) {
      if (missing[static_cast<size_t>(j)]) continue;
      for (int c = 0; c < 3; ++c) rows.push_back(block * kDims3 + 3 * j + c);
    }
  }
  return rows;
}

double sigma2For(const EigenwalkerModel& model, const CompletionOptions& options) {
  const double s2 = options.sigma2Mm2.value_or(defaultSigma2Mm2(model));
  if (!std::isfinite(s2) || s2 < 0.0)
    completionError(ErrorKind::BadArgument,
                    "σ² must be finite and ≥ 0, got " + std::to_string(s2) + " mm²");
  return s2;
}

// ĉ = (E_Oᵀ E_O + σ² Λ⁻¹)⁻¹ E_Oᵀ (w_O − w̄_O), by Cholesky (LDLT when not positive definite).
Eigen::VectorXd mapCoefficients(const EigenwalkerModel& model,
                                const Eigen::Ref<const Eigen::VectorXd>& w,
                                const std::vector<Eigen::Index>& rows, double sigma2) {
  const Eigen::Index n = model.componentCount();
  const auto m = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd eo(m, n);
  Eigen::VectorXd ro(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::Index r = rows[static_cast<size_t>(i)];
    eo.row(i) = model.eigenwalkers.row(r);
    ro(i) = w(r) - model.mean(r);
  }
  if (!ro.allFinite())
    completionError(ErrorKind::BadArgument, "the measured joints' coefficients are not finite");
  // λ floored as in precomputeModelGram: a zero eigenvalue must not divide.
  const double lambdaFloor = 1e-12 * std::max(model.eigenvalues.maxCoeff(), 1e-300);
  Eigen::MatrixXd g = eo.transpose() * eo;
  for (Eigen::Index i = 0; i < n; ++i)
    g(i, i) += sigma2 / std::max(model.eigenvalues(i), lambdaFloor);
  const Eigen::VectorXd b = eo.transpose() * ro;
  Eigen::LLT<Eigen::MatrixXd> llt(g);
  Eigen::VectorXd k = llt.info() == Eigen::Success ? Eigen::VectorXd(llt.solve(b))
                                                   : Eigen::VectorXd(g.ldlt().solve(b));
  if (!k.allFinite())
    completionError(ErrorKind::BadData, "the MAP solve gave non-finite coefficients");
  return k;
}

// Columns of the missing joints set to 0, so a fit of the frames sees only measured joints
// (3 columns per joint in 3D, 2 in 2D).
Eigen::MatrixXd measuredOnly(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                             const JointMask& missing) {
  Eigen::MatrixXd m = frames;
  const auto dims = static_cast<int>(frames.cols()) / kJointCount;
  for (int j = 0; j < kJointCount; ++j)
    if (missing[static_cast<size_t>(j)]) m.middleCols(dims * j, dims).setZero();
  return m;
}

}  // namespace

// [SECTION] Fit and completion

FourierFit fitFourierMeasured(const Eigen::Ref<const Eigen::MatrixXd>& frames, double rateHz,
                              const JointMask& missing, const FourierFitOptions& options) {
  if (frames.cols() != kDims3 && frames.cols() != kDims2)
    throw Error(ErrorKind::BadArgument, options.file, "",
                "Fourier fit: frames must have 45 (3D) or 30 (2D) columns, got " +
                    std::to_string(frames.cols()));
  // The phase reference z_l_ankle − z_r_ankle (METHOD §3) aligns the walker with the model's.
  JointMask ankles{};
  for (Joint j : {Joint::RAnkle, Joint::LAnkle})
    ankles[static_cast<size_t>(index(j))] = missing[static_cast<size_t>(index(j))];
  if (anyJoint(ankles))
    throwBadData(options.file, "",
                 "Fourier fit: too few joints measured to estimate the rest: " + jointList(ankles) +
                     " missing (the phase reference needs both ankles)");
  if (!anyJoint(missing)) return fitFourier(frames, rateHz, options);
  return fitFourier(measuredOnly(frames, missing), rateHz, options);
}

JointCompletion completeJoints(const EigenwalkerModel& model,
                               const Eigen::Ref<const Eigen::VectorXd>& w, const JointMask& missing,
                               const CompletionOptions& options) {
  checkModel(model, "joint completion");
  if (w.size() != kFourierDims3)
    completionError(ErrorKind::BadArgument,
                    "the walker must have 225 Fourier values, got " + std::to_string(w.size()));
  if (jointCount(missing) == kJointCount)
    completionError(ErrorKind::BadData, "every joint is missing: nothing to complete from");
  JointCompletion out;
  out.sigma2Mm2 = sigma2For(model, options);
  out.modelEstimated = missing;
  const std::vector<Eigen::Index> rows = measuredEntries(missing);
  if (!anyJoint(missing)) {
    if (!w.allFinite()) completionError(ErrorKind::BadArgument, "the walker is not finite");
    out.w = w;
    out.k = projectOntoModel(model, w);
    return out;
  }
  out.k = mapCoefficients(model, w, rows, out.sigma2Mm2);
  out.w = model.mean + model.eigenwalkers * out.k;  // ŵ_M = w̄_M + E_M ĉ …
  for (Eigen::Index r : rows) out.w(r) = w(r);      // … measured entries as measured
  return out;
}

CompletedTrial completeWalkingTrial(const WalkingTrial& trial, const EigenwalkerModel& model,
                                    const CompletionOptions& options) {
  const JointTrial& jt = trial.joints;
  FourierFitOptions fitOptions;
  fitOptions.file = jt.file;
  if (std::isfinite(trial.cycles.strideHz) && trial.cycles.strideHz > 0.0)
    fitOptions.omegaHintRadS = 2.0 * std::numbers::pi * trial.cycles.strideHz;
  CompletedTrial out;
  out.trial = trial;
  out.fit = fitFourierMeasured(jt.positionsMm, jt.rateHz, jt.missing, fitOptions);
  out.completion = completeJoints(model, out.fit.w, jt.missing, options);
  if (!anyJoint(jt.missing)) return out;
  out.fit.w = out.completion.w;
  const Eigen::MatrixXd synth =
      synthesizeFrames(out.completion.w, out.fit.omegaRadS, out.fit.phaseRad,
                       frameTimes(jt.frameCount(), jt.rateHz));
  for (int j = 0; j < kJointCount; ++j) {
    if (!jt.missing[static_cast<size_t>(j)]) continue;
    out.trial.joints.positionsMm.middleCols<3>(3 * j) = synth.middleCols<3>(3 * j);
    out.trial.modelEstimated[static_cast<size_t>(j)] = true;
  }
  out.trial.joints.warnings.push_back("joints estimated from the model (not measured): " +
                                      jointList(jt.missing));
  return out;
}

}  // namespace ew
