#pragma once
// Panels live in fixed windows laid out by the app (ui/app/layout.h): no moving, no
// resizing, no saved .ini. A rectangle in screen pixels.

#include <imgui.h>

namespace ew::ui {

struct PanelRect {
  ImVec2 pos{0.0f, 0.0f};
  ImVec2 size{0.0f, 0.0f};
};

// ImGui::Begin at a fixed place; always pair with ImGui::End().
inline bool beginPanel(const char* title, const PanelRect& r, ImGuiWindowFlags extra = 0) {
  ImGui::SetNextWindowPos(r.pos);
  ImGui::SetNextWindowSize(r.size);
  return ImGui::Begin(title, nullptr,
                      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                          ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                          ImGuiWindowFlags_NoBringToFrontOnFocus | extra);
}

}  // namespace ew::ui
