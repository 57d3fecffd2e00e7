#pragma once
// One interface over the reconstruction engines (STYLE §17): each takes the same input — a
// 2D sequence and what is known of the orthographic view — and gives the same output — the
// 3D walker at every input frame, the view angle, and how well the result reprojects —
// plus its own diagnostics. The GUI, the CLI and the experiments pick an engine by name.
//
//   eigenwalker  core/eigenwalker/   Zhang & Troje 2007: the 2D Fourier fit of the whole clip
//                                (at least one gait cycle), MAP or LSQ coefficients of the
//                                eigenwalker model at the known view or over the circle
//   snippet      core/snippet/  Howe, Leventon & Freeman 1999: overlapping 11-frame
//                                snippets, MAP under a mixture-of-PPCA prior, stitched
//   skeleton     core/skeleton/ Zou et al. 2009: every frame from geometry alone — each
//                                joint on its ray, every bone its length, depth-first from
//                                the pelvis; each bone's two depths chosen by the most
//                                plausible pose and by continuity (skeleton_solve.h)
//
// Input: u, v in mm at the walker (v up), as METHOD §5's orthographic view C(α) renders the
// walker's frame. The image may show the walker moving across it (overground) or walking
// in place; the eigenwalker removes the pelvis's straight-line image drift before its
// Fourier fit (a no-op for a view of METHOD §2's canonical frames, whose pelvis has no trend),
// the snippet engine keeps it (its prior was learnt with the progression); the skeleton
// engine places each frame's pelvis where the image shows it, at depth 0 (an orthographic
// view says nothing of depth: its walker never moves along the line of sight).
// Output frames are in the walker's frame (x right, y forward, z up; mm): the eigenwalker's
// walk in place (canonical frame), the snippet engine's with whatever progression the image
// and its prior imply. Compare them after removing each clip's mean translation or the
// pelvis's trend (metrics.h, removeProgression).

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <algorithm>
#include <vector>

#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/snippet/snippet_data.h"
#include "core/snippet/snippet_fit.h"
#include "core/skeleton/skeleton_solve.h"
#include "core/snippet/snippet_sequence.h"

