#pragma once
// Experiment "engines" (issue 17): the three engines on the same held-out walkers, the same
// views, the same noise and the same random cameras, in one table — which engine to trust
// for which data, and at what cost.
//
// Two settings, leave-one-subject-out over the dataset's subjects:
//   view    each held-out walker's first trial at 30 Hz seen orthographically at each known
//           view, with Gaussian 2D noise per level (mm; one draw per walker, view and level,
//           the same for every engine): experiment "snippet"'s protocol and scoring
//           (snippet_experiment.h) without its extra clips. MPJPE over every frame after
//           removing the clip's mean translation, and E_a (mean squared depth error).
//   camera  each held-out walker's Fourier walker filmed by random pinhole cameras, written
//           as OpenPose JSON, read back and reconstructed by every engine: experiment
//           "camera"'s protocol (camera_experiment.h). The eigenwalker knows nothing of the
//           camera; the skeleton and snippet engines are given it (they estimate none), and
//           the skeleton engine's bone lengths come from four sources (variants).
// Each row carries the engine's wall time on the clip; each reconstruction's gait measures
// are compared with the walker's own (gait_agreement.h) per setting, view and noise level.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/engines/engine.h"
#include "core/experiments/camera_experiment.h"
#include "core/experiments/gait_agreement.h"
#include "core/experiments/leave_one_out.h"
#include "core/experiments/snippet_experiment.h"
#include "core/gait/dataset.h"

namespace ew {

struct EnginesExperimentOptions {
  std::vector<double> anglesDeg{0.0, 30.0, 60.0, 90.0};
  std::vector<double> noiseMm{0.0, 10.0, 20.0};  // setting "view"
  std::vector<double> noisePx{0.0, 2.0, 5.0};    // setting "camera"
  int camerasPerWalker = 3;
  bool views = true, cameras = true;              // which settings run
  std::vector<EngineKind> engines{EngineKind::Eigenwalker, EngineKind::Snippet, EngineKind::Skeleton};
  double sigma2Mm2 = 1000.0;  // the eigenwalker's MAP σ² (the project's sweep optimum)
  ModelOptions model;
  SnippetPriorOptions prior;
  int threads = 1;
  std::optional<std::filesystem::path> keepClipsDir;  // setting "camera": CameraExperimentOptions's
};

struct EnginesRow {
  std::string setting;          // "view" or "camera"
  std::string subject, engine;  // engine: eigenwalker, snippet or skeleton
  std::string variant;          // how the engine was run ("MAP, known view", "own bones", …)
  double angleDeg = 0.0;        // the view, or the camera's azimuth
  int camera = -1;              // setting "camera": the walker's camera 0, 1, …
  double noise = 0.0;
  std::string noiseUnit;        // "mm" (view) or "px" (camera)
  int frames = 0;
  double mpjpeMm = 0.0;         // NaN when the engine gave no answer
  double depthErrorMm2 = 0.0;   // E_a; NaN in setting "camera"
  double seconds = 0.0;
  std::string error;            // why the engine gave no answer (empty: it did)
};

struct EnginesExperimentResults {
  std::vector<EnginesRow> rows;
  std::vector<GaitAgreementRow> gait;
  std::vector<std::string> warnings;
};

// Error(BadArgument) "engines: …" for no engine, no setting, no view or noise level, a
// non-finite angle, a negative or non-finite noise; Error(BadData) for fewer than 3 subjects.
// `folds` must be buildFolds(walkers, options.model, …) of `walkers`, which must be
// experimentWalkers of `dataset`.
EnginesExperimentResults compareEngines(const Dataset& dataset, const std::vector<Walker>& datasetWalkers,
                                        const std::vector<ExperimentWalker>& walkers, const std::vector<Fold>& folds,
                                        const EnginesExperimentOptions& options);

// Per setting, engine, variant and noise level, over the clips (every view or camera).
struct EnginesSummaryRow {
  std::string setting, engine, variant;
  double noise = 0.0;
  std::string noiseUnit;
  int clips = 0, failures = 0;
  double meanMpjpeMm = 0.0, medianMpjpeMm = 0.0;  // over the clips answered (NaN: none)
  double meanSeconds = 0.0;                        // per clip, answered or refused
  double msPerFrame = 0.0;                         // total time / total frames
};
std::vector<EnginesSummaryRow> summarizeEngines(const std::vector<EnginesRow>& rows);

}  // namespace ew
