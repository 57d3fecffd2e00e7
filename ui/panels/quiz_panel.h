#pragma once
// The quiz window (ui/app/quiz.h): its settings and Start, then each trial's question with
// Left / Right (a small window over the 3D view, which the quiz leaves empty), then the
// staircase plotted (the noise of every trial, the answers, the reversals and the threshold)
// and Save CSV. Shown in presentation mode too.

namespace ew::ui {

struct AppState;
struct FrameContext;

struct QuizPanel {
  bool wasRunning = false;  // last frame: a quiz ran (its end resizes the window for the plot)
  void draw(AppState& s, const FrameContext& ctx);
};

}  // namespace ew::ui