namespace ew {

enum class EngineKind { Eigenwalker, Snippet, Skeleton };

inline constexpr EngineKind kEngineKinds[] = {EngineKind::Eigenwalker, EngineKind::Snippet, EngineKind::Skeleton};

// "eigenwalker", "snippet", "skeleton": the names the CLI's --engine and the viewer use.
const char* engineName(EngineKind kind);
// Throws Error(BadArgument) naming `where` (e.g. "--engine") and the known names.
EngineKind parseEngineKind(const std::string& name, const std::string& where);
// Whether `kind` is among `engines` (an experiment's or a comparison's engines asked for).
inline bool hasEngine(const std::vector<EngineKind>& engines, EngineKind kind) {
  return std::find(engines.begin(), engines.end(), kind) != engines.end();
}

struct EigenwalkerEngine {
  EigenwalkerModel model;
  EstimatorOptions estimator{Estimator::Map, 1000.0};
  ViewSearchOptions search;
};

// The prior is shared, not copied: the viewer reconstructs again on every change of α with
// the same prior (several MB with its factors).
struct SnippetEngine {
  std::shared_ptr<const PreparedSnippetPrior> prior;
  SnippetSequenceOptions sequence;
};

// Needs no training. The bone lengths are the walker's own when known (the paper measures
// the performer); unset, each is estimated from the view itself (estimateBoneLengthsFromView).
struct SkeletonEngine {
  std::optional<BoneLengths> bones;
  SkeletonSolveOptions solve;
};

using Engine = std::variant<EigenwalkerEngine, SnippetEngine, SkeletonEngine>;

EngineKind engineKind(const Engine& engine);

struct ViewInput {
  Eigen::MatrixXd uvMm;                 // T × 30: u, v per joint (METHOD §1 order), NaN = not seen
  double rateHz = 0.0;
  std::optional<double> alphaDeg;       // the known view; unset: each engine finds it
  std::optional<double> strideHzHint;   // e.g. from gait events (the eigenwalker's ω scan)
  // A view of a walk in place (METHOD §2's canonical frames, a treadmill): the eigenwalker
  // leaves the pelvis's image drift alone. Over a fraction of a cycle the least-squares line
  // through a periodic pelvis has a small slope, which removing would take from the walk.
  bool inPlace = false;
  std::string name;                     // names the input in errors and warnings
};

// The eigenwalker's own results, for the panels and reports that show them.
struct EigenwalkerDiagnostics {
  FourierFit fit2d;                     // the 2D Fourier fit of the (detrended) input
  Reconstruction reconstruction;
  std::optional<ViewSearch> search;     // unknown view: J(α) and its minima
  std::vector<int> missingJoints;       // never seen: estimated by the model
};

struct EngineResult {
  EngineKind engine = EngineKind::Eigenwalker;
  Eigen::MatrixXd framesMm;             // T × 45 at the input's frames (walker's frame, mm)
  double alphaDeg = 0.0;                // the view: given, or the engine's estimate
  bool alphaEstimated = false;
  // RMS over the seen points of every frame of |C(α) x − y| (mm), after the engine's own
  // image alignment (the eigenwalker: the input's detrending; the snippet engine: each
  // snippet's shift). What "the 3D walker explains the 2D input" means, per engine.
  double reprojectionRmsMm = 0.0;
  std::vector<std::string> warnings;
  std::optional<EigenwalkerDiagnostics> eigenwalker;
  std::optional<SnippetSequence> snippet;
  std::optional<SkeletonSequence> skeleton;   // in the view's frame (U, D, V; skeleton_tree.h)
};

// Throws what the engine throws — typed errors naming input.name: the eigenwalker's
// "Fourier fit: less than one gait cycle: …" for a clip shorter than a cycle, the snippet
// engine's for a clip shorter than one snippet — and Error(BadArgument) for an input that
// is not T × 30 or has a rate that is not positive and finite.
EngineResult reconstructWithEngine(const Engine& engine, const ViewInput& input);

// A reconstruction against the 3D truth at the same frames (both T × 45, walker's frame),
// after removing the clip's mean translation (engines differ in what they know of where
// the walker stands; shape and motion are compared): per frame the mean over joints of
// the 3D error, its mean (MPJPE, mm) and E_a, the mean squared error along the line of
// sight of view α (mm²; METHOD §7 on frames). Throws Error(BadArgument) for unequal shapes.
struct ClipErrors {
  Eigen::VectorXd perFrameMm;
  double mpjpeMm = 0.0;
  double depthErrorMm2 = 0.0;
};
ClipErrors clipErrors(const Eigen::Ref<const Eigen::MatrixXd>& reconstructedMm,
                      const Eigen::Ref<const Eigen::MatrixXd>& truthMm, double alphaDeg);

// The eigenwalker engine's image detrending: subtracts from every u the least-squares line
// through the pelvis's u over the frames that see it (nothing when fewer than 2 do).
Eigen::MatrixXd removeImageDrift(const Eigen::Ref<const Eigen::MatrixXd>& uvMm, double rateHz);

// Bone lengths from an orthographic view alone (T × 30, mm): a bone's image is never
// longer than the bone, and walking turns every limb and the trunk parallel to the image
// at some point of the cycle, so each is the 95th percentile of its image length over the
// frames, the larger of a left/right pair for both. A bone along the line of sight the
// whole time (the hips and shoulders seen from the side) comes out short: its joints are
// then clamped to their parent's depth. Throws Error(BadData) naming `name` when a bone is
// never seen.
BoneLengths estimateBoneLengthsFromView(const Eigen::Ref<const Eigen::MatrixXd>& uvMm, const std::string& name);

// The view's frame (U along the image's horizontal, D away from the camera, V up) turned
// into the walker's frame of METHOD §2 by the view angle α (inverse of METHOD §5): T × 45.
Eigen::MatrixXd viewFrameToWalker(const Eigen::Ref<const Eigen::MatrixXd>& viewFramesMm, double alphaDeg);

// The view angle at which a pose seen in the view's frame walks forward: the body's forward
// axis (up × right, from the pelvis→sternum and left→right hip axes) is the walker's +y,
// seen at α = atan2(forward_U, forward_D); the circular mean over the frames, degrees.
double viewAngleFromPoses(const Eigen::Ref<const Eigen::MatrixXd>& viewFramesMm);

// [SECTION] Walkers known only as a Fourier vector (the viewer's population, a model)

// The walker w (225, METHOD §3, phase origin 0) walked overground: `cycles` gait cycles at
// `rateHz`, every joint carried forward along +y at `speedMps` (T × 45, mm). What an engine
// is shown of a walker whose trials are not at hand; the snippet prior was learnt
// overground, so it is shown the progression too. Throws Error(BadArgument) for a w that is
// not 225 values, or ω, speed, cycles or rate that are not positive and finite (speed may
// be 0: walking in place).
Eigen::MatrixXd overgroundFrames(const Eigen::Ref<const Eigen::VectorXd>& w, double omegaRadS, double speedMps,
                                 double cycles, double rateHz);

// An engine's frames summarised as one gait cycle: progression removed (removeProgression),
// the 3D Fourier fit at the known ω, turned to phase origin 0 (rephase), so it is compared
// with the walker's own w and drawn by the same code (225). Throws the Fourier fit's errors.
Eigen::VectorXd fourierSummary(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, double rateHz, double omegaRadS);

// A snippet prior's training trials from walkers known as Fourier vectors: each walked
// overground for `cycles` at 30 Hz (overgroundFrames) with its speed.
struct FourierWalkerTrial {
  std::string subject, name;
  Eigen::VectorXd w;
  double omegaRadS = 0.0;
  double speedMps = 0.0;
};
std::vector<SnippetTrainingTrial> snippetTrialsFromFourier(const std::vector<FourierWalkerTrial>& walkers,
                                                           double cycles = 4.0);
// A model's walkers as it stores them (storedWalkerVectors), without `withoutSubject`'s ("" for
// none), each at the speed the model records (speeds_mps), else the mean of those it records,
// else 1.3 m/s (a typical adult's): what a snippet prior learns from when the walkers are a
// model's (the viewer with the default model held, `reconstruct --engine snippet` without
// --prior).
std::vector<FourierWalkerTrial> modelFourierWalkers(const EigenwalkerModel& model, const std::string& withoutSubject);

}  // namespace ew
