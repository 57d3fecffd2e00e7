#include "ui/panels/mapping_tab.h"

#include <imgui.h>

#include <exception>
#include <filesystem>
#include <stdexcept>

#include "core/io/load_trial.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"

namespace ew::ui {

namespace {

void copyTo(std::array<char, 1024>& buffer, const std::string& text) {
  buffer.fill('\0');
  text.copy(buffer.data(), buffer.size() - 1);
}

// "LASI", "mean of LASI, RASI", "absent (model-estimated)".
std::string describe(const std::vector<std::string>& labels) {
  if (labels.empty()) return "absent (model-estimated)";
  if (labels.size() == 1) return labels.front();
  std::string text = "mean of ";
  for (std::size_t i = 0; i < labels.size(); ++i) text += (i ? ", " : "") + labels[i];
  return text;
}

}  // namespace

void MappingTab::read(AppState& s, const std::string& path) {
  copyTo(file, path);
  readFile = path;
  try {
    table = labelTable(readRawTrial(readFile));
    for (int j = 0; j < kJointCount; ++j)
      choice[static_cast<std::size_t>(j)] =
          table.suggested.joints[static_cast<std::size_t>(j)].empty() ? 0 : 1;
    const std::filesystem::path p(readFile);
    copyTo(outPath, (p.parent_path() / (p.stem().string() + ".mapping.json")).string());
    status = std::to_string(table.labels.size()) + " labels; suggested from " + table.suggestedFrom;
    statusIsError = false;
  } catch (const std::exception& e) {
    table = {};
    status = e.what();
    statusIsError = true;
    s.log.error("Joint mapping: " + status);
  }
}

JointMapping MappingTab::mapping() const {
  JointMapping m;
  for (std::size_t j = 0; j < m.joints.size(); ++j) {
    const int c = choice[j];
    if (c == 1) {
      m.joints[j] = table.suggested.joints[j];
    } else if (c >= 2 && c - 2 < static_cast<int>(table.labels.size())) {
      m.joints[j] = {table.labels[static_cast<std::size_t>(c - 2)]};
    }
  }
  return m;
}

void MappingTab::draw(AppState& s, const FrameContext& ctx) {
  // The selected walker's first file, until the user types another.
  if (file[0] == '\0')
    if (const Walker* w = s.doc.selectedWalker(); w && !w->files.empty())
      copyTo(file, w->files.front());
  ImGui::SetNextItemWidth(-110.0f * ctx.scale);
  ImGui::InputTextWithHint("##mapfile", "a marker file (.c3d, .trc)…", file.data(), file.size());
  ImGui::SameLine();
  if (ImGui::Button("Read labels")) read(s, file.data());
  if (!status.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    if (statusIsError) {
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.5f, 1.0f), "%s", status.c_str());
    } else {
      ImGui::TextDisabled("%s", status.c_str());
    }
    ImGui::PopTextWrapPos();
  }
  if (table.labels.empty()) return;
  const float tableH = ImGui::GetContentRegionAvail().y - 2.5f * ImGui::GetFrameHeightWithSpacing();
  if (ImGui::BeginTable("mapping", 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY,
                        ImVec2(0.0f, tableH))) {
    ImGui::TableSetupColumn("joint", ImGuiTableColumnFlags_WidthFixed, 110.0f * ctx.scale);
    ImGui::TableSetupColumn("from the file's labels", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableHeadersRow();
    for (int j = 0; j < kJointCount; ++j) {
      const auto ju = static_cast<std::size_t>(j);
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::AlignTextToFramePadding();
      ImGui::TextUnformatted(std::string(kJointNames[ju]).c_str());
      ImGui::TableNextColumn();
      ImGui::PushID(j);
      ImGui::SetNextItemWidth(-1.0f);
      const std::string suggested = "suggested: " + describe(table.suggested.joints[ju]);
      const std::string current = choice[ju] == 0 ? describe({})
                                  : choice[ju] == 1
                                      ? suggested
                                      : table.labels[static_cast<std::size_t>(choice[ju] - 2)];
      if (ImGui::BeginCombo("##joint", current.c_str())) {
        if (ImGui::Selectable(describe({}).c_str(), choice[ju] == 0)) choice[ju] = 0;
        if (ImGui::Selectable(suggested.c_str(), choice[ju] == 1)) choice[ju] = 1;
        for (std::size_t i = 0; i < table.labels.size(); ++i)
          if (ImGui::Selectable(table.labels[i].c_str(), choice[ju] == static_cast<int>(i) + 2))
            choice[ju] = static_cast<int>(i) + 2;
        ImGui::EndCombo();
      }
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  ImGui::SetNextItemWidth(-260.0f * ctx.scale);
  ImGui::InputText("##mapout", outPath.data(), outPath.size());
  ImGui::SameLine();
  const bool write = ImGui::Button("Write");
  ImGui::SameLine();
  const bool writeOpen = ImGui::Button("Write and open with it");
  if (!write && !writeOpen) return;
  try {
    this->write(s, writeOpen);
  } catch (const std::exception& e) {
    status = e.what();
    statusIsError = true;
  }
}

void MappingTab::write(AppState& s, bool openNow) {
  if (table.labels.empty()) throw std::invalid_argument("no labels read (Read labels first)");
  actions::writeJointMapping(s, readFile, outPath.data(), mapping(), openNow);
  status = "wrote " + std::string(outPath.data());
  statusIsError = false;
}

}  // namespace ew::ui
