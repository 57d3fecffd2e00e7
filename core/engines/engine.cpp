#include "core/engines/engine.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/common/statistics.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/joint_completion.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/walker_set.h"
#include "core/gait/canonical_frame.h"
#include "core/gait/missing_joints.h"

namespace ew {
namespace {

void checkInput(const ViewInput& input) {
  if (input.uvMm.cols() != 2 * kJointCount)
    throw Error(ErrorKind::BadArgument, input.name, "",
                "engine input: 2D frames need 30 columns (u, v of 15 joints), got " +
                    std::to_string(input.uvMm.cols()));
  if (!(input.rateHz > 0.0) || !std::isfinite(input.rateHz))
    throw Error(ErrorKind::BadArgument, input.name, "", "engine input: the frame rate must be positive and finite");
}

// RMS over the seen points of |projected − observed|, mm.
double reprojectionRms(const Eigen::MatrixXd& framesMm, double alphaDeg, const Eigen::MatrixXd& uvMm) {
  const Eigen::MatrixXd projected = projectFramesToView(framesMm, alphaDeg);
  double sum = 0.0;
  int points = 0;
  for (Eigen::Index f = 0; f < uvMm.rows(); ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const double u = uvMm(f, 2 * j), v = uvMm(f, 2 * j + 1);
      if (!std::isfinite(u) || !std::isfinite(v)) continue;
      sum += std::pow(projected(f, 2 * j) - u, 2) + std::pow(projected(f, 2 * j + 1) - v, 2);
      ++points;
    }
  }
  return points > 0 ? std::sqrt(sum / points) : 0.0;
}

EngineResult runEigenwalker(const EigenwalkerEngine& engine, const ViewInput& input) {
  EngineResult out;
  out.engine = EngineKind::Eigenwalker;
  const Eigen::MatrixXd uv = input.inPlace ? Eigen::MatrixXd(input.uvMm) : removeImageDrift(input.uvMm, input.rateHz);
  const JointMask missing = jointsMissingThroughout(uv);
  FourierFitOptions fitOptions;
  if (input.strideHzHint) fitOptions.omegaHintRadS = 2.0 * std::numbers::pi * *input.strideHzHint;
  fitOptions.file = input.name;
  EigenwalkerDiagnostics d;
  d.fit2d = fitFourierMeasured(uv, input.rateHz, missing, fitOptions);
  for (int j = 0; j < kJointCount; ++j)
    if (missing[static_cast<size_t>(j)]) d.missingJoints.push_back(j);
  const ModelGram gram = precomputeModelGram(engine.model, d.missingJoints);
  if (input.alphaDeg) {
    d.reconstruction = reconstructKnownView(gram, d.fit2d.w, *input.alphaDeg, engine.estimator);
  } else {
    d.search = searchViewAngle(gram, d.fit2d.w, engine.estimator, engine.search);
    d.reconstruction = d.search->best;
  }
  out.framesMm = synthesizeFrames(d.reconstruction.w, d.fit2d.omegaRadS, d.fit2d.phaseRad,
                                  frameTimes(static_cast<int>(uv.rows()), input.rateHz));
  out.alphaDeg = d.reconstruction.alphaDeg;
  out.alphaEstimated = !input.alphaDeg;
  out.reprojectionRmsMm = reprojectionRms(out.framesMm, out.alphaDeg, uv);
  out.warnings = d.fit2d.warnings;
  out.eigenwalker = std::move(d);
  return out;
}

EngineResult runSnippet(const SnippetEngine& engine, const ViewInput& input) {
  EngineResult out;
  out.engine = EngineKind::Snippet;
  SnippetSequenceOptions options = engine.sequence;
  options.fit.alphaDeg = input.alphaDeg;
  options.fit.scale = 1.0;  // the input is in mm at the walker
  SnippetSequence seq = [&] {
    try {
      return reconstructSnippetSequence(*engine.prior, input.uvMm, input.rateHz, options);
    } catch (const Error& e) {
      // The snippet code names its stage ("snippets") where a reader names the file: the
      // user needs to know which input.
      if (!input.name.empty() && e.file() == "snippets")
        throw Error(e.kind(), input.name, e.position(), "snippets: " + e.problem());
      throw;
    }
  }();
  out.framesMm = seq.framesMm;
  out.alphaDeg = seq.alphaDeg;
  out.alphaEstimated = !input.alphaDeg;
  out.reprojectionRmsMm = seq.reprojectionRms;
  out.snippet = std::move(seq);
  return out;
}

EngineResult runSkeleton(const SkeletonEngine& engine, const ViewInput& input) {
  EngineResult out;
  out.engine = EngineKind::Skeleton;
  const BoneLengths bones = engine.bones ? *engine.bones : estimateBoneLengthsFromView(input.uvMm, input.name);
  std::vector<JointRays> rays;
  std::vector<Eigen::Vector3d> roots;
  const int pelvis = index(Joint::Pelvis);
  for (Eigen::Index f = 0; f < input.uvMm.rows(); ++f) {
    rays.push_back(orthographicRays(input.uvMm.row(f)));
    roots.push_back(rays.back().origin.col(pelvis));
  }
  SkeletonSequence seq = [&] {
    try {
      return solveSkeletonSequence(rays, roots, bones, input.rateHz, engine.solve);
    } catch (const Error& e) {
      if (!input.name.empty() && e.file() == "skeleton")
        throw Error(e.kind(), input.name, e.position(), "skeleton: " + e.problem());
      throw;
    }
  }();
  out.alphaDeg = input.alphaDeg ? *input.alphaDeg : viewAngleFromPoses(seq.framesMm);
  out.alphaEstimated = !input.alphaDeg;
  out.framesMm = viewFrameToWalker(seq.framesMm, out.alphaDeg);
  out.reprojectionRmsMm = reprojectionRms(out.framesMm, out.alphaDeg, input.uvMm);
  if (seq.clampedBoneFrames > 0) {
    const auto worst = std::max_element(seq.clampedFrames.begin(), seq.clampedFrames.end()) - seq.clampedFrames.begin();
    const auto [a, b] = kBones[static_cast<size_t>(worst)];
    out.warnings.push_back("skeleton: " + std::to_string(seq.clampedBoneFrames) + " of " +
                           std::to_string(kBoneCount * input.uvMm.rows()) +
                           " bone-frames looked longer than their bone and were clamped (most: " +
                           std::string(jointName(a)) + "–" + std::string(jointName(b)) + ", " +
                           std::to_string(seq.clampedFrames[static_cast<size_t>(worst)]) + " frames)");
  }
  out.skeleton = std::move(seq);
  return out;
}

}  // namespace

