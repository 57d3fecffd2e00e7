#include "ui/widgets/angle_dial.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace ew::ui {

namespace {

constexpr float kDegToRad = std::numbers::pi_v<float> / 180.0f;

// Screen offset of angle α on a circle of radius r (screen y points down; α = 0 at the bottom).
ImVec2 onRim(ImVec2 centre, float r, float alphaDeg) {
  const float a = alphaDeg * kDegToRad;
  return {centre.x + r * std::sin(a), centre.y + r * std::cos(a)};
}

void drawDial(ImDrawList* dl, ImVec2 c, float r, float alphaDeg, bool active) {
  const ImU32 rim = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  const ImU32 accent = ImGui::GetColorU32(active ? ImGuiCol_SliderGrabActive : ImGuiCol_SliderGrab);
  const float line = std::max(1.0f, r / 18.0f);
  dl->AddCircleFilled(c, r, ImGui::GetColorU32(ImGuiCol_FrameBg), 48);
  dl->AddCircle(c, r, rim, 48, line);
  // Ticks at the frontal and profile views.
  for (float tick : {0.0f, 90.0f, 180.0f, -90.0f}) dl->AddLine(onRim(c, r * 0.82f, tick), onRim(c, r, tick), rim, line);
  // The walker: a dot facing the bottom (its walking direction, the α = 0 camera).
  dl->AddCircleFilled(c, r * 0.14f, ImGui::GetColorU32(ImGuiCol_Text), 16);
  dl->AddLine(c, onRim(c, r * 0.34f, 0.0f), ImGui::GetColorU32(ImGuiCol_Text), line);
  // The camera: a line of sight to the walker and a disc on the rim.
  const ImVec2 camera = onRim(c, r * 0.78f, alphaDeg);
  dl->AddLine(c, camera, accent, 1.5f * line);
  dl->AddCircleFilled(camera, r * 0.2f, accent, 16);
}

}  // namespace

bool angleDial(const char* id, double& alphaDeg, float radius) {
  const ImVec2 corner = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, ImVec2(2.0f * radius, 2.0f * radius));
  const ImVec2 c{corner.x + radius, corner.y + radius};
  bool changed = false;
  if (ImGui::IsItemActive()) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const float dx = m.x - c.x, dy = m.y - c.y;
    // The centre has no direction: wait until the pointer leaves it.
    if (dx * dx + dy * dy > 0.04f * radius * radius) {
      const double picked = std::round(std::atan2(dx, dy) / kDegToRad);
      if (picked != alphaDeg) {
        alphaDeg = picked;
        changed = true;
      }
    }
  }
  drawDial(ImGui::GetWindowDrawList(), c, radius, static_cast<float>(alphaDeg), ImGui::IsItemActive());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("view angle α, from above: click or drag to move the camera");
  return changed;
}

}  // namespace ew::ui
