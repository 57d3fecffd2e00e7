#include "core/experiments/snippet_experiment.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>
#include <random>

#include "core/engines/request.h"
#include "core/common/errors.h"
#include "core/common/wall_time.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/engines/engine.h"
#include "core/experiments/gait_agreement.h"
#include "core/experiments/leave_one_out.h"
#include "core/snippet/snippet_data.h"

namespace ew {

namespace {

constexpr double kClipRateHz = 30.0;

const DatasetTrial* firstTrialOf(const Dataset& dataset, const std::string& subject) {
  for (const auto& t : dataset.trials)
    if (t.info.subject == subject) return &t;
  return nullptr;
}

struct SnippetFold {
  std::string subject;
  size_t index = 0;  // of the subject: its noise streams
  EigenwalkerEngine eigenwalker;
  SnippetEngine snippet;
};

// A clip seen at a known view, as every engine is given it (mm, 30 Hz), plus `noiseMm`
// (T × 30, the same for every engine; empty: none).
ViewInput knownView(const SnippetFold& fold, const Eigen::MatrixXd& frames, double alphaDeg, double strideHz,
                    const Eigen::MatrixXd& noiseMm = {}) {
  ViewInput in;
  in.uvMm = projectFramesToView(frames, alphaDeg);
  if (noiseMm.size() > 0) in.uvMm += noiseMm;
  in.rateHz = kClipRateHz;
  in.alphaDeg = alphaDeg;
  if (strideHz > 0) in.strideHzHint = strideHz;
  in.name = fold.subject;
  return in;
}

struct Clip {
  Eigen::MatrixXd withProgression, withoutProgression;  // T × 45 at 30 Hz
  double strideHz = 0.0;
  double speedMps = 0.0;  // the trial's progression (its gait's truth is measured with it)
};

Clip clipOf(const WalkingTrial& trial) {
  Clip c;
  c.withProgression = resampleFrames(framesWithProgression(trial), trial.joints.rateHz, kClipRateHz);
  c.withoutProgression = resampleFrames(trial.joints.positionsMm, trial.joints.rateHz, kClipRateHz);
  c.strideHz = trial.cycles.strideHz;
  c.speedMps = trial.speedMps;
  return c;
}

Clip middleOf(const Clip& clip, int frames) {
  const int start = std::max(0, static_cast<int>(clip.withProgression.rows() - frames) / 2);
  Clip c = clip;
  c.withProgression = clip.withProgression.middleRows(start, std::min<Eigen::Index>(frames, clip.withProgression.rows()));
  c.withoutProgression = clip.withoutProgression.middleRows(start, c.withProgression.rows());
  return c;
}

struct FoldOutput {
  std::vector<EngineRow> rows;
  std::vector<ThetaRow> theta;
  std::vector<std::string> warnings;
  std::vector<GaitAgreementRow> gait;
  // per engine, angle, bin: sum of per-frame errors and counts
  std::vector<std::tuple<std::string, double, int, double>> phaseSamples;
};

// What a clip's rows collect beyond MPJPE: per-frame errors for the phase bins, and the gait
// measures of the reconstruction beside the truth's (the whole held-out trial only).
struct ClipScoring {
  bool phase = false;
  bool gait = false;
  double truthSpeedMps = 0.0;  // the trial's progression
};

// One engine's row for a clip at one view: its frames scored, or the reason it gave none.
// `reconstruct` returns the engine's frames; `truth` is what they are scored against.
template <class Reconstruct>
EngineRow engineRow(const SnippetFold& fold, const std::string& engine, const std::string& clipName, double alpha,
                    double noiseMm, const Eigen::MatrixXd& truth, const Reconstruct& reconstruct, FoldOutput& out,
                    const ClipScoring& scoring) {
  const bool phase = scoring.phase && noiseMm == 0.0;
  EngineRow row{fold.subject, engine, clipName, alpha, noiseMm, static_cast<int>(truth.rows()), 0.0, 0.0, "", 0.0};
  const auto t0 = std::chrono::steady_clock::now();
  const auto elapsed = [&] { return secondsSince(t0); };
  try {
    const Eigen::MatrixXd frames = reconstruct();
    row.seconds = elapsed();
    const ClipErrors e = clipErrors(frames, truth, alpha);
    if (scoring.gait) {
      // The eigenwalker's walker is two harmonics in place: its stance feet are read as such.
      const GaitSideWalk reconstructed{std::nullopt, engine.starts_with("eigenwalker"), std::nullopt};
      for (auto& g : gaitAgreementRows(fold.subject, engine, alpha, truth, frames, kClipRateHz,
                                       {scoring.truthSpeedMps, false, std::nullopt}, reconstructed)) {
        g.noise = noiseMm;
        out.gait.push_back(std::move(g));
      }
    }
    row.mpjpeMm = e.mpjpeMm;
    row.depthErrorMm2 = e.depthErrorMm2;
    if (phase)
      for (Eigen::Index f = 0; f < e.perFrameMm.size(); ++f)
        out.phaseSamples.emplace_back(engine, alpha, static_cast<int>(f), e.perFrameMm(f));
  } catch (const Error& err) {
    row.error = err.what();
    row.seconds = elapsed();
  }
  return row;
}

// Every engine's view of the clip at each level: the same draw, whatever the engine.
Eigen::MatrixXd viewNoise(const SnippetFold& fold, const SnippetExperimentOptions& o, size_t angle, size_t level,
                          Eigen::Index frames) {
  const double sd = o.noiseMm[level];
  if (sd == 0.0) return {};
  std::mt19937_64 rng(cellSeed(o.noiseSeed, fold.index, angle, level));
  std::normal_distribution<double> normal(0.0, sd);
  Eigen::MatrixXd noise(frames, 2 * kJointCount);
  for (Eigen::Index i = 0; i < noise.size(); ++i) noise.data()[i] = normal(rng);
  return noise;
}

void scoreClip(const SnippetFold& fold, const Clip& clip, const std::string& clipName, const SnippetExperimentOptions& o,
               FoldOutput& out, const FourierFit* phaseFit) {
  const ClipScoring scoring{phaseFit != nullptr, clipName == "trial", clip.speedMps};
  for (size_t a = 0; a < o.anglesDeg.size(); ++a)
    for (size_t l = 0; l < o.noiseMm.size(); ++l) {
      const double alpha = o.anglesDeg[a], level = o.noiseMm[l];
      const Eigen::MatrixXd noise = viewNoise(fold, o, a, l, clip.withProgression.rows());
      // Each engine is given the image it is designed for: the snippet engine's prior was
      // learnt overground, the eigenwalker's model in place (the pelvis's image drift is
      // removed by the engine either way: tests/engines/test_engine.cpp).
      if (hasEngine(o.engines, EngineKind::Snippet))
        out.rows.push_back(engineRow(fold, "snippet MAP", clipName, alpha, level, clip.withProgression, [&] {
          return reconstruct(fold.snippet, {knownView(fold, clip.withProgression, alpha, clip.strideHz, noise)})
              .engine.framesMm;
        }, out, scoring));
      // The skeleton engine is given the walker's own bone lengths (the paper measures its
      // performer) and the frames in place: an orthographic view says nothing of depth, so
      // its walker never moves along the line of sight.
      if (hasEngine(o.engines, EngineKind::Skeleton))
        out.rows.push_back(engineRow(fold, "skeleton", clipName, alpha, level, clip.withoutProgression, [&] {
          SkeletonEngine skeleton;
          skeleton.bones = boneLengthsFromFrames(clip.withoutProgression, fold.subject);
          return reconstruct(skeleton, {knownView(fold, clip.withoutProgression, alpha, clip.strideHz, noise)})
              .engine.framesMm;
        }, out, scoring));
      if (hasEngine(o.engines, EngineKind::Eigenwalker))
        out.rows.push_back(engineRow(fold, "eigenwalker MAP", clipName, alpha, level, clip.withoutProgression, [&] {
          return reconstruct(fold.eigenwalker, {knownView(fold, clip.withoutProgression, alpha, clip.strideHz, noise)})
              .engine.framesMm;
        }, out, scoring));
    }
}

void unknownView(const SnippetFold& fold, const Clip& clip, const SnippetExperimentOptions& o, FoldOutput& out) {
  const int length = fold.snippet.prior->prior.frames;
  for (double alpha : o.unknownAnglesDeg) {
    ViewInput in = knownView(fold, clip.withProgression, alpha, clip.strideHz);
    in.alphaDeg.reset();
    try {
      const SnippetSequence seq = *reconstruct(fold.snippet, {in}).engine.snippet;
      for (size_t k = 0; k < seq.starts.size(); ++k) {
        const SnippetPlacement place = snippetPlacement(clip.withProgression, seq.starts[k], length);
        ThetaRow row;
        row.subject = fold.subject;
        row.angleDeg = alpha;
        row.snippet = static_cast<int>(k);
        row.trueDeg = wrapDeg(alpha - place.headingRad * 180.0 / std::numbers::pi);
        row.estimatedDeg = seq.freeAlphaDeg[k];
        row.errorDeg = std::abs(wrapDeg(row.estimatedDeg - row.trueDeg));
        row.clipEstimateDeg = seq.alphaDeg;
        out.theta.push_back(row);
      }
    } catch (const Error& err) {
      out.warnings.push_back("snippet: unknown view " + fold.subject + ": " + err.what());
    }
  }
}

}  // namespace

Eigen::MatrixXd framesWithProgression(const WalkingTrial& trial) {
  Eigen::MatrixXd frames = trial.joints.positionsMm;
  for (Eigen::Index f = 0; f < frames.rows(); ++f) {
    const double forward = trial.speedMps * 1000.0 * static_cast<double>(f) / trial.joints.rateHz;
    for (int j = 0; j < 15; ++j) frames(f, 3 * j + 1) += forward;
  }
  return frames;
}

std::vector<SnippetTrainingTrial> snippetTrainingTrials(const Dataset& dataset, const std::string& without) {
  std::vector<SnippetTrainingTrial> trials;
  for (const auto& t : dataset.trials) {
    if (t.info.subject == without) continue;
    trials.push_back({t.info.subject, t.info.file, framesWithProgression(t.trial), t.trial.joints.rateHz});
  }
  return trials;
}

SnippetExperimentResults snippetComparison(const Dataset& dataset, const std::vector<Walker>& walkers,
                                           const SnippetExperimentOptions& o) {
  const std::vector<std::string> subjects = dataset.subjects();
  if (subjects.size() < 3) throwBadData("snippet", "", "leave-one-subject-out needs at least 3 subjects");
  if (o.noiseMm.empty()) throw Error(ErrorKind::BadArgument, "snippet", "", "no noise level");
  for (double n : o.noiseMm)
    if (!(std::isfinite(n) && n >= 0.0))
      throw Error(ErrorKind::BadArgument, "snippet", "", "noise levels must be finite and >= 0");
  for (double a : o.anglesDeg)
    if (!std::isfinite(a)) throw Error(ErrorKind::BadArgument, "snippet", "", "view angles must be finite");
  std::vector<FoldOutput> outputs(subjects.size());
  std::vector<double> trainS(subjects.size(), 0.0);
  std::vector<int> snippets(subjects.size(), 0);
  parallelFor(static_cast<int>(subjects.size()), o.threads, [&](int i) {
    SnippetFold fold;
    fold.subject = subjects[static_cast<size_t>(i)];
    fold.index = static_cast<size_t>(i);
    if (hasEngine(o.engines, EngineKind::Snippet)) {
      const auto t0 = std::chrono::steady_clock::now();
      const SnippetPrior prior = trainSnippetPrior(snippetTrainingTrials(dataset, fold.subject), o.prior);
      trainS[static_cast<size_t>(i)] = secondsSince(t0);
      snippets[static_cast<size_t>(i)] = prior.trainingSnippets;
      fold.snippet = {std::make_shared<const PreparedSnippetPrior>(prepareSnippetPrior(prior)), o.sequence};
    }
    if (hasEngine(o.engines, EngineKind::Eigenwalker)) {
      fold.eigenwalker.model = buildModelWithoutSubject(walkers, fold.subject, o.model);
      fold.eigenwalker.estimator = {Estimator::Map, o.sigma2Mm2};
    }
    FoldOutput& out = outputs[static_cast<size_t>(i)];
    const DatasetTrial* trial = firstTrialOf(dataset, fold.subject);
    if (!trial) return;
    const Clip clip = clipOf(trial->trial);
    FourierFitOptions fo;
    fo.omegaHintRadS = 2.0 * std::numbers::pi * clip.strideHz;
    FourierFit phase3d;
    const FourierFit* phaseFit = nullptr;
    try {
      phase3d = fitFourier(clip.withoutProgression, kClipRateHz, fo);
      phaseFit = &phase3d;
    } catch (const Error& e) {
      out.warnings.push_back("snippet: " + fold.subject + ": no gait phase (" + e.what() + ")");
    }
    const size_t before = out.phaseSamples.size();
    scoreClip(fold, clip, "trial", o, out, phaseFit);
    if (phaseFit) {  // frame index → phase bin
      for (size_t k = before; k < out.phaseSamples.size(); ++k) {
        auto& [engine, alpha, frame, err] = out.phaseSamples[k];
        const double ph = std::fmod(phaseFit->omegaRadS * frame / kClipRateHz + phaseFit->phaseRad +
                                        8.0 * std::numbers::pi, 2.0 * std::numbers::pi);
        frame = std::min(o.phaseBins - 1, static_cast<int>(ph / (2.0 * std::numbers::pi) * o.phaseBins));
      }
    }
    if (!o.beyondTheTrial) return;
    const int shortFrames = static_cast<int>(std::lround(o.shortClipS * kClipRateHz)) + 1;
    FoldOutput shortOut;
    scoreClip(fold, middleOf(clip, shortFrames), "0.5 s", o, shortOut, nullptr);
    out.rows.insert(out.rows.end(), shortOut.rows.begin(), shortOut.rows.end());
    if (hasEngine(o.engines, EngineKind::Snippet)) unknownView(fold, clip, o, out);
    if (!o.wholeTrialSuffix.empty()) {
      for (const auto& t : dataset.trials) {
        const std::string& f = t.info.file;
        if (t.info.subject != fold.subject || f.size() < o.wholeTrialSuffix.size() ||
            f.compare(f.size() - o.wholeTrialSuffix.size(), o.wholeTrialSuffix.size(), o.wholeTrialSuffix) != 0)
          continue;
        PrepareOptions whole;
        whole.cropToSteadyWindow = false;
        FoldOutput wholeOut;
        scoreClip(fold, clipOf(loadWalkingTrial(f, {}, whole)), "whole trial", o, wholeOut, nullptr);
        out.rows.insert(out.rows.end(), wholeOut.rows.begin(), wholeOut.rows.end());
      }
    }
  });
  SnippetExperimentResults res;
  std::map<std::tuple<std::string, double, int>, std::pair<double, int>> bins;
  for (auto& out : outputs) {
    res.rows.insert(res.rows.end(), out.rows.begin(), out.rows.end());
    res.theta.insert(res.theta.end(), out.theta.begin(), out.theta.end());
    res.warnings.insert(res.warnings.end(), out.warnings.begin(), out.warnings.end());
    res.gait.insert(res.gait.end(), out.gait.begin(), out.gait.end());
    for (const auto& [engine, alpha, bin, err] : out.phaseSamples) {
      auto& b = bins[{engine, alpha, bin}];
      b.first += err;
      ++b.second;
    }
  }
  for (const auto& [key, value] : bins)
    res.phase.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), value.first / value.second, value.second});
  for (size_t i = 0; i < subjects.size(); ++i) {
    res.trainSecondsMean += trainS[i] / static_cast<double>(subjects.size());
    res.snippetsMean += snippets[i] / static_cast<int>(subjects.size());
  }
  return res;
}

