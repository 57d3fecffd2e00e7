#include "ui/panels/presentation_bar.h"

#include <algorithm>
#include <cmath>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/panels/playback_panel.h"
#include "ui/panels/stage_controls.h"
#include "ui/widgets/angle_dial.h"

namespace ew::ui {

namespace {

// A button as tall as the row, so that it can be hit from the back of a lecture hall too.
bool rowButton(const char* label, float width, float height) { return ImGui::Button(label, ImVec2(width, height)); }

void drawAngle(AppState& s, float rowH, float sliderW) {
  double alpha = s.doc.recon.alphaDeg;
  if (angleDial("##alpha_dial", alpha, 0.5f * rowH)) actions::setAngle(s, alpha);
  ImGui::SameLine();
  float slider = static_cast<float>(s.doc.recon.alphaDeg);
  ImGui::SetNextItemWidth(sliderW);
  if (ImGui::SliderFloat("##alpha", &slider, -180.0f, 180.0f,
                         "α = %.0f°", ImGuiSliderFlags_AlwaysClamp))
    actions::setAngle(s, std::round(slider));
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("view angle of the 2D input ([ ] ±1°, Shift ±15°)");
}

// The classroom displays over the views, opened above the bar (keys do the same: F1 lists them).
void drawDisplaysMenu(AppState& s, float scale) {
  const ImVec2 barPadding = ImGui::GetStyle().FramePadding;
  ImGui::PopStyleVar();  // the menu's items at their usual height, not the bar's
  ImGui::SetNextWindowSize(ImVec2(std::min(420.0f * scale, ImGui::GetMainViewport()->Size.x - 20.0f * scale), 0.0f));
  if (ImGui::BeginPopup("##displays")) {
    drawStageControls(s);
    ImGui::EndPopup();
  }
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, barPadding);
}

}  // namespace

void PresentationBar::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "##presentation_bar", rect, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar)) {
    const ImGuiStyle& style = ImGui::GetStyle();
    // (A frame fits: the bar is 0.12 of the window at least, 46 UI pixels in the smallest window
    // the UI scale allows, kMinLogicalWindowH.)
    const float rowH = std::floor(ImGui::GetContentRegionAvail().y);
    // Every item of the row as tall as the row, with its text in the middle (the same padding
    // for all, so that ImGui's baseline alignment leaves the row one row high).
    const float framePad = std::max(0.0f, 0.5f * (rowH - ImGui::GetFontSize()));
    ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(style.FramePadding.x, framePad));
    auto& p = s.view.playback;
    if (rowButton(p.playing ? "||##play" : ">##play", 1.6f * rowH, rowH)) p.playing = !p.playing;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("play / pause (space)");
    ImGui::SameLine(0.0f, 2.0f * style.ItemSpacing.x);
    const char* leave = "Leave (F5)";
    const float leaveW = ImGui::CalcTextSize(leave).x + 2.0f * style.FramePadding.x;
    const char* displays = "Displays";
    const float displaysW = ImGui::CalcTextSize(displays).x + 2.0f * style.FramePadding.x;
    // The dial and the slider take what the buttons leave; the slider stops at a readable length.
    const float sliderW = std::min(ImGui::GetContentRegionAvail().x - rowH - leaveW - displaysW -
                                       5.0f * style.ItemSpacing.x,
                                   900.0f * ctx.scale);
    // A clip or a video is seen from where it was filmed: the bar scrubs its frames instead.
    if (playsFrames(s)) {
      ImGui::SetNextItemWidth(std::max(80.0f * ctx.scale, sliderW) + rowH + style.ItemSpacing.x);
      drawFrameSlider(s, false);
    } else {
      drawAngle(s, rowH, std::max(80.0f * ctx.scale, sliderW));
    }
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - leaveW - displaysW - style.ItemSpacing.x);
    if (rowButton(displays, displaysW, rowH)) ImGui::OpenPopup("##displays");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("the classroom displays: inverted, scrambled, masked, turning … (keys in F1)");
    drawDisplaysMenu(s, ctx.scale);
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - leaveW);
    if (rowButton(leave, leaveW, rowH)) actions::setPresentation(s, false);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to the panels (F5 or Esc)");
    ImGui::PopStyleVar();
  }
  ImGui::End();
}

}  // namespace ew::ui
