#pragma once
// Panels live in fixed windows laid out by the app (ui/app/layout.h): no moving, no
// resizing, no saved .ini. A rectangle in screen pixels.

#include <imgui.h>

#include <algorithm>
#include <cstring>

#include "ui/render/backdrop.h"

namespace ew::ui {

struct PanelRect {
  ImVec2 pos{0.0f, 0.0f};
  ImVec2 size{0.0f, 0.0f};
};

// A floating window's first size along one side of the screen (`screen` px): `share` of it, at
// least `least` (the content's need at the UI scale, already scaled), and never closer than
// `margin` to the edges — so that a small window or a large UI scale gets most of the screen.
inline float floatingExtent(float screen, float share, float least, float margin) {
  return std::min(screen - margin, std::max(screen * share, least));
}

// `title`, or `shortTitle` where the title bar (`width` px) cannot show the title's visible part
// (before "###", which both must share). A long title cut mid-word reads as a mistake on a
// projector (the drawer at 1024 × 768).
inline const char* fittingTitle(const char* title, const char* shortTitle, float width) {
  const char* visibleEnd = std::strstr(title, "###");
  const float need = ImGui::CalcTextSize(title, visibleEnd).x + 2.0f * ImGui::GetStyle().FramePadding.x;
  return need <= width ? title : shortTitle;
}

// ImGui::Begin at a fixed place; always pair with ImGui::End(). The window's background
// is filled by the backdrop (a plain GL clear) rather than by ImGui, unless `extra` asks
// for no background at all.
inline bool beginPanel(Backdrop& backdrop, const char* title, const PanelRect& r, ImGuiWindowFlags extra = 0) {
  if (!(extra & ImGuiWindowFlags_NoBackground)) {
    const ImVec4 c = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
    backdrop.fill({r.pos.x, r.pos.y}, {r.size.x, r.size.y}, {c.x, c.y, c.z, c.w});
  }
  ImGui::SetNextWindowPos(r.pos);
  ImGui::SetNextWindowSize(r.size);
  return ImGui::Begin(title, nullptr,
                      ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                          ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus |
                          ImGuiWindowFlags_NoBackground | extra);
}

}  // namespace ew::ui
