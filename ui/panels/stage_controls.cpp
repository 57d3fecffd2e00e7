#include "ui/panels/stage_controls.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <exception>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/widgets/flow.h"

namespace ew::ui {

namespace {

// A toggle labelled with its key ("inverted (I)"), calling `apply` when clicked.
// The first of a row starts a line; the others follow while they fit.
template <class Apply>
void toggle(const char* label, bool on, Apply apply, bool first = false) {
  if (!first) sameLineOrWrap(toggleWidth(label));
  bool value = on;
  if (checkboxWrapped(label, &value)) apply(value);
}

// Runs a control's action; what it refuses goes to the log (the controls' ranges keep to the
// actions', so this is a guard, not a path a user takes).
template <class Apply>
void guarded(AppState& s, Apply apply) {
  try {
    apply();
  } catch (const std::exception& e) {
    s.log.error(e.what());
  }
}

}  // namespace

void drawStageControls(AppState& s) {
  const StageFeature& stage = s.stage;
  const BiologicalMotionOptions& d = stage.display;
  toggle("inverted (I)", d.inverted, [&](bool on) { actions::setInverted(s, on); }, true);
  toggle("backwards (W)", d.backwards, [&](bool on) { actions::setBackwards(s, on); });
  toggle("overground (O)", d.translating, [&](bool on) { actions::setTranslating(s, on); });
  toggle("depth-reversed beside (D)", stage.depthReversed, [&](bool on) { actions::setDepthReversed(s, on); });

  int scramble = static_cast<int>(d.scramble);
  const char* scrambles[] = {"intact", "phase-scrambled", "position-scrambled"};
  ImGui::TextDisabled("dots (X)");
  if (radioRow(scrambles, 3, &scramble)) actions::setScramble(s, static_cast<Scramble>(scramble));

  toggle("noise dots (K)", d.maskDots > 0, [&](bool) { actions::toggleMask(s); }, true);
  int dots = stage.maskSlider;
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderInt("##mask_dots", &dots, 1, 1000, "%d noise dots", ImGuiSliderFlags_AlwaysClamp |
                                                                            ImGuiSliderFlags_Logarithmic))
    guarded(s, [&] {
      s.stage.maskSlider = dots;
      if (s.stage.display.maskDots > 0) actions::setMaskDots(s, dots);
    });
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("noise dots that each move like one of the walker's dots");

  toggle("limited lifetime (L)", d.dotLifetimeS > 0.0, [&](bool) { actions::toggleLifetime(s); }, true);
  if (d.dotLifetimeS > 0.0) {
    float life = static_cast<float>(d.dotLifetimeS);
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderFloat("##lifetime", &life, 0.05f, 2.0f, "each dot lives %.2f s", ImGuiSliderFlags_AlwaysClamp))
      guarded(s, [&] { actions::setDotLifetime(s, life); });
  }

  toggle("turning stage (T)", stage.turning, [&](bool on) { actions::setTurning(s, on); }, true);
  float rate = static_cast<float>(stage.turnDegPerS);
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderFloat("##turn_rate", &rate, -90.0f, 90.0f, "turns %.0f°/s", ImGuiSliderFlags_AlwaysClamp))
    guarded(s, [&] { actions::setTurnRate(s, std::round(rate)); });
  float elevation = static_cast<float>(stage.elevationDeg);
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderFloat("##elevation", &elevation, -60.0f, 60.0f, "elevation %.0f°", ImGuiSliderFlags_AlwaysClamp))
    guarded(s, [&] { actions::setStageElevation(s, std::round(elevation)); });
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("> 0 looks down on the walker (both views)");

  toggle("audience window (A)", s.audience.open, [&](bool on) { actions::setAudienceOpen(s, on); }, true);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("a second window showing only the stage: drag it to the projector");

  const bool any = stage.shown();
  const bool quizzing = s.quiz.running();
  const int clicked = buttonRow({{"all off (0)", any}, {quizzing ? "stop quiz (Q)" : "quiz… (Q)", s.doc.mode != Mode::Clip}});
  if (clicked == 0) actions::resetStage(s);
  if (clicked == 1)
    guarded(s, [&] {
      if (quizzing)
        actions::quizStop(s);
      else
        actions::quizStart(s, s.quiz.options);
    });
  if (s.doc.mode == Mode::Clip) textDisabledWrapped("a clip or a video is shown as filmed: the displays apply to walkers");
}

}  // namespace ew::ui
