#pragma once
// Derived results: functions of the Document, cached and recomputed only when their
// input struct changes (compared with operator== = default). Playback, camera and
// overlays are not inputs: animating or orbiting never recomputes anything here.

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/reconstruction.h"
#include "ui/app/document.h"
#include "ui/app/semantic.h"

namespace ew::ui {

// [SECTION] Reconstruction of the selected walker (leave-one-subject-out model)

struct ReconKey {
  std::uint64_t generation = 0;
  int walker = -1;
  ReconstructionSettings settings;
  bool operator==(const ReconKey&) const = default;
};

struct ReconBase {
  std::string modelName;       // the held model (heldModelName)
  bool inModel = false;        // the walker's subject is in the held model …
  std::string heldOutSubject;  // … and this one was left out of the model used
  bool inspected = false;      // a trial the user opened, not a population member
  // Joints the trial lacked, filled in from a model: its "ground truth" there is the model's,
  // so their errors are reported apart from the measured joints'.
  std::array<bool, kJointCount> modelEstimated{};
  int modelWalkers = 0;          // walkers in the model used
  int components = 0;            // N used
  bool autoComponents = true;    // N from the 95 % rule
  double explained = 0.0;        // variance share of the N components
  EigenwalkerModel model;        // leave-one-out, truncated to N
  ModelGram gram;
  Eigen::VectorXd sd;            // √λ_n, mm
  Eigen::VectorXd wTrue;         // the held-out walker's own Fourier vector (225)
  Eigen::VectorXd observed;      // ŵ = C(α) w (150): what the reconstruction sees
  Eigen::MatrixXd observedTrail; // ŵ over one cycle: kTrailSamples × 30
  Reconstruction estimate;       // at α, or at α̂ in unknown-angle mode
  std::optional<ViewSearch> search;  // unknown-angle mode only
  double alphaTrueDeg = 0.0;
  double alphaUsedDeg = 0.0;     // α, or α̂
  double strideHz = 0.0;
  // The snippet engine (settings.engine): it is shown the walker walked overground for
  // kSnippetCycles at 30 Hz and at `speedMps`, learns its prior from the population's other
  // subjects, and its frames are summarised as one cycle (fourierSummary) into estimate.w;
  // estimate.k is then that summary's least-squares coefficients (read only).
  EngineKind engine = EngineKind::Eigenwalker;
  std::optional<SnippetSequence> snippets;
  double speedMps = 0.0;
  std::string speedSource;       // "measured", "population mean", "typical adult"
  int priorWalkers = 0;          // walkers the snippet prior learnt from
  // The skeleton engine: the walker in place for kSnippetCycles at 30 Hz with its own bone
  // lengths, summarised as one cycle into estimate.w like the snippet engine's.
  std::optional<SkeletonSequence> skeleton;
};

inline constexpr double kSnippetCycles = 2.0;

struct DisplayKey {
  ReconKey base;
  std::vector<double> editedSd;
  bool operator==(const DisplayKey&) const = default;
};

// What the views show: the estimate, or the estimate with the user's coefficient edits.
struct ReconDisplay {
  bool edited = false;
  Eigen::VectorXd kSd;           // coefficients in SD units (N)
  Eigen::VectorXd w;             // 225, model synthesis w̄ + E k
  Eigen::VectorXd reprojected;   // C(α_used) w (150)
  DepthErrors errors;            // at the true α (METHOD §7), all 15 joints
  Eigen::VectorXd depthRmsMm;    // √E_abs(j) per joint, mm
  // The headline errors, over the joints the trial measured (all 15 unless a marker set
  // lacked some), as `reconstruct` reports them: a model-estimated joint has no truth.
  double absScoredMm2 = 0.0;     // E_a
  double relScored = 0.0;        // E_r = E_a / σ_m²
  double mpjpeMm = 0.0;
  int jointsScored = kJointCount;
  double mpjpeMeasuredMm = 0.0;                 // over the measured joints (= mpjpeMm)
  std::optional<double> mpjpeModelEstimatedMm;  // over the model-estimated joints, if any
  double residualRmsMm = 0.0;    // RMS of ŵ − C(α_used) w over the 150 values
  double angleErrorDeg = 0.0;    // |α̂ − α| (0 with a known angle)
};

// [SECTION] Compare mode: the walker reconstructed by every engine

struct CompareEntry {
  EngineKind engine = EngineKind::Eigenwalker;
  std::shared_ptr<const ReconBase> base;        // null when the engine gave no answer
  std::shared_ptr<const ReconDisplay> display;  // its errors (no coefficient edits)
  std::string error;                            // why not
  double seconds = 0.0;                         // the reconstruction's wall time
};

struct CompareResult {
  std::vector<CompareEntry> engines;  // kEngineKinds order
  const CompareEntry* of(EngineKind kind) const;
};

// [SECTION] Explorer: a walker synthesised from coefficients of the full model

struct ExploreKey {
  std::uint64_t generation = 0;
  int components = 0;
  std::vector<double> sd;
  double omegaOffsetRadS = 0.0;
  double alphaDeg = 0.0;
  bool operator==(const ExploreKey&) const = default;
};

struct ExploreResult {
  int components = 0;
  bool autoComponents = true;
  double explained = 0.0;
  Eigen::VectorXd sd;            // √λ_n of the full model
  Eigen::VectorXd shares;        // λ_n / Σλ
  Eigen::VectorXd k;             // N, mm
  Eigen::VectorXd w;             // 225
  Eigen::VectorXd projected;     // C(α) w (150)
  Eigen::MatrixXd projectedTrail;
  double strideHz = 0.0;         // mean of the population, plus the explorer's offset
  int modelWalkers = 0;
  std::string modelName;  // the held model (heldModelName)
};

inline constexpr int kTrailSamples = 64;

// Snippet priors learnt from the population, one per held-out subject, kept while the
// population stays (a new load clears them): switching walkers costs one training each.
class SnippetPriorCache {
 public:
  struct Entry {
    std::shared_ptr<const PreparedSnippetPrior> prior;
    int walkers = 0;
  };
  // The prior learnt from the walkers the eigenwalker reconstructs walker `index` against (the
  // loaded population, or the held model's walkers: the engines compared on the same
  // reference walkers), without the walker's own subject.
  Entry get(const Document& doc, int index);
  int trainings() const { return trainings_; }

