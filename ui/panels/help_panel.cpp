#include "ui/panels/help_panel.h"

#include <imgui.h>

#include <iterator>

#include "ui/app/app_state.h"

namespace ew::ui {

namespace {

struct Shortcut {
  const char* keys;
  const char* what;
};

constexpr Shortcut kKeys[] = {
    {"Space", "play / pause"},
    {"← / →", "step the gait phase by one 1/60 s frame"},
    {"P", "point-light display on / off (dots only)"},
    {"F1", "this help"},
    {"F12", "save a PNG of the window (Export… sets the folder)"},
    {"Esc", "close this help / end the tour"},
};

constexpr Shortcut kMouse[] = {
    {"drag (3D view)", "orbit the camera"},
    {"right- or middle-drag", "pan"},
    {"wheel", "zoom"},
    {"double-click", "reset the camera"},
    {"hover a plot", "read the values at the cursor"},
};

void table(const char* id, const Shortcut* rows, int n, float keyWidth) {
  if (ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_PadOuterX)) {
    ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed, keyWidth);
    ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
    for (int i = 0; i < n; ++i) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(ImVec4(1.0f, 0.62f, 0.26f, 1.0f), "%s", rows[i].keys);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(rows[i].what);
    }
    ImGui::EndTable();
  }
}

}  // namespace

void HelpPanel::draw(AppState& s, const FrameContext& ctx) {
  if (!open) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSize(ImVec2(600.0f * ctx.scale, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(1.0f);
  if (ImGui::Begin("Keyboard and mouse (F1)", &open,
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize |
                       ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize)) {
    if (s.fonts.large) ImGui::PushFont(s.fonts.large);
    ImGui::TextUnformatted("Keyboard");
    if (s.fonts.large) ImGui::PopFont();
    table("keys", kKeys, static_cast<int>(std::size(kKeys)), 190.0f * ctx.scale);
    ImGui::Spacing();
    if (s.fonts.large) ImGui::PushFont(s.fonts.large);
    ImGui::TextUnformatted("Mouse");
    if (s.fonts.large) ImGui::PopFont();
    table("mouse", kMouse, static_cast<int>(std::size(kMouse)), 190.0f * ctx.scale);
    ImGui::Spacing();
    ImGui::TextDisabled("Header: Export… (PNG, video, CSV, BVH, model) · Analysis · Tour");
  }
  ImGui::End();
}

}  // namespace ew::ui