BoneLengths estimateBoneLengthsFromView(const Eigen::Ref<const Eigen::MatrixXd>& uvMm, const std::string& name) {
  if (uvMm.cols() != kDims2)
    throw Error(ErrorKind::BadArgument, name, "", "bone lengths from a view need T × 30 frames");
  BoneLengths bones;
  for (int b = 0; b < kBoneCount; ++b) {
    const auto [a, c] = kBones[static_cast<size_t>(b)];
    std::vector<double> lengths;
    for (Eigen::Index f = 0; f < uvMm.rows(); ++f) {
      const double l = std::hypot(uvMm(f, 2 * index(a)) - uvMm(f, 2 * index(c)),
                                  uvMm(f, 2 * index(a) + 1) - uvMm(f, 2 * index(c) + 1));
      if (std::isfinite(l)) lengths.push_back(l);
    }
    if (lengths.empty())
      throw Error(ErrorKind::BadData, name, "",
                  "skeleton: the bone " + std::string(jointName(a)) + "–" + std::string(jointName(c)) +
                      " is never seen, so its length cannot be estimated from the view");
    bones.mm[static_cast<size_t>(b)] = percentile(std::move(lengths), 0.95);
  }
  for (int b = 0; b < kBoneCount; ++b) {  // left/right pairs: the larger for both
    const auto [a, c] = kBones[static_cast<size_t>(b)];
    for (int o = 0; o < kBoneCount; ++o) {
      const auto [ma, mc] = kBones[static_cast<size_t>(o)];
      if (o != b && ma == mirrorJoint(a) && mc == mirrorJoint(c))
        bones.mm[static_cast<size_t>(b)] = std::max(bones.mm[static_cast<size_t>(b)], bones.mm[static_cast<size_t>(o)]);
    }
  }
  return bones;
}