 private:
  std::uint64_t generation_ = 0;
  const Population* population_ = nullptr;
  const EigenwalkerModel* model_ = nullptr;  // the held model when it is not the population's
  std::map<std::string, Entry> entries_;
  int trainings_ = 0;
};

// The speed a population walker is shown walking at: its measured speed, else the mean of
// the population's measured speeds, else 1.3 m/s (a typical adult's self-selected speed).
std::pair<double, std::string> walkerSpeedMps(const Document& doc, int walker);

class Derived {
 public:
  // Brings every cache up to date with the document (cheap when nothing changed).
  void update(const Document& doc);

  const ReconBase* recon() const { return recon_.get(); }
  const ReconDisplay* display() const { return display_.get(); }
  const ExploreResult* explore() const { return explore_.get(); }
  // Compare mode only (Document::compareEngines): each engine's reconstruction.
  const CompareResult* compare() const { return compare_.get(); }
  // Explore mode: the semantic axes in the explorer's model (semantic.h says of which walkers).
  const SemanticAxes* semantic() const { return semantic_.get(); }
  // Reconstruct mode (eigenwalker, population walker): attributes predicted from the 2D view.
  const std::vector<AttributeFromView>& attributesFromView() const { return fromView_; }
  // The walkers those attributes' axes are learnt from ("the default model's 24 walkers") and
  // the subject left out of them ("" for none).
  const ViewAxes& attributesFromViewAxes() const { return viewAxes_; }
  // The last computation's error (empty when it succeeded).
  const std::string& error() const { return error_; }
  // How many times each cache was recomputed (for tests and the log).
  int reconComputations() const { return reconComputations_; }

 private:
  std::optional<ReconKey> reconKey_;
  std::optional<DisplayKey> displayKey_;
  std::optional<ExploreKey> exploreKey_;
  std::unique_ptr<ReconBase> recon_;
  std::unique_ptr<ReconDisplay> display_;
  std::unique_ptr<ExploreResult> explore_;
  std::optional<ReconKey> compareKey_;  // settings.engine normalised: every engine is in it
  std::unique_ptr<CompareResult> compare_;
  std::string error_;
  int reconComputations_ = 0;
  SnippetPriorCache snippetPriors_;
  // The population's walkers and attributes (measured once per generation), and the held
  // model's when it is not the population's (once per model held): what the axes learn from.
  std::unique_ptr<const AxesWalkers> populationAxesWalkers_;
  std::uint64_t attributesGeneration_ = 0;
  std::unique_ptr<const AxesWalkers> modelAxesWalkers_;
  std::pair<std::uint64_t, const EigenwalkerModel*> modelAxesWalkersKey_{0, nullptr};  // generation, model
  std::optional<SemanticAxesKey> semanticKey_;
  std::unique_ptr<SemanticAxes> semantic_;
  std::optional<ReconKey> fromViewKey_;
  std::vector<AttributeFromView> fromView_;
  // The axes of the walker's attributes, refitted only when the walker or its model changes.
  // generation, walker, N, and which model is held (its source and file)
  std::optional<std::tuple<std::uint64_t, int, int, ModelSource, int>> viewAxesKey_;
  ViewAxes viewAxes_;
  const AxesWalkers& populationAxes(const Document& doc);
  const AxesWalkers& heldModelAxes(const Document& doc, const EigenwalkerModel& held);
  void updateSemantic(const Document& doc);
};

// Pose helpers: w (225 or 150) evaluated at a gait phase (0 … 1); all walkers share the
// phase origin of METHOD §3, so phase p is the same moment of the cycle for everyone.
Eigen::VectorXd frameAtPhase(const Eigen::VectorXd& w, double phase01);
Eigen::MatrixXd trailOverCycle(const Eigen::VectorXd& w, int samples);

}  // namespace ew::ui
