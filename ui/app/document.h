#pragma once
// The three kinds of state (docs/VIEWER_DESIGN.md, "State and threads"):
//   Document  — what is loaded and what the user chose to compute (walker, view angle,
//               estimator, coefficients); everything derived is a function of it.
//   ViewState — how it is looked at (camera, overlays, playback, UI scale).
//   Derived   — the reconstruction and friends, cached (ui/app/derived.h).

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/eigenwalker/reconstruction.h"
#include "core/engines/engine.h"
#include "ui/app/model_set.h"
#include "ui/app/population.h"
#include "ui/render/camera.h"

namespace ew::ui {

// Clip: a pose estimator's keypoint clip, reconstructed through its unknown camera.
enum class Mode { Reconstruct, Explore, Clip };

struct ReconstructionSettings {
  double alphaDeg = 30.0;        // true view angle of the 2D input (METHOD §5)
  Estimator estimator = Estimator::Map;
  double sigma2Mm2 = 70.0;       // MAP σ²
  int components = 0;            // N; 0 = the smallest N reaching 95 % of the variance
  bool unknownAngle = false;     // estimate α instead of using it (METHOD §6)
  // Which engine reconstructs (core/engines/engine.h); the estimator, σ² and N are the
  // eigenwalker's own settings.
  EngineKind engine = EngineKind::Eigenwalker;
  bool operator==(const ReconstructionSettings&) const = default;
};

// Where the model the viewer holds comes from (docs/VIEWER.md, "Models and walkers"): the
// loaded population (leave-one-out per subject), the default model of real walkers, or a
// saved .ewm file the user opened.
enum class ModelSource { Population, Default, File };

// A model read from a file (or the default model's asset), with what the header calls it.
struct SavedModel {
  std::string name;            // "24 real walkers (default)", "my_model.ewm"
  std::filesystem::path file;  // empty for the default model
  EigenwalkerModel model;
};

struct Document {
  // The loaded population and its models; a new load bumps the generation.
  std::shared_ptr<const Population> population;
  std::shared_ptr<const ModelSet> models;
  std::uint64_t generation = 0;
  std::vector<std::filesystem::path> sourcePaths;  // empty: the synthetic default
  FileOverrides fileOverrides;                      // per-file unit / frame-rate overrides

  // [SECTION] The model held and the walkers inspected against it
  ModelSource modelSource = ModelSource::Population;
  std::shared_ptr<const SavedModel> defaultModel;             // read on first use
  std::vector<std::shared_ptr<const SavedModel>> modelFiles;  // .ewm files opened, in order
  int modelFile = 0;                                          // which one, when modelSource is File
  // Trials the user opened to inspect against the held model (not population members).
  std::shared_ptr<const Population> inspected;

  Mode mode = Mode::Reconstruct;
  // Index into the walkers: the population's first, then the inspected ones.
  int walker = 0;
  ReconstructionSettings recon;
  // σ² follows the held model's stored optimum (defaultSigma2Mm2) until the user sets it.
  bool sigma2Chosen = false;
  std::vector<double> exploreSd;   // explorer coefficients, units of each component's SD
  double exploreOmegaOffsetRadS = 0.0;  // explorer's ω − the population's mean (semantic axes move it)
  std::vector<double> editedSd;    // reconstruct mode: coefficients the user dragged
                                   // (empty = the estimate)
  // Compare mode (reconstruct mode): every engine reconstructs the walker, drawn together
  // over the ground truth; which of them the views show (kEngineKinds order).
  bool compareEngines = false;
  std::array<bool, 3> compareShown{true, true, true};

  int populationCount() const { return population ? population->walkerCount() : 0; }
  int walkerCount() const { return populationCount() + (inspected ? inspected->walkerCount() : 0); }
  bool isInspected(int index) const { return index >= populationCount(); }
  // Walker `index` (population first, then inspected) and its facts; nullptr out of range.
  const Walker* walkerAt(int index) const;
  const WalkerFacts* factsAt(int index) const;
  const Walker* selectedWalker() const { return walkerAt(walker); }
  const WalkerFacts* selectedFacts() const { return factsAt(walker); }
  // The model of every walker the held source gives (nullptr while the population's models
  // are being built, or when the chosen source has none).
  const EigenwalkerModel* heldModel() const;
  bool ready() const { return walkerCount() > 0 && heldModel() != nullptr; }
};

struct Overlays {
  bool depthErrorColour = true;  // joints coloured by their depth error, with a colour bar
  bool errorLines = true;        // ground truth → reconstruction, per joint
  bool errorBars = true;         // per-joint error bar chart
  bool metrics = true;           // the metrics strip
  bool ghost = true;             // ground truth drawn as a ghost in 3D
  bool cameraGlyph = true;       // where the 2D view is taken from
  bool grid = true;              // the floor grid
  bool reprojection = true;      // 2D: the reconstruction projected back at α
  bool stickFigure = true;       // 2D: bones between the point-lights
  bool trails = true;            // 2D: each point-light's path over the cycle
  bool pointLights = false;      // point-light display: joints as dots only, no skeleton,
                                 // trails, ghost or error lines (Johansson 1973)
  bool operator==(const Overlays&) const = default;
};

// Dark (default), light (UI panels light, the views stay dark so point-lights show), or
// projector (dark, higher contrast, every size × kProjectorScale).
enum class Theme { Dark, Light, Projector };
inline constexpr float kProjectorScale = 1.3f;
// The smallest window, in the UI's own pixels, the layout is made for (UI scale 1.83 at 1024×768).
inline constexpr float kMinLogicalWindowW = 560.0f, kMinLogicalWindowH = 384.0f;

struct Playback {
  bool playing = true;
  float speed = 1.0f;     // × real time
  double cycles = 0.0;    // continuous gait-cycle count; the phase is its fraction
  double phase() const;   // 0 … 1
  void setPhase(double phase01);
  void advance(double seconds, double strideHz);
  void step(int frames, double strideHz);  // ± one 1/60 s frame
};

struct ViewState {
  OrbitCamera camera;
  Overlays overlays;
  Playback playback;
  Theme theme = Theme::Dark;
  float uiScale = 1.0f;       // user setting, times the monitor's content scale
  float contentScale = 1.0f;  // from the monitor
  // The UI scale the window's size allows, when it is less than uiScale (0: not limited): the
  // UI keeps at least kMinLogicalWindow of its own pixels, so that panels hold their words.
  float uiScaleLimit = 0.0f;
  // Presentation mode (F5): only the two views and the presentation bar. Never saved: every
  // run starts in the workspace.
  bool presentation = false;
};

}  // namespace ew::ui
