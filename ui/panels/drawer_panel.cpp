#include "ui/panels/drawer_panel.h"

#include <imgui.h>

#include <cctype>
#include <stdexcept>
#include <string>

#include "ui/app/app_state.h"

namespace ew::ui {

void DrawerPanel::draw(AppState& /*s*/, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "##drawer_tabs", rect, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar)) {
    // Tabs wrap onto more rows when the drawer is narrow; when the layout gave them too little
    // height for their rows (a narrow drawer at a large scale), a list of the panels instead.
    if (drawerTabsHeight(rect.size.x, ctx.scale) > rect.size.y + 0.5f) {
      ImGui::SetNextItemWidth(-1.0f);
      if (ImGui::BeginCombo("##drawer_panel", drawerTabName(active))) {
        for (DrawerTab tab : kDrawerTabs)
          if (ImGui::Selectable(drawerTabName(tab), tab == active)) active = tab;
        ImGui::EndCombo();
      }
      ImGui::End();
      return;
    }
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    bool first = true;
    for (DrawerTab tab : kDrawerTabs) {
      const char* name = drawerTabName(tab);
      const float w = ImGui::CalcTextSize(name).x + 2.0f * ImGui::GetStyle().FramePadding.x;
      if (!first) {
        ImGui::SameLine();
        if (ImGui::GetCursorScreenPos().x + w > right) ImGui::NewLine();
      }
      first = false;
      const bool selected = tab == active;
      if (selected) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
      if (ImGui::Button(name)) active = tab;
      if (selected) ImGui::PopStyleColor();
    }
  }
  ImGui::End();
}

DrawerTab drawerTabFromName(const std::string& name) {
  for (DrawerTab tab : kDrawerTabs) {
    std::string lower = drawerTabName(tab);
    for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (name == lower) return tab;
  }
  throw std::invalid_argument("unknown drawer tab '" + name + "' (subjects, controls, coefficients, errors, view, log)");
}

}  // namespace ew::ui
