#pragma once
// The classroom kit (stage_actions.cpp): the stage's displays, the turning stage, the quiz and
// the walker as an HTML page. Part of the viewer's actions (ui/app/actions.h): each
// validates its argument and throws std::invalid_argument with a readable message when it
// cannot apply. The keys, the script actions, the Controls panel, the presentation bar's
// Displays menu and the quiz panel all call these.

#include <Eigen/Core>
#include <filesystem>
#include <optional>
#include <string>

#include "ui/app/app_state.h"

namespace ew::ui {

// [SECTION] What the stage shows (read by the views, the captions and the audience window)

// Whether the views draw the stage rather than their usual figures: a display is on, the
// stage turned, or a quiz runs; never for a clip or a video (they are no Fourier walkers).
bool stageDrawsViews(const AppState& s);

// A view's walker on the stage, and the view the 2D view takes of it.
struct StageWalker {
  const Eigen::VectorXd* w = nullptr;  // 225
  double strideHz = 0.0;
  double alphaDeg = 0.0;      // the 2D view's azimuth before the stage turned it
  double speedMmS = 0.0;      // its walking speed (overground displays)
  std::string name;           // "SYN005", "the synthesised walker", "the reconstruction of …"
};
// The 2D view's walker (the measured walker in reconstruct mode, the synthesised one in
// explore mode) and the 3D view's (the reconstruction, or the synthesised walker).
std::optional<StageWalker> stageWalker2d(const AppState& s);
std::optional<StageWalker> stageWalker3d(const AppState& s);
// The stage's settings with a running quiz's trial applied (its noise dots and seed).
StageFeature effectiveStage(const AppState& s);
// The 2D view's azimuth: the walker's α turned by the stage, or a quiz trial's profile (+90°:
// walking right, −90°: walking left).
double stageAzimuthDeg(const AppState& s, double alphaDeg);

namespace actions {

// [SECTION] The displays (core/teaching/biological_motion.h)
void setInverted(AppState& s, bool on);
void setScramble(AppState& s, Scramble scramble);
void setMaskDots(AppState& s, int dots);          // 0 (off) … kMaxMaskDots
void setDotLifetime(AppState& s, double seconds);  // 0 (off) or 0.05 … 5 s
void setBackwards(AppState& s, bool on);
void setTranslating(AppState& s, bool on);        // overground (on) or treadmill
void setDepthReversed(AppState& s, bool on);
void resetStage(AppState& s);                      // every display off, the stage unturned
// The keys' toggles: the mask at the slider's N, scrambling none → phase → position → none,
// limited lifetime at 0.2 s.
void toggleMask(AppState& s);
void cycleScramble(AppState& s);
void toggleLifetime(AppState& s);

// [SECTION] The turning stage
void setTurning(AppState& s, bool on);
void setTurnRate(AppState& s, double degPerS);       // −180 … 180
void setStageElevation(AppState& s, double degrees);  // −60 … 60; the 3D camera's pitch follows
// Once a frame: the stage turns (both views: the 3D camera's yaw turns with it).
void advanceStage(AppState& s, double seconds);

// [SECTION] The quiz (ui/app/quiz.h)
void quizStart(AppState& s, const StaircaseOptions& options);
void quizAnswer(AppState& s, WalkDirection answer);
void quizStop(AppState& s);
// trial,noise_dots,shown,answered,correct,reversal rows (core's quizCsv), written atomically.
void saveQuizCsv(AppState& s, const std::filesystem::path& path);

// [SECTION] The audience window (ui/app/audience.h)
void setAudienceOpen(AppState& s, bool open);
void setAudienceSize(AppState& s, int width, int height);  // 320×240 … 7680×4320
void setAudienceTheme(AppState& s, const std::string& name);  // "dark", "projector"
void setAudienceViews(AppState& s, const std::string& name);  // "both", "input", "reconstruction"
// A PNG of the audience window's next frame; throws when it is not open.
void requestAudiencePng(AppState& s, const std::filesystem::path& path);

// [SECTION] The walker as a web page (core/teaching/html_walker.h)
// The 2D view's walker as one self-contained HTML file, framed as the viewer frames its 2D
// view, at the stage's view, phase, direction and progression.
void exportWalkerHtml(AppState& s, const std::filesystem::path& path);

}  // namespace actions
}  // namespace ew::ui
