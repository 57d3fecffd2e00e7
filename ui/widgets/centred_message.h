#pragma once
// A view's message where it has nothing to draw ("nothing loaded", "type the image's size…"):
// muted, in the middle of the view, wrapped at 0.8 of its width so that a narrow view (a small
// window, a large UI scale) shows it whole.

#include <imgui.h>

namespace ew::ui {

// Draws `msg` centred on the view at p0 of `size`; returns the height it took.
inline float drawCentredMessage(ImDrawList* dl, ImVec2 p0, ImVec2 size, const char* msg) {
  const float wrap = 0.8f * size.x;
  const ImVec2 ts = ImGui::CalcTextSize(msg, nullptr, false, wrap);
  dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(p0.x + 0.5f * (size.x - ts.x), p0.y + 0.5f * size.y),
              IM_COL32(160, 168, 180, 255), msg, nullptr, wrap);
  return ts.y;
}

}  // namespace ew::ui