Eigen::MatrixXd viewFrameToWalker(const Eigen::Ref<const Eigen::MatrixXd>& viewFramesMm, double alphaDeg) {
  const double a = degToRad(alphaDeg), c = std::cos(a), s = std::sin(a);
  Eigen::MatrixXd out = viewFramesMm;
  for (Eigen::Index f = 0; f < out.rows(); ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const double u = viewFramesMm(f, 3 * j), d = viewFramesMm(f, 3 * j + 1);
      out(f, 3 * j) = u * c - d * s;
      out(f, 3 * j + 1) = u * s + d * c;
    }
  }
  return out;
}

double viewAngleFromPoses(const Eigen::Ref<const Eigen::MatrixXd>& viewFramesMm) {
  double sumSin = 0.0, sumCos = 0.0;
  const auto at = [&](Eigen::Index f, Joint j) {
    return Eigen::Vector3d(viewFramesMm.row(f).segment<3>(3 * index(j)).transpose());
  };
  for (Eigen::Index f = 0; f < viewFramesMm.rows(); ++f) {
    const Eigen::Vector3d up = at(f, Joint::Sternum) - at(f, Joint::Pelvis);
    const Eigen::Vector3d right = at(f, Joint::RHip) - at(f, Joint::LHip);
    const Eigen::Vector3d forward = up.cross(right);
    const double n = std::hypot(forward(0), forward(1));
    if (!(n > 0.0)) continue;
    sumSin += forward(0) / n;
    sumCos += forward(1) / n;
  }
  return std::atan2(sumSin, sumCos) * 180.0 / std::numbers::pi;
}

const char* engineName(EngineKind kind) {
  switch (kind) {
    case EngineKind::Eigenwalker: return "eigenwalker";
    case EngineKind::Snippet: return "snippet";
    case EngineKind::Skeleton: return "skeleton";
  }
  return "?";
}

EngineKind parseEngineKind(const std::string& name, const std::string& where) {
  std::string known;
  for (EngineKind k : kEngineKinds) {
    if (name == engineName(k)) return k;
    known += (known.empty() ? "" : ", ") + std::string(engineName(k));
  }
  throw Error(ErrorKind::BadArgument, where, "", "unknown engine '" + name + "' (known: " + known + ")");
}

EngineKind engineKind(const Engine& engine) {
  if (std::holds_alternative<EigenwalkerEngine>(engine)) return EngineKind::Eigenwalker;
  return std::holds_alternative<SnippetEngine>(engine) ? EngineKind::Snippet : EngineKind::Skeleton;
}

Eigen::MatrixXd removeImageDrift(const Eigen::Ref<const Eigen::MatrixXd>& uvMm, double rateHz) {
  Eigen::MatrixXd out = uvMm;
  const int pelvisU = 2 * static_cast<int>(Joint::Pelvis);
  double n = 0, st = 0, su = 0, stt = 0, stu = 0;
  for (Eigen::Index f = 0; f < uvMm.rows(); ++f) {
    const double u = uvMm(f, pelvisU);
    if (!std::isfinite(u)) continue;
    const double t = static_cast<double>(f) / rateHz;
    n += 1, st += t, su += u, stt += t * t, stu += t * u;
  }
  const double det = n * stt - st * st;
  if (n < 2 || !(det > 0.0)) return out;
  const double slope = (n * stu - st * su) / det;
  const double intercept = (su - slope * st) / n;
  for (Eigen::Index f = 0; f < out.rows(); ++f) {
    const double drift = intercept + slope * static_cast<double>(f) / rateHz;
    for (int j = 0; j < kJointCount; ++j) out(f, 2 * j) -= drift;
  }
  return out;
}