std::vector<ClusterChoiceRow> chooseSnippetClusters(const Dataset& dataset, const std::vector<int>& clusters,
                                                    const SnippetPriorOptions& base, int emIterations,
                                                    int threads) {
  const std::vector<std::string> subjects = dataset.subjects();
  std::vector<ClusterChoiceRow> rows;
  for (int m : clusters) {
    std::vector<double> sum(subjects.size(), 0.0), sumEm(subjects.size(), 0.0);
    std::vector<int> count(subjects.size(), 0);
    parallelFor(static_cast<int>(subjects.size()), threads, [&](int i) {
      const std::string& s = subjects[static_cast<size_t>(i)];
      SnippetPriorOptions o = base;
      o.clusters = m;
      std::vector<SnippetTrainingTrial> held;
      for (const auto& t : snippetTrainingTrials(dataset))
        if (t.subject == s) held.push_back(t);
      const Eigen::MatrixXd test = cutTrainingSnippets(held, o.frames, o.hop, o.rateHz);
      if (test.cols() == 0) return;
      const auto train = snippetTrainingTrials(dataset, s);
      sum[static_cast<size_t>(i)] = meanLogDensity(trainSnippetPrior(train, o), test) * static_cast<double>(test.cols());
      o.emIterations = emIterations;
      sumEm[static_cast<size_t>(i)] = emIterations > 0
          ? meanLogDensity(trainSnippetPrior(train, o), test) * static_cast<double>(test.cols())
          : sum[static_cast<size_t>(i)];
      count[static_cast<size_t>(i)] = static_cast<int>(test.cols());
    });
    double total = 0.0, totalEm = 0.0;
    int n = 0;
    for (size_t i = 0; i < subjects.size(); ++i) { total += sum[i]; totalEm += sumEm[i]; n += count[i]; }
    rows.push_back({m, total / n, totalEm / n});
  }
  return rows;
}

}  // namespace ew
