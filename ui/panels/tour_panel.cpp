#include "ui/panels/tour_panel.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/tour.h"
#include "ui/widgets/flow.h"

namespace ew::ui {

namespace {

// The card's height with its text at `wrapWidth`: the title bar, the title, the text, the dots
// and buttons, and the spacing between them.
float unfoldedHeight(const AppState& s, const TourStep& st, float wrapWidth) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float titleLine = s.fonts.large ? s.fonts.large->FontSize : ImGui::GetTextLineHeight();
  const float titleH = titleLine * std::ceil(ImGui::CalcTextSize(st.title, nullptr, false, wrapWidth).y /
                                             ImGui::GetTextLineHeight());
  return ImGui::GetFrameHeight() + 2.0f * style.WindowPadding.y + titleH +
         ImGui::CalcTextSize(st.text, nullptr, false, wrapWidth).y + ImGui::GetFrameHeight() +
         6.0f * style.ItemSpacing.y;
}

}  // namespace

// Whether the step has the analysis window open and the card with its text would leave that
// window less than 0.4 of the screen's height (the window sits between the header and the card).
bool TourPanel::textCrowdsTheWindow(const AppState& s, const TourStep& st, float wrapWidth, float scale) const {
  if (!s.panels.analysis.open) return false;
  const float screenH = ImGui::GetIO().DisplaySize.y;
  const float cardBottom = (bottom > 0.0f ? bottom : screenH) - 16.0f * scale;
  const float room = cardBottom - unfoldedHeight(s, st, wrapWidth) - 80.0f * scale;
  return room < 0.4f * screenH;
}

void TourPanel::draw(AppState& s, const FrameContext& ctx) {
  if (!active) return;
  const auto steps = tourSteps();
  const auto& st = steps[static_cast<std::size_t>(step)];
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float margin = 16.0f * ctx.scale;
  // Beside the drawer, not over it: the steps point at its panels (and open the one they name).
  const float areaLeft = left + margin, areaW = display.x - margin - areaLeft;
  float w = std::min({display.x * 0.46f, 760.0f * ctx.scale, areaW});
  // A text that would stand taller than 0.4 of the window at that width gets the whole width
  // beside the drawer, so that the card stays clear of the header (1024×768 at UI scale 2).
  const float pad = 2.0f * ImGui::GetStyle().WindowPadding.x;
  if (ImGui::CalcTextSize(st.text, nullptr, false, w - pad).y > 0.4f * display.y) w = std::max(w, areaW);
  const bool foldable = textCrowdsTheWindow(s, st, w - pad, ctx.scale);
  folded = foldable && unfoldedStep != step;
  ImGui::SetNextWindowSize(ImVec2(w, 0.0f), ImGuiCond_Always);
  const float y = (bottom > 0.0f ? bottom : display.y) - margin;
  switch (st.anchor) {
    case TourAnchor::BottomCentre:
      ImGui::SetNextWindowPos(ImVec2(std::max(display.x * 0.5f, areaLeft + 0.5f * w), y), ImGuiCond_Always,
                              ImVec2(0.5f, 1.0f));
      break;
    case TourAnchor::BottomLeft:
      ImGui::SetNextWindowPos(ImVec2(areaLeft, y), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
      break;
    case TourAnchor::BottomRight:
      ImGui::SetNextWindowPos(ImVec2(display.x - margin, y), ImGuiCond_Always, ImVec2(1.0f, 1.0f));
      break;
  }
  ImGui::SetNextWindowBgAlpha(1.0f);
  bool open = true;
  char title[96];
  std::snprintf(title, sizeof title, "Guided tour · step %d of %zu###tour", step + 1, steps.size());
  if (ImGui::Begin(title, &open,
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize |
                       ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoScrollbar)) {
    // Above every other window (the analysis window a step opens), without taking focus.
    ImGui::BringWindowToDisplayFront(ImGui::GetCurrentWindow());
    lastHeight = ImGui::GetWindowHeight();
    // The title wraps as the text does (a long one on a narrow card).
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + w - 2.0f * ImGui::GetStyle().WindowPadding.x);
    if (s.fonts.large) ImGui::PushFont(s.fonts.large);
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.62f, 0.26f, 1.0f));
    ImGui::TextUnformatted(st.title);
    ImGui::PopStyleColor();
    if (s.fonts.large) ImGui::PopFont();
    ImGui::Spacing();
    if (!folded) ImGui::TextUnformatted(st.text);
    ImGui::PopTextWrapPos();
    if (foldable && !folded) {
      if (ImGui::SmallButton("Hide the text")) unfoldedStep = -1;
    }
    ImGui::Spacing();
    const float r = 5.0f * ctx.scale, h = ImGui::GetFrameHeight();
    // Progress dots (folded: the text's switch instead; the title bar counts the steps), then
    // the buttons on the right.
    float leadW = static_cast<float>(steps.size()) * 4.0f * r + 8.0f * ctx.scale;
    if (folded) {
      leadW = buttonWidth("Show the text");
      const ImVec2 at = ImGui::GetCursorPos();
      if (ImGui::Button("Show the text")) unfoldedStep = step;
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("folded so that the window this step opened has room; unfolded, it covers it");
      ImGui::SetCursorPos(at);  // the buttons go on this row, as beside the dots
    } else {
      ImGui::Separator();
      ImDrawList* dl = ImGui::GetWindowDrawList();
      const ImVec2 c = ImGui::GetCursorScreenPos();
      for (int i = 0; i < static_cast<int>(steps.size()); ++i) {
        const ImVec2 centre{c.x + r + static_cast<float>(i) * 4.0f * r, c.y + 0.5f * h};
        if (i == step) {
          dl->AddCircleFilled(centre, r, IM_COL32(255, 158, 66, 255));
        } else {
          dl->AddCircle(centre, r, ImGui::GetColorU32(ImGuiCol_TextDisabled), 0, 1.5f * ctx.scale);
        }
      }
    }
    try {
      // Buttons as wide as 110 px × scale allows beside the dots; narrower down to their labels';
      // on a row of their own below the dots when even that does not fit. Three gaps: after
      // the dots (or the text's switch) and between the buttons.
      const ImGuiStyle& style = ImGui::GetStyle();
      const float contentW = ImGui::GetContentRegionAvail().x;
      const float minW = ImGui::CalcTextSize("End tour").x + 2.0f * style.FramePadding.x;
      const float bw = std::clamp((contentW - leadW - 3.0f * style.ItemSpacing.x) / 3.0f, minW, 110.0f * ctx.scale);
      if (leadW + 3.0f * bw + 3.0f * style.ItemSpacing.x > contentW) ImGui::Dummy(ImVec2(leadW, h));
      ImGui::SetCursorPosX(ImGui::GetWindowContentRegionMax().x - 3.0f * bw - 2.0f * style.ItemSpacing.x);
      ImGui::BeginDisabled(step == 0);
      if (ImGui::Button("Back", ImVec2(bw, 0))) actions::tourBack(s);
      ImGui::EndDisabled();
      ImGui::SameLine();
      const bool last = step + 1 >= static_cast<int>(steps.size());
      if (ImGui::Button(last ? "Finish" : "Next", ImVec2(bw, 0))) actions::tourNext(s);
      ImGui::SameLine();
      if (ImGui::Button("End tour", ImVec2(bw, 0))) actions::tourEnd(s);
    } catch (const std::exception& e) {
      s.log.error(e.what());
    }
  }
  ImGui::End();
  if (!open) actions::tourEnd(s);
}

}  // namespace ew::ui
