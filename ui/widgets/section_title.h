#pragma once
// A side panel's section heading: a little space, the title in muted blue, a rule.

#include <imgui.h>

namespace ew::ui {

inline void sectionTitle(const char* text) {
  ImGui::Spacing();
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.62f, 0.72f, 1.0f));
  ImGui::PushTextWrapPos(0.0f);  // a long title wraps at the panel's edge
  ImGui::TextUnformatted(text);
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
  ImGui::Separator();
}

}  // namespace ew::ui