ClipErrors clipErrors(const Eigen::Ref<const Eigen::MatrixXd>& reconstructedMm,
                      const Eigen::Ref<const Eigen::MatrixXd>& truthMm, double alphaDeg) {
  if (reconstructedMm.rows() != truthMm.rows() || reconstructedMm.cols() != 3 * kJointCount ||
      truthMm.cols() != 3 * kJointCount || truthMm.rows() == 0)
    throw Error(ErrorKind::BadArgument, "", "", "clip errors: the reconstruction and the truth need the same T × 45 shape");
  const Eigen::MatrixXd diff = reconstructedMm - truthMm;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
  for (int j = 0; j < kJointCount; ++j)
    offset += diff.middleCols(3 * j, 3).colwise().mean().transpose() / static_cast<double>(kJointCount);
  const double a = degToRad(alphaDeg);
  ClipErrors e;
  e.perFrameMm = Eigen::VectorXd::Zero(diff.rows());
  double depth = 0.0;
  for (Eigen::Index f = 0; f < diff.rows(); ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const Eigen::Vector3d d = diff.block<1, 3>(f, 3 * j).transpose() - offset;
      e.perFrameMm(f) += d.norm() / static_cast<double>(kJointCount);
      const double alongSight = -d.x() * std::sin(a) + d.y() * std::cos(a);
      depth += alongSight * alongSight;
    }
  }
  e.mpjpeMm = e.perFrameMm.mean();
  e.depthErrorMm2 = depth / static_cast<double>(diff.rows() * kJointCount);
  return e;
}

EngineResult reconstructWithEngine(const Engine& engine, const ViewInput& input) {
  checkInput(input);
  if (const auto* e = std::get_if<EigenwalkerEngine>(&engine)) return runEigenwalker(*e, input);
  if (const auto* e = std::get_if<SkeletonEngine>(&engine)) return runSkeleton(*e, input);
  return runSnippet(std::get<SnippetEngine>(engine), input);
}

// [SECTION] Walkers known only as a Fourier vector

Eigen::MatrixXd overgroundFrames(const Eigen::Ref<const Eigen::VectorXd>& w, double omegaRadS, double speedMps,
                                 double cycles, double rateHz) {
  const auto finitePositive = [](double v) { return v > 0.0 && std::isfinite(v); };
  if (w.size() != kFourierDims3)
    throw Error(ErrorKind::BadArgument, "", "", "overground frames: w needs 225 values");
  if (!finitePositive(omegaRadS) || !finitePositive(cycles) || !finitePositive(rateHz) || !(speedMps >= 0.0) ||
      !std::isfinite(speedMps) || cycles * 2.0 * std::numbers::pi / omegaRadS * rateHz > 1e6)
    throw Error(ErrorKind::BadArgument, "", "", "overground frames: ω, cycles and rate must be positive and finite, "
                                                "the speed finite and not negative, and at most 10⁶ frames");
  const int count = static_cast<int>(std::ceil(cycles * 2.0 * std::numbers::pi / omegaRadS * rateHz));
  const Eigen::VectorXd t = frameTimes(count, rateHz);
  Eigen::MatrixXd frames = synthesizeFrames(w, omegaRadS, 0.0, t);
  for (int j = 0; j < kJointCount; ++j) frames.col(3 * j + 1) += 1000.0 * speedMps * t;
  return frames;
}

Eigen::VectorXd fourierSummary(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, double rateHz, double omegaRadS) {
  Eigen::MatrixXd inPlace = framesMm;
  removeProgression(inPlace, rateHz);
  FourierFitOptions o;
  o.omegaFixedRadS = omegaRadS;
  const FourierFit fit = fitFourier(inPlace, rateHz, o);
  return rephase(fit.w, fit.phaseRad, 0.0);
}

std::vector<FourierWalkerTrial> modelFourierWalkers(const EigenwalkerModel& model, const std::string& withoutSubject) {
  double known = 0.0;
  int counted = 0;
  for (const auto& v : model.speedsMps)
    if (v) known += *v, ++counted;
  const double fallback = counted > 0 ? known / counted : 1.3;
  const std::vector<Walker> stored = storedWalkers(model, "");
  std::vector<FourierWalkerTrial> walkers;
  for (int r = 0; r < model.walkerCount(); ++r) {
    const Walker& w = stored[static_cast<std::size_t>(r)];
    if (w.subject == withoutSubject) continue;
    walkers.push_back({w.subject, w.id, w.fit.w, w.fit.omegaRadS, model.speedMpsOf(r).value_or(fallback)});
  }
  return walkers;
}

std::vector<SnippetTrainingTrial> snippetTrialsFromFourier(const std::vector<FourierWalkerTrial>& walkers,
                                                           double cycles) {
  std::vector<SnippetTrainingTrial> trials;
  for (const auto& w : walkers)
    trials.push_back({w.subject, w.name, overgroundFrames(w.w, w.omegaRadS, w.speedMps, cycles, 30.0), 30.0});
  return trials;
}

}  // namespace ew
