#pragma once
// Experiment "snippet" (issue 15): the snippet engine (Howe, Leventon & Freeman 1999;
// core/snippet) beside the eigenwalker, leave-one-subject-out, on the same 2D frames.
//
// Each held-out walker's first trial, resampled to 30 Hz, with its overground progression
// (the canonical frame's removed trend put back: speed × time along +y), is seen
// orthographically at each angle (mm, scale known):
//   snippet engine   the prior learnt from every trial of the other subjects, the clip cut
//                    into 11-frame snippets every 4 frames, MAP per snippet, stitched, depth
//                    slip removed by ground contact;
//   skeleton         (evaluate --engine skeleton) every frame from geometry alone with the
//                    walker's own bone lengths (core/skeleton, Zou et al. 2009);
//   eigenwalker MAP  the 2D Fourier fit of the same frames without progression (as the
//                    eigenwalker's experiments feed it) at the walker's ω, MAP at the known
//                    view with the fold's model, synthesised at every frame.
// Both are scored on every frame against the mocap frames after removing the clip's mean
// translation: MPJPE (mm) and E_a (mean squared depth error, mm²), and per phase bin of the
// gait cycle (phase from the walker's own 3D fit: ωt + φ).
// Beyond a cycle: 0.5 s clips cut from the middle of each held-out trial (the snippet engine
// reconstructs them; the eigenwalker's Fourier fit refuses them — its message is recorded),
// CMU 05_01's whole trial (speeding up and slowing down; `wholeTrial`), and an unknown view:
// every snippet's own α̂ against its true view (α minus the heading of its middle frame).

#include <cstdint>
#include <string>
#include <vector>

#include "core/eigenwalker/model.h"
#include "core/eigenwalker/walker_set.h"
#include "core/engines/engine.h"
#include "core/experiments/gait_agreement.h"
#include "core/gait/dataset.h"
#include "core/snippet/snippet_prior.h"
#include "core/snippet/snippet_sequence.h"

namespace ew {

struct SnippetExperimentOptions {
  std::vector<double> anglesDeg{0.0, 30.0, 60.0, 90.0};
  std::vector<double> unknownAnglesDeg{-60.0, -30.0, 0.0, 30.0, 60.0};
  SnippetPriorOptions prior;
  SnippetSequenceOptions sequence;
  ModelOptions model;
  double sigma2Mm2 = 1000.0;   // the eigenwalker's MAP σ² (the project's sweep optimum)
  double shortClipS = 0.5;
  int phaseBins = 20;
  std::string wholeTrialSuffix = "05_01.bvh";  // a trial loaded uncropped ("" = none)
  int threads = 1;
  // 2D noise levels (mm, Gaussian per coordinate): every engine is given the same noisy
  // frames at a level (one draw per walker, view and level from noiseSeed). The phase bins
  // are scored at level 0 only.
  std::vector<double> noiseMm{0.0};
  std::uint64_t noiseSeed = 20070501;
  // The clips beyond the held-out trial: 0.5 s, the whole trial, and the unknown view.
  bool beyondTheTrial = true;
  // The engines scored (evaluate --engine): these two by default; the unknown-view part is the
  // snippet engine's (the eigenwalker's is experiment unknown-view).
  std::vector<EngineKind> engines{EngineKind::Eigenwalker, EngineKind::Snippet};
};

struct EngineRow {
  std::string subject, engine, clip;  // clip: "trial", "0.5 s", "whole trial"
  double angleDeg = 0.0;
  double noiseMm = 0.0;
  int frames = 0;
  double mpjpeMm = 0.0, depthErrorMm2 = 0.0;
  std::string error;                   // why the engine gave no answer (empty: it did)
  double seconds = 0.0;                // the engine's wall time on this clip (answer or refusal)
};

struct PhaseRow {
  std::string engine;
  double angleDeg = 0.0;
  int bin = 0;                         // phase [bin, bin + 1) / bins of the cycle
  double mpjpeMm = 0.0;
  int frames = 0;
};

struct ThetaRow {
  std::string subject;
  double angleDeg = 0.0;
  int snippet = 0;
  double trueDeg = 0.0, estimatedDeg = 0.0, errorDeg = 0.0;  // error wrapped to [0, 180]
  double clipEstimateDeg = 0.0;       // the clip's α̂ (circular median)
};

struct SnippetExperimentResults {
  std::vector<EngineRow> rows;
  std::vector<PhaseRow> phase;
  std::vector<ThetaRow> theta;
  // The gait measures of each engine's reconstruction of the held-out trial beside the
  // motion capture's, per walker and view (gait_agreement.h).
  std::vector<GaitAgreementRow> gait;
  std::vector<std::string> warnings;
  double trainSecondsMean = 0.0;       // one fold's prior
  int snippetsMean = 0;                // training snippets per fold
};

SnippetExperimentResults snippetComparison(const Dataset& dataset, const std::vector<Walker>& walkers,
                                           const SnippetExperimentOptions& options);

// The prior's training trials from a dataset: every trial's canonical frames with its
// progression put back (speed × time along +y), subjects other than `without`.
std::vector<SnippetTrainingTrial> snippetTrainingTrials(const Dataset& dataset, const std::string& without = "");

// Frames with progression: canonical frames + speed·t along +y.
Eigen::MatrixXd framesWithProgression(const WalkingTrial& trial);

// Held-out likelihood per snippet for m clusters (LOSO over subjects): choosing m.
struct ClusterChoiceRow {
  int clusters = 0;
  double heldOutLogLikelihood = 0.0;   // mean over held-out snippets (nats per snippet)
  double emHeldOutLogLikelihood = 0.0; // the same after `emIterations` EM steps
};
std::vector<ClusterChoiceRow> chooseSnippetClusters(const Dataset& dataset, const std::vector<int>& clusters,
                                                    const SnippetPriorOptions& base, int emIterations,
                                                    int threads);

}  // namespace ew
