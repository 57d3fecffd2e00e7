// Document edits and view state: the walker, the reconstruction's parameters, the explorer, playback, overlays and camera.
#include "ui/app/document_actions.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "core/eigenwalker/model.h"
#include "ui/app/actions.h"
#include "ui/app/actions_internal.h"

namespace ew::ui::actions {

// [SECTION] Document edits

void requireLoaded(const AppState& s) {
  if (s.doc.walkerCount() == 0) throw std::invalid_argument("no data loaded");
}

void selectWalker(AppState& s, int index) {
  requireLoaded(s);
  if (index < 0 || index >= s.doc.walkerCount())
    throw std::invalid_argument("walker index " + std::to_string(index) + " out of range");
  if (s.doc.walker != index) s.doc.editedSd.clear();
  s.doc.walker = index;
  // A walker picked while a keypoint clip is shown: show that walker (the clip stays open).
  if (s.doc.mode == Mode::Clip) s.doc.mode = Mode::Reconstruct;
}

void selectSubject(AppState& s, const std::string& subjectOrId) {
  requireLoaded(s);
  int i = s.doc.population ? s.doc.population->findWalker(subjectOrId) : -1;
  if (i < 0 && s.doc.inspected) {
    const int j = s.doc.inspected->findWalker(subjectOrId);
    if (j >= 0) i = s.doc.populationCount() + j;
  }
  if (i < 0) throw std::invalid_argument("no subject or walker \"" + subjectOrId + "\"");
  selectWalker(s, i);
  s.panels.subjects.scrollToSelection = true;  // bring it into the list's view
}

void setMode(AppState& s, Mode mode) { s.doc.mode = mode; }

void setAngle(AppState& s, double alphaDeg) {
  if (!std::isfinite(alphaDeg) || alphaDeg < -180.0 || alphaDeg > 180.0)
    throw std::invalid_argument("view angle must lie in [-180, 180] degrees");
  if (s.doc.recon.alphaDeg != alphaDeg) s.doc.editedSd.clear();
  s.doc.recon.alphaDeg = alphaDeg;
}

void setEstimator(AppState& s, Estimator estimator) {
  if (s.doc.recon.estimator != estimator) s.doc.editedSd.clear();
  s.doc.recon.estimator = estimator;
}

void setEngine(AppState& s, EngineKind engine) {
  if (s.doc.recon.engine != engine) s.doc.editedSd.clear();
  s.doc.recon.engine = engine;
}

void setCompareEngines(AppState& s, bool on) {
  s.doc.compareEngines = on;
  if (on) s.doc.mode = Mode::Reconstruct;
}

void setCompareShown(AppState& s, EngineKind engine, bool shown) {
  s.doc.compareShown[static_cast<std::size_t>(engine)] = shown;
}

void setSigma2(AppState& s, double sigma2Mm2) {
  if (!std::isfinite(sigma2Mm2) || sigma2Mm2 <= 0.0)
    throw std::invalid_argument("sigma2 must be a positive number of mm^2");
  s.doc.sigma2Chosen = true;
  if (s.doc.recon.sigma2Mm2 != sigma2Mm2) s.doc.editedSd.clear();
  s.doc.recon.sigma2Mm2 = sigma2Mm2;
}

void followModelSigma2(AppState& s) {
  const EigenwalkerModel* held = s.doc.heldModel();
  if (s.doc.sigma2Chosen || held == nullptr) return;
  const double optimum = defaultSigma2Mm2(*held);
  if (s.doc.recon.sigma2Mm2 != optimum) s.doc.editedSd.clear();
  s.doc.recon.sigma2Mm2 = optimum;
}

void setComponents(AppState& s, int components) {
  if (components < 0) throw std::invalid_argument("components must be >= 0 (0 = auto)");
  if (const EigenwalkerModel* held = s.doc.heldModel()) {
    const int maxN = held->componentCount();
    if (components > maxN)
      throw std::invalid_argument("components must be at most " + std::to_string(maxN));
  }
  if (s.doc.recon.components != components) s.doc.editedSd.clear();
  s.doc.recon.components = components;
}

void setUnknownAngle(AppState& s, bool unknown) {
  if (s.doc.recon.unknownAngle != unknown) s.doc.editedSd.clear();
  s.doc.recon.unknownAngle = unknown;
}

int coefficientCount(const AppState& s) {
  if (s.doc.mode == Mode::Explore) {
    const auto* e = s.derived.explore();
    return e ? e->components : 0;
  }
  const auto* r = s.derived.recon();
  return r ? r->components : 0;
}

void setCoefficient(AppState& s, int index, double sd) {
  requireLoaded(s);
  const int n = coefficientCount(s);
  if (index < 0 || index >= n)
    throw std::invalid_argument("coefficient " + std::to_string(index + 1) + " out of range 1…" +
                                std::to_string(n));
  if (!std::isfinite(sd)) throw std::invalid_argument("coefficient value must be a number");
  sd = std::clamp(sd, -3.0, 3.0);
  if (s.doc.mode == Mode::Explore) {
    s.doc.exploreSd.resize(static_cast<std::size_t>(n), 0.0);
    s.doc.exploreSd[static_cast<std::size_t>(index)] = sd;
  } else {
    const auto* d = s.derived.display();
    if (!d) throw std::invalid_argument("no reconstruction yet");
    if (static_cast<int>(s.doc.editedSd.size()) != n)
      s.doc.editedSd.assign(d->kSd.data(), d->kSd.data() + d->kSd.size());
    s.doc.editedSd[static_cast<std::size_t>(index)] = sd;
  }
}

void resetCoefficients(AppState& s) {
  if (s.doc.mode == Mode::Explore) {
    s.doc.exploreSd.assign(s.doc.exploreSd.size(), 0.0);
    s.doc.exploreOmegaOffsetRadS = 0.0;
  } else {
    s.doc.editedSd.clear();
  }
}

void randomiseCoefficients(AppState& s, unsigned seed) {
  const int n = coefficientCount(s);
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  s.doc.exploreSd.resize(static_cast<std::size_t>(n));
  for (auto& v : s.doc.exploreSd) v = std::clamp(normal(rng), -3.0, 3.0);
  s.doc.exploreOmegaOffsetRadS = 0.0;
}

void coefficientsFromWalker(AppState& s) {
  requireLoaded(s);
  const EigenwalkerModel* held = s.doc.heldModel();
  const Walker* walker = s.doc.selectedWalker();
  if (!held || !walker) throw std::invalid_argument("models not built yet");
  const auto* e = s.derived.explore();
  const int n = e ? e->components : 0;
  const EigenwalkerModel m = truncateModel(*held, n);
  const Eigen::VectorXd k = projectOntoModel(m, walker->fit.w);
  s.doc.exploreSd.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    s.doc.exploreSd[static_cast<std::size_t>(i)] =
        std::clamp(k(i) / std::max(std::sqrt(m.eigenvalues(i)), 1e-12), -3.0, 3.0);
  s.doc.exploreOmegaOffsetRadS = held->omegasRadS.size() > 0 ? walker->fit.omegaRadS - held->omegasRadS.mean() : 0.0;
}

ExploreState exploreState(const AppState& s) { return {s.doc.exploreSd, s.doc.exploreOmegaOffsetRadS}; }

void moveAlongAxis(AppState& s, const std::string& attribute, const ExploreState& from, double delta) {
  const auto* e = s.derived.explore();
  const auto* axes = s.derived.semantic();
  const SemanticAxisView* a = axes ? axes->find(attribute) : nullptr;
  if (!e || !a) throw std::invalid_argument("no semantic axis '" + attribute + "' (explore mode, population loaded)");
  if (!std::isfinite(delta)) throw std::invalid_argument("the attribute's value must be a number");
  const int n = e->components;
  s.doc.exploreSd = from.sd;
  s.doc.exploreSd.resize(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n && i < a->axis.directionK.size(); ++i)
    s.doc.exploreSd[static_cast<std::size_t>(i)] =
        std::clamp(s.doc.exploreSd[static_cast<std::size_t>(i)] + a->axis.directionK(i) * delta / std::max(e->sd(i), 1e-12), -3.0, 3.0);
  s.doc.exploreOmegaOffsetRadS = from.omegaOffsetRadS + a->axis.directionOmega * delta;
}

double semanticReading(const AppState& s, const std::string& attribute) {
  const auto* e = s.derived.explore();
  const auto* axes = s.derived.semantic();
  const SemanticAxisView* a = axes ? axes->find(attribute) : nullptr;
  if (!e || !a) throw std::invalid_argument("no semantic axis '" + attribute + "' (explore mode, population loaded)");
  return predictAttribute(a->axis, e->k, 2.0 * std::numbers::pi * e->strideHz);
}

void setSemanticValue(AppState& s, const std::string& attribute, double value) {
  moveAlongAxis(s, attribute, exploreState(s), value - semanticReading(s, attribute));
}

// [SECTION] View state

void setPhase(AppState& s, double phase01) {
  if (!std::isfinite(phase01) || phase01 < 0.0 || phase01 > 1.0)
    throw std::invalid_argument("phase must lie in [0, 1]");
  s.view.playback.setPhase(phase01);
}

void setPlaying(AppState& s, bool playing) { s.view.playback.playing = playing; }

std::vector<std::string> overlayNames() {
  return {"depth_error", "error_lines",  "error_bars",   "metrics", "ghost",       "camera",
          "grid",        "reprojection", "stick_figure", "trails",  "point_lights"};
}

namespace {

// The flag of overlay `name`, or nullptr.
template <class O>
auto overlayFlag(O& o, const std::string& name) -> decltype(&o.trails) {
  return name == "depth_error"    ? &o.depthErrorColour
         : name == "error_lines"  ? &o.errorLines
         : name == "error_bars"   ? &o.errorBars
         : name == "metrics"      ? &o.metrics
         : name == "ghost"        ? &o.ghost
         : name == "camera"       ? &o.cameraGlyph
         : name == "grid"         ? &o.grid
         : name == "reprojection" ? &o.reprojection
         : name == "stick_figure" ? &o.stickFigure
         : name == "trails"       ? &o.trails
         : name == "point_lights" ? &o.pointLights
                                  : nullptr;
}

[[noreturn]] void unknownOverlay(const std::string& name) {
  std::string known;
  for (const auto& n : overlayNames()) known += (known.empty() ? "" : ", ") + n;
  throw std::invalid_argument("unknown overlay \"" + name + "\" (known: " + known + ")");
}

}  // namespace

bool overlay(const AppState& s, const std::string& name) {
  const bool* flag = overlayFlag(s.view.overlays, name);
  if (!flag) unknownOverlay(name);
  return *flag;
}

void setOverlay(AppState& s, const std::string& name, bool on) {
  auto& o = s.view.overlays;
  bool* target = overlayFlag(o, name);
  if (!target) unknownOverlay(name);
  *target = on;
}

void setCamera(AppState& s, const std::string& preset) {
  if (preset == "three_quarter") {
    s.view.camera = OrbitCamera::preset(CameraPreset::ThreeQuarter);
  } else if (preset == "front") {
    s.view.camera = OrbitCamera::preset(CameraPreset::Front);
  } else if (preset == "side") {
    s.view.camera = OrbitCamera::preset(CameraPreset::Side);
  } else if (preset == "top") {
    s.view.camera = OrbitCamera::preset(CameraPreset::Top);
  } else {
    throw std::invalid_argument("unknown camera \"" + preset +
                                "\" (known: three_quarter, front, side, top)");
  }
}

double playbackStrideHz(const AppState& s) {
  if (s.doc.mode == Mode::Clip) return s.clip.fit() ? s.clip.fit()->rec.fit.strideHz : 0.9;
  if (s.doc.mode == Mode::Explore) {
    const auto* e = s.derived.explore();
    return e ? e->strideHz : 0.9;
  }
  const WalkerFacts* f = s.doc.selectedFacts();
  return f ? f->strideHz : 0.9;
}

}  // namespace ew::ui::actions
