#include "ui/widgets/flow.h"

#include <algorithm>

#include <imgui.h>

#include <string>

namespace ew::ui {

namespace {

// The box alone, then the label wrapped at the panel's edge; true when either was clicked.
template <class Box>
bool boxWithWrappedLabel(const char* label, Box box) {
  ImGui::PushID(label);
  bool pressed = box("##box");
  ImGui::PopID();
  ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted(label);
  ImGui::PopTextWrapPos();
  return ImGui::IsItemClicked() || pressed;
}

}  // namespace

float toggleWidth(const char* label) {
  return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label, nullptr, true).x;
}

float buttonWidth(const char* label) {
  return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

void sameLineOrWrap(float width, float spacing) {
  ImGui::SameLine(0.0f, spacing);
  if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
}

bool checkboxWrapped(const char* label, bool* value) {
  if (toggleWidth(label) <= ImGui::GetContentRegionAvail().x) return ImGui::Checkbox(label, value);
  bool v = *value;
  const bool clicked = boxWithWrappedLabel(label, [&](const char* id) { return ImGui::Checkbox(id, &v); });
  if (clicked) *value = !*value;
  return clicked;
}

bool radioWrapped(const char* label, bool active) {
  if (toggleWidth(label) <= ImGui::GetContentRegionAvail().x) return ImGui::RadioButton(label, active);
  return boxWithWrappedLabel(label, [&](const char* id) { return ImGui::RadioButton(id, active); });
}

bool radioRow(const char* const* labels, int count, int* value) {
  bool changed = false;
  for (int i = 0; i < count; ++i) {
    if (i > 0) sameLineOrWrap(toggleWidth(labels[i]));
    if (radioWrapped(labels[i], *value == i) && *value != i) {
      *value = i;
      changed = true;
    }
  }
  return changed;
}

void textDisabledWrapped(const char* text) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted(text);
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
}

int buttonRow(std::initializer_list<std::pair<const char*, bool>> buttons) {
  const float spacing = ImGui::GetStyle().ItemSpacing.x, avail = ImGui::GetContentRegionAvail().x;
  float widest = 0.0f;
  for (const auto& b : buttons) widest = std::max(widest, buttonWidth(b.first));
  const int count = static_cast<int>(buttons.size());
  const int perRow = std::clamp(static_cast<int>((avail + spacing) / (widest + spacing)), 1, count);
  const int rows = (count + perRow - 1) / perRow;
  const int across = (count + rows - 1) / rows;  // rows as even as they can be
  const float w = (avail - static_cast<float>(across - 1) * spacing) / static_cast<float>(across);
  int clicked = -1, i = 0;
  for (const auto& [label, enabled] : buttons) {
    if (i % across != 0) ImGui::SameLine();
    ImGui::BeginDisabled(!enabled);
    if (ImGui::Button(label, ImVec2(w, 0.0f))) clicked = i;
    ImGui::EndDisabled();
    ++i;
  }
  return clicked;
}

}  // namespace ew::ui
