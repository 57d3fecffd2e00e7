#include "ui/panels/log_panel.h"

#include "ui/app/app_state.h"
#include "ui/app/theme.h"

namespace ew::ui {

void LogPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "Log", rect)) {
    ImGui::Checkbox("info", &showInfo);
    ImGui::Separator();
    ImGui::BeginChild("##entries");
    for (const auto& e : s.log.entries()) {
      if (e.level == LogLevel::Info && !showInfo) continue;
      const ImVec4 colour = e.level == LogLevel::Error     ? ImVec4(1.0f, 0.45f, 0.5f, 1.0f)
                            : e.level == LogLevel::Warning ? warningTextColour()
                                                           : ImGui::GetStyleColorVec4(ImGuiCol_Text);
      ImGui::TextDisabled("%6.1f", e.timeS);
      ImGui::SameLine();
      ImGui::PushStyleColor(ImGuiCol_Text, colour);
      ImGui::TextWrapped("%s", e.text.c_str());
      ImGui::PopStyleColor();
    }
    if (s.log.entries().size() != seenEntries) {
      seenEntries = s.log.entries().size();
      ImGui::SetScrollHereY(1.0f);
    }
    ImGui::EndChild();
  }
  ImGui::End();
}

}  // namespace ew::ui
