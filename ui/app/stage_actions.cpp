#include "ui/app/stage_actions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/io/atomic_write.h"
#include "core/teaching/html_walker.h"
#include "ui/app/theme.h"

namespace ew::ui {

namespace {

// A walker of the population: its measured speed, else a typical adult's stride (the 3D
// floor's treadmill uses the same).
double walkingSpeedMmS(const AppState& s, double strideHz) {
  const WalkerFacts* f = s.doc.selectedFacts();
  if (s.doc.mode == Mode::Reconstruct && f && f->speedMps && f->strideHz > 0.0) return *f->speedMps * 1000.0;
  constexpr double kTypicalStrideMm = 1400.0;
  return kTypicalStrideMm * strideHz;
}

std::string selectedName(const AppState& s) {
  const Walker* w = s.doc.selectedWalker();
  return w ? w->subject : std::string("the walker");
}

void refuse(const std::string& why) { throw std::invalid_argument(why); }

}  // namespace

// [SECTION] What the stage shows

bool stageDrawsViews(const AppState& s) {
  return s.doc.mode != Mode::Clip && (s.stage.shown() || s.quiz.running());
}

std::optional<StageWalker> stageWalker2d(const AppState& s) {
  if (s.doc.mode == Mode::Reconstruct) {
    const ReconBase* r = s.derived.recon();
    if (!r || r->wTrue.size() != kFourierDims3 || !(r->strideHz > 0.0)) return std::nullopt;
    return StageWalker{&r->wTrue, r->strideHz, r->alphaTrueDeg, walkingSpeedMmS(s, r->strideHz), selectedName(s)};
  }
  if (s.doc.mode == Mode::Explore) {
    const ExploreResult* e = s.derived.explore();
    if (!e || !(e->strideHz > 0.0)) return std::nullopt;
    return StageWalker{&e->w, e->strideHz, s.doc.recon.alphaDeg, walkingSpeedMmS(s, e->strideHz),
                       "the synthesised walker"};
  }
  return std::nullopt;
}

std::optional<StageWalker> stageWalker3d(const AppState& s) {
  if (s.doc.mode == Mode::Reconstruct) {
    const ReconBase* r = s.derived.recon();
    const ReconDisplay* d = s.derived.display();
    if (!r || !d || d->w.size() != kFourierDims3 || !(r->strideHz > 0.0)) return std::nullopt;
    return StageWalker{&d->w, r->strideHz, r->alphaUsedDeg, walkingSpeedMmS(s, r->strideHz),
                       "the reconstruction of " + selectedName(s)};
  }
  return stageWalker2d(s);
}

StageFeature effectiveStage(const AppState& s) {
  StageFeature stage = s.stage;
  if (s.quiz.running()) {
    const Staircase& q = *s.quiz.staircase;
    stage.display.maskDots = std::min(q.noiseDots(), kMaxMaskDots);
    stage.display.translating = false;  // the walker's facing is the only cue
    stage.display.backwards = false;
    stage.depthReversed = false;
    // Each trial its own noise: the room cannot learn where the noise dots are.
    stage.display.seed = q.options().seed + static_cast<std::uint64_t>(q.trials().size()) + 1;
  }
  return stage;
}

double stageAzimuthDeg(const AppState& s, double alphaDeg) {
  if (s.quiz.running()) return s.quiz.staircase->direction() == WalkDirection::Right ? 90.0 : -90.0;
  return alphaDeg + s.stage.turnedDeg;
}

namespace actions {

// [SECTION] The displays

void setInverted(AppState& s, bool on) { s.stage.display.inverted = on; }
void setScramble(AppState& s, Scramble scramble) { s.stage.display.scramble = scramble; }

void setMaskDots(AppState& s, int dots) {
  if (dots < 0 || dots > kMaxMaskDots)
    refuse("mask dots must be 0 to " + std::to_string(kMaxMaskDots) + ", not " + std::to_string(dots));
  s.stage.display.maskDots = dots;
  if (dots > 0) s.stage.maskSlider = dots;
}

void setDotLifetime(AppState& s, double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0 || (seconds > 0.0 && seconds < 0.05) || seconds > 5.0)
    refuse("a dot's lifetime is 0 (off) or 0.05 to 5 s");
  s.stage.display.dotLifetimeS = seconds;
}

void setBackwards(AppState& s, bool on) { s.stage.display.backwards = on; }
void setTranslating(AppState& s, bool on) { s.stage.display.translating = on; }
void setDepthReversed(AppState& s, bool on) { s.stage.depthReversed = on; }

void resetStage(AppState& s) {
  const int slider = s.stage.maskSlider;
  s.stage = {};
  s.stage.maskSlider = slider;
}

void toggleMask(AppState& s) { setMaskDots(s, s.stage.display.maskDots > 0 ? 0 : s.stage.maskSlider); }

void cycleScramble(AppState& s) {
  const Scramble next = s.stage.display.scramble == Scramble::None    ? Scramble::Phase
                        : s.stage.display.scramble == Scramble::Phase ? Scramble::Position
                                                                      : Scramble::None;
  setScramble(s, next);
}

void toggleLifetime(AppState& s) {
  constexpr double kLifetimeS = 0.2;  // Beintema & Lappe (2002) showed lifetimes of 0.1 to 0.4 s
  setDotLifetime(s, s.stage.display.dotLifetimeS > 0.0 ? 0.0 : kLifetimeS);
}

// [SECTION] The turning stage

void setTurning(AppState& s, bool on) { s.stage.turning = on; }

void setTurnRate(AppState& s, double degPerS) {
  if (!std::isfinite(degPerS) || std::abs(degPerS) > kStageMaxTurnDegPerS)
    refuse("the stage turns at −180 to 180 °/s");
  s.stage.turnDegPerS = degPerS;
}

void setStageElevation(AppState& s, double degrees) {
  if (!std::isfinite(degrees) || std::abs(degrees) > kStageMaxElevationDeg)
    refuse("the stage's elevation is −60 to 60°");
  s.stage.elevationDeg = degrees;
  s.view.camera.pitchDeg = static_cast<float>(degrees);
}

void advanceStage(AppState& s, double seconds) {
  if (!s.stage.turning || s.quiz.running()) return;
  const double before = s.stage.turnedDeg;
  s.stage.turnedDeg = turnedAfter(s.stage, seconds);
  // The 3D view turns with the 2D one: the camera goes round the walker as α grows.
  double turned = s.stage.turnedDeg - before;
  if (turned > 180.0) turned -= 360.0;
  if (turned < -180.0) turned += 360.0;
  s.view.camera.yawDeg = static_cast<float>(std::fmod(s.view.camera.yawDeg + turned + 540.0, 360.0) - 180.0);
}

// [SECTION] The quiz

void quizStart(AppState& s, const StaircaseOptions& options) {
  if (s.doc.mode == Mode::Clip) refuse("the quiz shows a Fourier walker: leave the clip view first (R or E)");
  if (options.maxDots > kMaxMaskDots)
    refuse("the quiz's noise stops at " + std::to_string(kMaxMaskDots) + " dots");
  try {
    s.quiz.staircase.emplace(options);
  } catch (const std::exception& e) {
    refuse(e.what());
  }
  s.quiz.options = options;
  s.quiz.stopped = false;
  s.quiz.open = true;
  s.quiz.status.clear();
  s.log.info("Quiz started: which way is it walking? (← / → answer)");
}

void quizAnswer(AppState& s, WalkDirection answer) {
  if (!s.quiz.running()) refuse("no quiz is running (Q starts one)");
  const QuizTrial& t = s.quiz.staircase->answer(answer);
  if (s.quiz.staircase->done()) {
    char text[160];
    std::snprintf(text, sizeof text, "Quiz ended after %d trials: threshold %.1f noise dots (70.7 %% right)",
                  t.number, s.quiz.staircase->thresholdDots());
    s.log.info(text);
  }
}

void quizStop(AppState& s) {
  if (!s.quiz.running()) return;
  // The trials answered stay, to be plotted and saved.
  s.quiz.stopped = true;
  s.log.info("Quiz stopped after " + std::to_string(s.quiz.staircase->trials().size()) + " trials");
}

void saveQuizCsv(AppState& s, const std::filesystem::path& path) {
  if (!s.quiz.staircase || s.quiz.staircase->trials().empty()) refuse("no quiz trials to save");
  const std::vector<QuizTrial>& trials = s.quiz.staircase->trials();
  const std::string csv = quizCsv(trials);
  writeFileAtomically(path, [&](std::ostream& out) { out << csv; });
  s.quiz.status = "wrote " + path.filename().string();
  s.log.info("Wrote " + path.string() + " (quiz, " + std::to_string(trials.size()) + " trials)");
}

// [SECTION] The audience window

void setAudienceOpen(AppState& s, bool open) { s.audience.open = open; }

void setAudienceSize(AppState& s, int width, int height) {
  if (width < 320 || height < 240 || width > 7680 || height > 4320)
    refuse("the audience window is 320×240 to 7680×4320, not " + std::to_string(width) + "×" + std::to_string(height));
  s.audience.widthPx = width;
  s.audience.heightPx = height;
}

void setAudienceTheme(AppState& s, const std::string& name) {
  if (name == "dark")
    s.audience.theme = AudienceTheme::Dark;
  else if (name == "projector")
    s.audience.theme = AudienceTheme::Projector;
  else
    refuse("the audience window's theme is \"dark\" or \"projector\" (its dots are light: a lit room takes "
           "the projector's black), not \"" + name + "\"");
}

void setAudienceViews(AppState& s, const std::string& name) {
  if (name == "both")
    s.audience.views = AudienceViews::Both;
  else if (name == "input")
    s.audience.views = AudienceViews::Input;
  else if (name == "reconstruction")
    s.audience.views = AudienceViews::Reconstruction;
  else
    refuse("the audience window shows \"both\" views, the \"input\" or the \"reconstruction\", not \"" + name + "\"");
}

void requestAudiencePng(AppState& s, const std::filesystem::path& path) {
  if (!s.audience.open) refuse("the audience window is not open");
  s.audience.capture = path;
}

// [SECTION] The walker as a web page

void exportWalkerHtml(AppState& s, const std::filesystem::path& path) {
  s.derived.update(s.doc);  // a script may have changed the document since the last frame
  const std::optional<StageWalker> walker = stageWalker2d(s);
  if (!walker) refuse("no walker to export (the HTML walker is a Fourier walker: reconstruct or explore mode)");
  HtmlWalker html{*walker->w, 2.0 * std::numbers::pi * walker->strideHz, 0.0, walker->name};
  HtmlWalkerSettings settings;
  const StageFeature& stage = s.stage;
  settings.viewAngleDeg = stageAzimuthDeg(s, walker->alphaDeg);
  settings.elevationDeg = stage.elevationDeg;
  settings.playbackSpeed = (stage.display.backwards ? -1.0 : 1.0) * std::clamp(static_cast<double>(s.view.playback.speed), 0.0, 5.0);
  settings.startPhase01 = s.view.playback.phase();
  settings.lines = s.view.overlays.stickFigure && !s.view.overlays.pointLights && displayKeepsTheForm(stage.display);
  settings.translate = stage.display.translating;
  settings.translateSpeedMps = std::clamp(walker->speedMmS / 1000.0, 0.0, 10.0);
  settings.framing = HtmlFraming::Viewer;
  settings.theme = s.view.theme == Theme::Light ? HtmlTheme::Light
                   : s.view.theme == Theme::Projector ? HtmlTheme::Projector
                                                      : HtmlTheme::Dark;
  settings.title = "Point-light walker: " + walker->name;
  std::string caption = "Exported from Eigenwalker's 2D view.";
  const std::string viewerOnly = [&] {
    std::string parts;
    const BiologicalMotionOptions& d = stage.display;
    const auto add = [&](const char* p) { parts += (parts.empty() ? "" : ", ") + std::string(p); };
    if (d.inverted) add("inverted");
    if (d.scramble != Scramble::None) add("scrambled");
    if (d.maskDots > 0) add("masked");
    if (d.dotLifetimeS > 0.0) add("limited-lifetime");
    return parts;
  }();
  if (!viewerOnly.empty()) caption += " The page shows the walker plainly (the viewer showed it " + viewerOnly + ").";
  settings.caption = caption;
  writeWalkerHtml(path, html, settings);
  s.log.info("Wrote " + path.string() + " (the walker as a web page" +
             (viewerOnly.empty() ? std::string(")") : ", shown plainly: the viewer's " + viewerOnly + " display is not in it)"));
}

}  // namespace actions
}  // namespace ew::ui
