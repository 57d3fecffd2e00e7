#include "ui/panels/help_panel.h"

#include <imgui.h>

#include <algorithm>
#include <span>

#include "ui/app/app_state.h"
#include "ui/app/shortcuts.h"

namespace ew::ui {

namespace {

struct Shortcut {
  const char* keys;
  const char* what;
};

constexpr Shortcut kMouse[] = {
    {"drag (3D view)", "orbit the camera"},
    {"right- or middle-drag", "pan"},
    {"wheel", "zoom"},
    {"double-click", "reset the camera"},
    {"the α dial (F5)", "click or drag: the camera of the 2D view, seen from above"},
    {"click (video, marking)", "place the joint asked for; drag a mark or a tracked joint to correct it"},
    {"wheel / right-drag (2D view of a video or clip)", "magnify about the cursor / move; right double-click: whole"},
    {"hover a plot", "read the values at the cursor"},
};

template <class Row>
void table(const char* id, std::span<const Row> rows, float keyWidth) {
  if (ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_PadOuterX)) {
    ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed, keyWidth);
    ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
    for (const Row& row : rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + keyWidth);
      ImGui::TextColored(ImVec4(1.0f, 0.62f, 0.26f, 1.0f), "%s", row.keys);
      ImGui::PopTextWrapPos();
      ImGui::TableNextColumn();
      ImGui::TextWrapped("%s", row.what);
    }
    ImGui::EndTable();
  }
}

}  // namespace

void HelpPanel::draw(AppState& s, const FrameContext& ctx) {
  if (!open) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  // As wide as the keys' names need, and no taller than the window: the rest scrolls.
  const float width = std::min(680.0f * ctx.scale, 0.96f * display.x);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, 0.92f * display.y));
  ImGui::SetNextWindowBgAlpha(1.0f);
  if (ImGui::Begin("Keyboard and mouse (F1)", &open,
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoResize |
                       ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize)) {
    if (s.fonts.large) ImGui::PushFont(s.fonts.large);
    ImGui::TextUnformatted("Keyboard");
    if (s.fonts.large) ImGui::PopFont();
    // Every key, from the table the frame loop answers them from (ui/app/shortcuts.h).
    table("keys", shortcutRows(), 0.36f * width);
    ImGui::Spacing();
    if (s.fonts.large) ImGui::PushFont(s.fonts.large);
    ImGui::TextUnformatted("Mouse");
    if (s.fonts.large) ImGui::PopFont();
    table("mouse", std::span<const Shortcut>(kMouse), 0.36f * width);
    ImGui::Spacing();
    ImGui::TextDisabled("Header: Export… (PNG, video, CSV, BVH, model) · Analysis · Tour");
  }
  ImGui::End();
}

}  // namespace ew::ui
