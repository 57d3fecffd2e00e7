#include "ui/panels/quiz_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <vector>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/panels/panel_window.h"
#include "ui/widgets/flow.h"
#include "ui/widgets/plot.h"

namespace ew::ui {

namespace {

void drawSettings(AppState& s, float scale) {
  StaircaseOptions& o = s.quiz.options;
  const float field = 110.0f * scale;
  ImGui::SetNextItemWidth(field);
  ImGui::InputInt("noise dots at the start", &o.startDots, 10, 50);
  ImGui::SetNextItemWidth(field);
  ImGui::InputInt("step (dots)", &o.stepDots, 1, 10);
  ImGui::SetNextItemWidth(field);
  ImGui::InputInt("reversals", &o.reversals, 1, 4);
  o.startDots = std::clamp(o.startDots, 0, kMaxMaskDots);
  o.stepDots = std::clamp(o.stepDots, 1, 500);
  o.reversals = std::clamp(o.reversals, 2, 60);
  o.maxDots = std::max(kMaxMaskDots / 2, o.startDots);
  o.averagedReversals = std::min(o.averagedReversals, o.reversals);
  textDisabledWrapped("Two right answers in a row add noise, one wrong answer takes it away: the noise "
                      "settles where the room is right 70.7 % of the time (Levitt 1971).");
}

// The noise of every trial, its answer (right: filled dots of the first series; wrong: of the
// second) and the threshold as a line.
void drawStaircasePlot(const Staircase& q, float scale) {
  const std::vector<QuizTrial>& trials = q.trials();
  std::vector<double> x, noise, right, wrong, threshold;
  for (const QuizTrial& t : trials) {
    x.push_back(t.number);
    noise.push_back(t.noiseDots);
    right.push_back(t.correct ? static_cast<double>(t.noiseDots) : std::nan(""));
    wrong.push_back(t.correct ? std::nan("") : static_cast<double>(t.noiseDots));
  }
  const double level = q.thresholdDots();
  threshold.assign(x.size(), level);  // NaN (no line) before the first reversal
  const PlotSeries series[] = {
      {"noise dots", x, noise, IM_COL32(200, 205, 215, 255), 1.5f},
      {"right", x, right, IM_COL32(90, 220, 140, 255), 0.0f, false, true},
      {"wrong", x, wrong, IM_COL32(255, 90, 120, 255), 0.0f, false, true},
      {"threshold", x, threshold, IM_COL32(255, 170, 60, 255), 2.0f, true},
  };
  PlotSpec spec;
  spec.xLabel = "trial";
  spec.yLabel = "noise dots";
  spec.valueFormat = "%.0f";
  for (const QuizTrial& t : trials)
    if (t.reversal) spec.markers.push_back({static_cast<double>(t.number), "", IM_COL32(255, 255, 255, 60)});
  // What the window leaves under the plot: the Save / Start row and the status line.
  const float below = 2.0f * ImGui::GetFrameHeightWithSpacing();
  const float height = std::max(150.0f * scale, ImGui::GetContentRegionAvail().y - below);
  drawPlot("##staircase", ImVec2(ImGui::GetContentRegionAvail().x, height), spec, series, scale);
}

}  // namespace

void QuizPanel::draw(AppState& s, const FrameContext& ctx) {
  QuizFeature& quiz = s.quiz;
  if (!quiz.open) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // While it runs: a small window (the question's line and the two answers) at the bottom
  // right, over the 3D view the quiz leaves empty, never over the 2D view the room watches;
  // the plot once it is over, in a window as large as the screen allows.
  const bool running = quiz.running();
  const float pad = 10.0f * ctx.scale;
  // The 3D view the last frame laid out (the whole window's right before any frame).
  const PanelRect view = s.lastFrame.layout.reconstruction;
  const bool laidOut = view.size.x > 0.0f && view.size.y > 0.0f;
  const float viewRight = laidOut ? view.pos.x + view.size.x - pad : display.x - 2.0f * pad;
  const float viewBottom = laidOut ? view.pos.y + view.size.y - pad : display.y - 100.0f * ctx.scale;
  const float width = running ? (laidOut ? std::max(view.size.x - 2.0f * pad, 0.25f * display.x)
                                         : floatingExtent(display.x, 0.3f, 380.0f * ctx.scale, 40.0f * ctx.scale))
                              : floatingExtent(display.x, 0.36f, 420.0f * ctx.scale, 40.0f * ctx.scale);
  const float height = floatingExtent(display.y, 0.5f, 390.0f * ctx.scale, 120.0f * ctx.scale);
  // The large window once, when the quiz has just ended (or the window opens on a result).
  const ImGuiCond resize = running || wasRunning ? ImGuiCond_Always : ImGuiCond_Appearing;
  wasRunning = running;
  if (running)
    ImGui::SetNextWindowSize(ImVec2(width, 0.0f), resize);  // its height fits its lines
  else
    ImGui::SetNextWindowSize(ImVec2(width, height), resize);
  const ImVec2 corner = running ? ImVec2(viewRight, viewBottom)
                                : ImVec2(display.x - 2.0f * pad, std::max(display.y - 100.0f * ctx.scale,
                                                                          std::min(display.y, height + pad)));
  ImGui::SetNextWindowPos(corner, resize, ImVec2(1.0f, 1.0f));
  // (The title bar also holds the close button: a frame's height.)
  const char* title = fittingTitle("Quiz: which way is it walking?###quiz", "Quiz###quiz",
                                   width - ImGui::GetFrameHeight() - ImGui::GetStyle().ItemInnerSpacing.x);
  if (!ImGui::Begin(title, &quiz.open,
                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  const auto attempt = [&](auto apply) {
    try {
      apply();
    } catch (const std::exception& e) {
      quiz.status = e.what();
    }
  };
  if (quiz.running()) {
    const Staircase& q = *quiz.staircase;
    ImGui::TextWrapped("Trial %zu · %d noise dots · %d reversals of %d", q.trials().size() + 1, q.noiseDots(),
                       q.reversalCount(), q.options().reversals);
    const float half = 0.5f * (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x);
    const float tall = 2.2f * ImGui::GetFrameHeight();
    if (ImGui::Button("← Left", ImVec2(half, tall))) attempt([&] { actions::quizAnswer(s, WalkDirection::Left); });
    ImGui::SameLine();
    if (ImGui::Button("Right →", ImVec2(half, tall))) attempt([&] { actions::quizAnswer(s, WalkDirection::Right); });
    textDisabledWrapped("the room answers, you press ← or → · Q stops · the plot comes at the end");
  } else {
    if (quiz.staircase && !quiz.staircase->trials().empty()) {
      const Staircase& q = *quiz.staircase;
      const double level = q.thresholdDots();
      if (std::isfinite(level))
        ImGui::Text("%s after %zu trials: threshold %.0f noise dots", q.done() ? "Done" : "Stopped", q.trials().size(), level);
      else
        ImGui::Text("Stopped after %zu trials, before a reversal: no threshold yet", q.trials().size());
      drawStaircasePlot(q, ctx.scale);
      if (ImGui::Button("Save CSV")) {
        const auto& e = s.panels.exports;
        const std::filesystem::path path =
            std::filesystem::path(e.folder.data()) / (std::string(e.baseName.data()) + "-quiz.csv");
        attempt([&] { actions::saveQuizCsv(s, path); });
      }
      ImGui::SameLine();
    }
    if (ImGui::Button(quiz.staircase ? "Start again" : "Start")) attempt([&] { actions::quizStart(s, quiz.options); });
    if (ImGui::CollapsingHeader("Settings", quiz.staircase ? 0 : ImGuiTreeNodeFlags_DefaultOpen)) drawSettings(s, ctx.scale);
  }
  if (!quiz.status.empty()) textDisabledWrapped(quiz.status.c_str());
  ImGui::End();
}

}  // namespace ew::ui
