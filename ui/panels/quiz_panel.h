#pragma once
// The quiz window (ui/app/quiz.h): its settings and Start, then each trial's question with
// Left / Right, then the staircase plotted (the noise of every trial, the answers, the
// reversals and the threshold) and Save CSV. Floats over the 3D view, which the quiz leaves
// empty; shown in presentation mode too.

namespace ew::ui {

struct AppState;
struct FrameContext;

struct QuizPanel {
  void draw(AppState& s, const FrameContext& ctx);
};

}  // namespace ew::ui
