#include "ui/panels/notice_panel.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <string>
#include <vector>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"

namespace ew::ui {

namespace {

// The banner keeps its own dark colours in every theme, so its text colours are fixed too.
const ImVec4 kErrorBg{0.23f, 0.07f, 0.09f, 1.0f};
const ImVec4 kErrorAccent{1.0f, 0.45f, 0.5f, 1.0f};
const ImVec4 kWarningBg{0.22f, 0.16f, 0.05f, 1.0f};
const ImVec4 kWarningAccent{0.98f, 0.8f, 0.35f, 1.0f};
const ImVec4 kDetailText{0.95f, 0.93f, 0.93f, 1.0f};
const ImVec4 kKeptText{0.62f, 0.88f, 0.8f, 1.0f};
constexpr int kMaxDetailLines = 6;  // longer reasons scroll

float buttonWidth(const char* label) {
  return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

}  // namespace

void NoticePanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& area) {
  if (!s.jobs.notice) return;
  const OpenNotice n = *s.jobs.notice;  // a button below may replace or clear it
  const ImVec4 accent = n.error ? kErrorAccent : kWarningAccent;
  const float margin = 8.0f * ctx.scale;
  const float width = std::max(area.size.x - 2.0f * margin, 240.0f * ctx.scale);
  ImGui::SetNextWindowPos(ImVec2(area.pos.x + margin, area.pos.y + 0.5f * margin),
                          ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
  ImGui::PushStyleColor(ImGuiCol_WindowBg, n.error ? kErrorBg : kWarningBg);
  ImGui::PushStyleColor(ImGuiCol_Border, accent);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, std::max(1.0f, 1.5f * ctx.scale));
  const bool shown =
      ImGui::Begin("##open_notice", nullptr,
                   ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                       ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                       ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize |
                       ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  ImGui::PopStyleVar();
  ImGui::PopStyleColor(2);
  if (shown) {
    // A new notice comes in front of the floating windows once (the Data window it came from).
    if (n.serial != frontSerial) {
      ImGui::BringWindowToDisplayFront(ImGui::GetCurrentWindow());
      frontSerial = n.serial;
    }
    const ImGuiStyle& style = ImGui::GetStyle();
    const float contentW = width - 2.0f * style.WindowPadding.x;
    // Title, then the buttons on the right (or below it when it is long).
    std::vector<const char*> buttons;
    if (n.canRetry) buttons.push_back("Retry");
    const bool nothingLoaded = !s.doc.population && !s.jobs.busy();
    if (n.error && nothingLoaded) buttons.push_back("Open the synthetic default");
    buttons.push_back("Dismiss");
    float buttonsW = 0.0f;
    for (const char* b : buttons) buttonsW += buttonWidth(b) + style.ItemSpacing.x;
    if (s.fonts.large) ImGui::PushFont(s.fonts.large);
    const float titleW = ImGui::CalcTextSize(n.title.c_str()).x;
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + contentW);
    ImGui::TextColored(accent, "%s", n.title.c_str());
    ImGui::PopTextWrapPos();
    if (s.fonts.large) ImGui::PopFont();
    if (titleW + buttonsW <= contentW) {
      ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - buttonsW + style.ItemSpacing.x);
    }
    std::string clicked;
    for (std::size_t i = 0; i < buttons.size(); ++i) {
      if (i > 0) ImGui::SameLine();
      if (ImGui::Button(buttons[i])) clicked = buttons[i];
    }

    // Why, in full (scrolling past kMaxDetailLines lines), then what is still shown.
    ImGui::PushStyleColor(ImGuiCol_Text, kDetailText);
    const float detailH = ImGui::CalcTextSize(n.detail.c_str(), nullptr, false, contentW).y;
    const float maxH = static_cast<float>(kMaxDetailLines) * ImGui::GetTextLineHeightWithSpacing();
    if (!n.detail.empty() && detailH > maxH) {
      ImGui::BeginChild("##detail", ImVec2(contentW, maxH));
      ImGui::TextWrapped("%s", n.detail.c_str());
      ImGui::EndChild();
    } else if (!n.detail.empty()) {
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + contentW);
      ImGui::TextUnformatted(n.detail.c_str());
      ImGui::PopTextWrapPos();
    }
    ImGui::PopStyleColor();
    if (n.fullText != n.detail && !n.fullText.empty() && ImGui::IsItemHovered()) {
      ImGui::SetTooltip("%s", n.fullText.c_str());
    }
    if (!n.kept.empty()) {
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + contentW);
      ImGui::TextColored(kKeptText, "%s", n.kept.c_str());
      ImGui::PopTextWrapPos();
    }
    ImGui::Dummy(ImVec2(contentW, 0.0f));  // the banner spans the views even for a short message

    if (clicked == "Retry") {
      actions::dismissNotice(s);
      actions::open(s, n.retryPaths);
    } else if (clicked == "Open the synthetic default") {
      actions::dismissNotice(s);
      actions::open(s, {});
    } else if (clicked == "Dismiss") {
      actions::dismissNotice(s);
    }
  }
  ImGui::End();
}

}  // namespace ew::ui
