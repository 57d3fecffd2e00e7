#include "core/eigenwalker/metrics.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"

namespace ew {
namespace {

constexpr int kMaxMpjpeSamples = 100'000;  // 2 × 36 MB of synthesised frames

[[noreturn]] void metricsError(ErrorKind kind, const std::string& problem) {
  throw Error(kind, "", "", "error measures: " + problem);
}

void requireWalker(const Eigen::Ref<const Eigen::VectorXd>& w, const char* what) {
  if (w.size() != kFourierDims3)
    metricsError(ErrorKind::BadArgument,
                 std::string(what) + " must have 225 values, got " + std::to_string(w.size()));
  if (!w.allFinite())
    metricsError(ErrorKind::BadArgument, std::string(what) + " has non-finite values");
}

void requireRate(double rateHz) {
  if (!(rateHz > 0.0) || !std::isfinite(rateHz))
    metricsError(ErrorKind::BadArgument,
                 "frame rate must be positive and finite, got " + std::to_string(rateHz) + " Hz");
}

// Depth coefficients (75, block-major then joint) → per joint temporal variance over one
// cycle: ½(p1² + q1² + p2² + q2²).
Eigen::VectorXd cycleVariance(const Eigen::VectorXd& d) {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(kJointCount);
  for (int b = 1; b < kFourierBlocks; ++b)
    v += 0.5 * d.segment(b * kJointCount, kJointCount).array().square().matrix();
  return v;
}

// Per joint mean square over one cycle: p0² + variance.
Eigen::VectorXd cycleMeanSquare(const Eigen::VectorXd& d) {
  return d.head(kJointCount).array().square().matrix() + cycleVariance(d);
}

DepthErrors finish(Eigen::VectorXd absPerJoint, double sigmaM2) {
  DepthErrors e;
  e.absPerJoint = std::move(absPerJoint);
  e.absMean = e.absPerJoint.mean();
  e.sigmaM2Mm2 = sigmaM2;
  e.relPerJoint = sigmaM2 > 0.0 ? Eigen::VectorXd(e.absPerJoint / sigmaM2)
                                : Eigen::VectorXd::Constant(kJointCount, std::nan(""));
  e.relMean = e.relPerJoint.mean();
  return e;
}

// Complete rows of frames (T × 45) and their times.
struct CompleteFrames {
  Eigen::MatrixXd frames;
  Eigen::VectorXd times;
};

CompleteFrames completeFrames(const Eigen::Ref<const Eigen::MatrixXd>& frames, double rateHz) {
  if (frames.cols() != kDims3)
    metricsError(ErrorKind::BadArgument,
                 "frames must be T × 45, got " + std::to_string(frames.cols()) + " columns");
  requireRate(rateHz);
  std::vector<Eigen::Index> rows;
  for (Eigen::Index i = 0; i < frames.rows(); ++i) {
    if (frames.row(i).allFinite()) rows.push_back(i);
  }
  if (rows.empty())
    metricsError(ErrorKind::BadData,
                 "no complete frame to compare with (of " + std::to_string(frames.rows()) + ")");
  CompleteFrames out;
  out.frames.resize(static_cast<Eigen::Index>(rows.size()), kDims3);
  out.times.resize(out.frames.rows());
  for (Eigen::Index i = 0; i < out.frames.rows(); ++i) {
    out.frames.row(i) = frames.row(rows[static_cast<size_t>(i)]);
    out.times(i) = static_cast<double>(rows[static_cast<size_t>(i)]) / rateHz;
  }
  return out;
}

double meanJointDistance(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  double sum = 0.0;
  for (Eigen::Index t = 0; t < a.rows(); ++t) {
    for (int j = 0; j < kJointCount; ++j)
      sum += (a.row(t).segment<3>(3 * j) - b.row(t).segment<3>(3 * j)).norm();
  }
  return sum / static_cast<double>(a.rows() * kJointCount);
}

}  // namespace

double depthVarianceMm2(const Eigen::Ref<const Eigen::VectorXd>& wTrue, double alphaDeg) {
  requireWalker(wTrue, "true walker");
  return cycleVariance(depthAtView(wTrue, alphaDeg)).mean();
}

DepthErrors depthErrors(const Eigen::Ref<const Eigen::VectorXd>& wTrue,
                        const Eigen::Ref<const Eigen::VectorXd>& wRec, double alphaDeg) {
  requireWalker(wTrue, "true walker");
  requireWalker(wRec, "reconstruction");
  const Eigen::VectorXd dTrue = depthAtView(wTrue, alphaDeg);
  const Eigen::VectorXd delta = dTrue - depthAtView(wRec, alphaDeg);
  return finish(cycleMeanSquare(delta), cycleVariance(dTrue).mean());
}

DepthErrors depthErrorsFrames(const Eigen::Ref<const Eigen::MatrixXd>& framesTrue, double rateHz,
                              const Eigen::Ref<const Eigen::VectorXd>& wRec, double omegaRadS,
                              double phaseRad, double alphaDeg) {
  requireWalker(wRec, "reconstruction");
  const CompleteFrames cf = completeFrames(framesTrue, rateHz);
  // σ_m² is the frames' temporal depth variance: one frame has none (E_r would be 0 / 0).
  if (cf.frames.rows() < 2)
    metricsError(ErrorKind::BadData,
                 "depth errors against frames need at least 2 complete frames, got 1");
  const Eigen::MatrixXd dTrue = depthFramesAtView(cf.frames, alphaDeg);
  const Eigen::MatrixXd dRec =
      depthFramesAtView(synthesizeFrames(wRec, omegaRadS, phaseRad, cf.times), alphaDeg);
  const Eigen::VectorXd absPerJoint = (dTrue - dRec).array().square().colwise().mean().transpose();
  const Eigen::RowVectorXd mean = dTrue.colwise().mean();
  const double sigmaM2 = (dTrue.rowwise() - mean).array().square().colwise().mean().mean();
  return finish(absPerJoint, sigmaM2);
}

namespace {

// Both walkers over one cycle of ω = 1 rad/s at phase 0 (they share ω and φ, so any would
// do), `samples` frames each, after checking the inputs MPJPE needs.
std::pair<Eigen::MatrixXd, Eigen::MatrixXd> sampledCycles(
    const Eigen::Ref<const Eigen::VectorXd>& wTrue, const Eigen::Ref<const Eigen::VectorXd>& wRec,
    int samples) {
  requireWalker(wTrue, "true walker");
  requireWalker(wRec, "reconstruction");
  if (samples < 1 || samples > kMaxMpjpeSamples)
    metricsError(ErrorKind::BadArgument, "MPJPE needs 1 to " + std::to_string(kMaxMpjpeSamples) +
                                             " samples, got " + std::to_string(samples));
  const Eigen::VectorXd t =
      Eigen::VectorXd::LinSpaced(samples, 0.0, 2.0 * std::numbers::pi * (samples - 1) / samples);
  return {synthesizeFrames(wTrue, 1.0, 0.0, t), synthesizeFrames(wRec, 1.0, 0.0, t)};
}

}  // namespace

double mpjpe(const Eigen::Ref<const Eigen::VectorXd>& wTrue,
             const Eigen::Ref<const Eigen::VectorXd>& wRec, int samples) {
  const auto [a, b] = sampledCycles(wTrue, wRec, samples);
  return meanJointDistance(a, b);
}

Eigen::VectorXd mpjpePerJoint(const Eigen::Ref<const Eigen::VectorXd>& wTrue,
                              const Eigen::Ref<const Eigen::VectorXd>& wRec, int samples) {
  const auto [a, b] = sampledCycles(wTrue, wRec, samples);
  Eigen::VectorXd perJoint(kJointCount);
  for (int j = 0; j < kJointCount; ++j)
    perJoint(j) = (a.middleCols<3>(3 * j) - b.middleCols<3>(3 * j)).rowwise().norm().mean();
  return perJoint;
}

double meanOverJoints(const Eigen::Ref<const Eigen::VectorXd>& perJoint,
                      const std::array<bool, kJointCount>& joints) {
  if (perJoint.size() != kJointCount)
    metricsError(ErrorKind::BadArgument,
                 "per-joint errors need 15 values, got " + std::to_string(perJoint.size()));
  double sum = 0.0;
  int count = 0;
  for (int j = 0; j < kJointCount; ++j) {
    if (!joints[static_cast<size_t>(j)]) continue;
    sum += perJoint(j);
    ++count;
  }
  return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN();
}

double mpjpeFrames(const Eigen::Ref<const Eigen::MatrixXd>& framesTrue, double rateHz,
                   const Eigen::Ref<const Eigen::VectorXd>& wRec, double omegaRadS,
                   double phaseRad) {
  requireWalker(wRec, "reconstruction");
  const CompleteFrames cf = completeFrames(framesTrue, rateHz);
  return meanJointDistance(cf.frames, synthesizeFrames(wRec, omegaRadS, phaseRad, cf.times));
}

double viewAngleErrorDeg(double estimatedDeg, double trueDeg) {
  if (!std::isfinite(estimatedDeg) || !std::isfinite(trueDeg))
    metricsError(ErrorKind::BadArgument, "view angle error of non-finite angles (" +
                                             std::to_string(estimatedDeg) + "°, " +
                                             std::to_string(trueDeg) + "°)");
  return std::abs(wrapDeg(estimatedDeg - trueDeg));
}

double mpjpeWithoutTranslation(const Eigen::Ref<const Eigen::MatrixXd>& rec,
                               const Eigen::Ref<const Eigen::MatrixXd>& truth) {
  const Eigen::MatrixXd d = rec - truth;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int j = 0; j < kJointCount; ++j) mean += d.middleCols<3>(3 * j).colwise().mean().transpose();
  mean /= kJointCount;
  double sum = 0;
  for (Eigen::Index f = 0; f < d.rows(); ++f)
    for (int j = 0; j < kJointCount; ++j)
      sum += (d.block<1, 3>(f, 3 * j).transpose() - mean).norm();
  return sum / static_cast<double>(d.rows() * kJointCount);
}

}  // namespace ew
