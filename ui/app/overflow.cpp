#include "ui/app/overflow.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <string>

namespace ew::ui {

std::vector<std::pair<std::string, float>> windowsCutOnTheRight() {
  constexpr ImGuiWindowFlags kTransient = ImGuiWindowFlags_Tooltip | ImGuiWindowFlags_Popup |
                                          ImGuiWindowFlags_ChildMenu | ImGuiWindowFlags_HorizontalScrollbar |
                                          ImGuiWindowFlags_AlwaysHorizontalScrollbar;
  std::vector<std::pair<std::string, float>> cut;
  for (const ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
    if (!w->Active || w->Hidden || (w->Flags & kTransient)) continue;
    // ImGui clips a window's content half its padding inside the border: what reaches past
    // that is not seen.
    // (The views' images fill their windows to the edge, past the clip rectangle's border.)
    const float clipRight = std::max(w->InnerClipRect.Max.x, w->WorkRect.Max.x);
    const float reach = w->DC.CursorMaxPos.x;
    if (reach > clipRight + 1.0f) cut.emplace_back(w->Name, reach - clipRight);
    // A window past the screen's right or bottom edge (a menu opened near it) hides that part.
    const ImVec2 screen = ImGui::GetIO().DisplaySize;
    const float pastRight = w->Pos.x + w->Size.x - screen.x, pastBottom = w->Pos.y + w->Size.y - screen.y;
    if (pastRight > 1.0f) cut.emplace_back(std::string(w->Name) + " (off the screen)", pastRight);
    if (pastBottom > 1.0f) cut.emplace_back(std::string(w->Name) + " (off the screen's bottom)", pastBottom);
    // A window without a scroll bar hides what goes past its bottom.
    const float clipBottom = std::max(w->InnerClipRect.Max.y, w->WorkRect.Max.y);
    if ((w->Flags & ImGuiWindowFlags_NoScrollbar) && w->DC.CursorMaxPos.y > clipBottom + 1.0f)
      cut.emplace_back(std::string(w->Name) + " (bottom)", w->DC.CursorMaxPos.y - clipBottom);
  }
  // A table's cells clip their content at the column's edge, unseen by its window's reach, and
  // its headings end in an ellipsis. (A table that scrolls sideways shows the rest when
  // scrolled, as a window with a horizontal scroll bar does.)
  ImGuiContext& g = *ImGui::GetCurrentContext();
  for (int i = 0; i < g.Tables.GetMapSize(); ++i) {
    const ImGuiTable* t = g.Tables.TryGetMapData(i);
    if (!t || t->LastFrameActive != g.FrameCount || !t->OuterWindow || (t->Flags & ImGuiTableFlags_ScrollX)) continue;
    for (int c = 0; c < t->ColumnsCount; ++c) {
      const ImGuiTableColumn& col = t->Columns[c];
      if (!col.IsEnabled || !col.IsVisibleX) continue;
      const float reach = std::max({col.ContentMaxXUnfrozen, col.ContentMaxXFrozen, col.ContentMaxXHeadersIdeal});
      const float over = reach - col.ClipRect.Max.x;
      if (over > 1.0f)
        cut.emplace_back(std::string(t->OuterWindow->Name) + " / table " + std::to_string(t->ID) + " column " +
                             std::to_string(c),
                         over);
    }
  }
  return cut;
}

}  // namespace ew::ui
