#pragma once
// A side panel's section heading: a little space, the title in muted blue, a rule.

#include <imgui.h>

namespace ew::ui {

inline void sectionTitle(const char* text) {
  ImGui::Spacing();
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.55f, 0.62f, 0.72f, 1.0f));
  ImGui::TextUnformatted(text);
  ImGui::PopStyleColor();
  ImGui::Separator();
}

}  // namespace ew::ui
