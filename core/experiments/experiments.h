#pragma once
// The Zhang & Troje (2007) evaluation and the project's extensions (METHOD §7–8), as free
// functions over plain rows: the CLI writes them as CSV, the viewer can plot them.
//
// Protocol: leave-one-subject-out (leave_one_out.h); the held-out walker's own 3D Fourier
// vector w is projected at α (METHOD §5), reconstructed (METHOD §6) and scored against w
// (METHOD §7: E_a in closed form over one cycle, E_r, σ_m², MPJPE over one cycle).

#include <cstdint>
#include <functional>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "core/experiments/camera_experiment.h"
#include "core/experiments/engines_experiment.h"
#include "core/experiments/leave_one_out.h"
#include "core/experiments/lower_body.h"
#include "core/experiments/semantic_experiment.h"
#include "core/experiments/snippet_experiment.h"

namespace ew {

enum class Experiment {
  Variance, SigmaSweep, KnownView, UnknownView, Noise, MissingJoints, LowerBody, Camera,
  Snippet,          // snippet engine beside the eigenwalker (snippet_experiment.h); by name only
  SnippetClusters,  // the snippet prior's cluster count by held-out likelihood; by name only
  Engines,          // the three engines on the same views, noise and cameras (engines_experiment.h)
  Semantic,         // semantic axes of the walkers' attributes (semantic_experiment.h); by name only
  CameraWide,       // the camera experiment's factors one at a time (camera_experiment.h); by name only
};

std::string experimentName(Experiment e);  // "variance", "sigma-sweep", …
std::optional<Experiment> experimentFromName(const std::string& name);
// Every experiment "all" runs, in the order they run (a reference to one constant list).
// "camera" (camera_experiment.h) is asked for by name only: it writes and reads a keypoint
// folder per clip and takes minutes.
const std::vector<Experiment>& allExperiments();

// METHOD §8.2: the σ² grid (mm²).
std::vector<double> defaultSigma2GridMm2();

// A set of 2D joints hidden from the reconstruction (their rows of Ê dropped).
struct JointSet {
  std::string name;         // "r_wrist", "both_wrists", …
  std::vector<int> joints;  // METHOD §1 indices
};
// Every single joint, then groups: both wrists, both arms (elbows + wrists), both ankles,
// both lower legs (knees + ankles).
std::vector<JointSet> defaultMissingJointSets();

// (done, total, what): called after each fold of each experiment, serialised.
using ExperimentProgressFn = std::function<void(int, int, const std::string&)>;

struct EvaluationOptions {
  std::vector<double> anglesDeg;        // view angles; empty = −90…90 step 1 (METHOD §8)
  bool lsq = true;
  bool map = true;
  std::optional<double> sigma2Mm2;      // MAP σ²; unset = the sweep's optimum
  std::vector<double> sigma2GridMm2 = defaultSigma2GridMm2();
  std::vector<double> noiseLevelsMm = {0.0, 5.0, 10.0, 20.0, 40.0};
  std::uint64_t noiseSeed = 20070501;
  std::vector<JointSet> missingJointSets = defaultMissingJointSets();
  ModelOptions model;                   // N per fold (default 95 %, ≤ R − 2 in LOO)
  // Experiment "camera": the other engines scored beside the eigenwalker (camera_experiment.h).
  bool cameraSkeleton = true, cameraSnippet = true;
  // Its simulated detector's hips and whether the reader allows for the layout's offsets
  // (CameraExperimentOptions::detectorHipOffsetMm, allowForDetectorOffsets).
  std::optional<double> cameraDetectorHipOffsetMm;
  bool cameraAllowForDetectorOffsets = true;
  // Experiment "camera-wide": the factors to run (cameraWideConditions; empty: all) and the
  // cameras per held-out walker (unset: the camera experiment's 3).
  std::vector<std::string> cameraWideFactors;
  std::optional<int> cameraWideCameras;
  std::optional<std::filesystem::path> keepClipsDir;  // experiment "camera": each clip kept there
  int threads = 1;
  ExperimentProgressFn progress;
};

// [SECTION] Rows (one CSV line each)

struct HarmonicsRow {
  std::string walker, subject, source;
  double strideHz = 0, h1Share = 0, h2Share = 0, residualShare = 0;
};

struct VarianceRow {
  int component = 0;  // 1-based
  double eigenvalueMm2 = 0, varianceShare = 0, cumulativeShare = 0;
};

struct SigmaSweepRow {
  double sigma2Mm2 = 0;
  std::string method;  // "map"; "lsq" rows repeat the σ²-independent LSQ error as reference
  double meanAbsErrorMm2 = 0, meanRelError = 0, mpjpeMm = 0;
};

// Known view, 2D noise and missing joints: one row per subject × condition × angle × method.
struct ViewErrorRow {
  std::string subject;
  std::string condition;  // noise: the noise level (mm); missing joints: the set's name
  double angleDeg = 0;
  std::string method;     // "lsq" or "map"
  double absErrorMm2 = 0, relError = 0, varMissingMm2 = 0, mpjpeMm = 0;
};

struct UnknownViewRow {
  std::string subject;
  double trueAngleDeg = 0;
  std::string method;
  double estAngleDeg = 0, angleErrorDeg = 0, absErrorMm2 = 0, mpjpeMm = 0;
};

struct EvaluationResults {
  int walkers = 0, subjects = 0;
  int components = 0;             // N of the model of all walkers
  int components95 = 0;           // smallest N with ≥ 95 % cumulative variance (all walkers)
  std::set<Experiment> ran;
  std::vector<HarmonicsRow> harmonics;
  std::vector<VarianceRow> variance;
  std::vector<SigmaSweepRow> sigmaSweep;
  std::optional<double> sigma2OptMm2;   // the sweep's optimum (mean E_a over subjects, angles)
  bool sigma2OptAtGridEdge = false;
  double sigma2UsedMm2 = 0;             // σ² of every other MAP result
  std::vector<ViewErrorRow> knownView, noise, missingJoints;
  std::vector<UnknownViewRow> unknownView;
  std::vector<LowerBodyRow> lowerBody;  // experiment "lower-body" (lower_body.h)
  std::vector<CameraRow> camera;        // experiment "camera" (camera_experiment.h)
  std::vector<CameraWideRow> cameraWide;  // experiment "camera-wide" (camera_experiment.h)
  // Experiments "snippet" and "snippet-clusters" (snippet_experiment.h): they need the
  // dataset's trials, so the caller runs them (snippetComparison, chooseSnippetClusters).
  SnippetExperimentResults snippet;
  std::vector<ClusterChoiceRow> snippetClusters;
  EnginesExperimentResults engines;     // experiment "engines": the caller runs it too
  SemanticExperimentResults semantic;   // experiment "semantic": the caller runs it too
  std::vector<std::pair<std::string, double>> timingsS;  // per experiment, wall seconds
  std::vector<std::string> warnings;
};

// [SECTION] Experiments (each over the same folds)
//
// Preconditions, Error(BadArgument) "STAGE: …" (stage: "σ² sweep", "known view", …):
// finite view angles, σ² finite and ≥ 0, folds whose test walkers index `walkers` (folds
// of another walker list are refused, not read past the end); the sweep needs folds and a
// non-empty grid of positive, finite σ²; noise levels finite and ≥ 0; missing-joint sets
// with indices 0…14 that do not hide every joint.

std::vector<HarmonicsRow> harmonicsTable(const std::vector<ExperimentWalker>& walkers);
// One row per eigenvalue of the whole spectrum (R − 1 rows).
std::vector<VarianceRow> varianceTable(const EigenwalkerModel& model);
int componentsForShare(const std::vector<VarianceRow>& variance, double share);

std::vector<SigmaSweepRow> sigmaSweep(const std::vector<ExperimentWalker>& walkers,
                                      const std::vector<Fold>& folds,
                                      const EvaluationOptions& options);
std::vector<ViewErrorRow> knownViewErrors(const std::vector<ExperimentWalker>& walkers,
                                          const std::vector<Fold>& folds,
                                          const EvaluationOptions& options, double sigma2Mm2);
std::vector<UnknownViewRow> unknownViewErrors(const std::vector<ExperimentWalker>& walkers,
                                              const std::vector<Fold>& folds,
                                              const EvaluationOptions& options, double sigma2Mm2);
// Noise and missing joints use the multiples of 10° of a grid of more than 19 angles.
// Frames of the held-out walker projected at α, Gaussian noise (SD noise_mm per image
// coordinate and frame) added, the 2D Fourier fit at the walker's ω, reconstructed and
// scored against the 3D fit of the same frames at the same ω. Walkers without frames, or
// whose frames cannot be fitted at their ω, are skipped (a warning). `warnings` receives
// per-cell fit failures.
std::vector<ViewErrorRow> noiseErrors(const std::vector<ExperimentWalker>& walkers,
                                      const std::vector<Fold>& folds,
                                      const EvaluationOptions& options, double sigma2Mm2,
                                      std::vector<std::string>& warnings);
std::vector<ViewErrorRow> missingJointErrors(const std::vector<ExperimentWalker>& walkers,
                                             const std::vector<Fold>& folds,
                                             const EvaluationOptions& options, double sigma2Mm2);

// Runs the chosen experiments (folds built once) and times each. Fewer than 2 walkers →
// Error(BadData) "evaluation: …"; no method, a non-finite angle or σ² → Error(BadArgument).
EvaluationResults runEvaluation(const std::vector<ExperimentWalker>& walkers,
                                const std::set<Experiment>& experiments,
                                const EvaluationOptions& options);

// Angles "a:b:step" (degrees, inclusive) or a comma list "0,30,90". Throws
// Error(BadArgument) on a malformed spec, a non-positive step or more than 10 000 angles.
std::vector<double> parseAngleSpec(const std::string& spec);

}  // namespace ew
