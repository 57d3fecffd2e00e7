#include "ui/panels/data_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <system_error>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/video.h"
#include "ui/widgets/flow.h"

namespace ew::ui {

namespace {

constexpr const char* kUnits[] = {"file's", "mm", "cm", "m", "in", "cmu"};
constexpr const char* kFormatNames[] = {".c3d", ".bvh", ".asf/.amc", ".trc/.tsv", ".csv", "video", ".json", ".ewm"};
constexpr const char* kOpenTip =
    "Tip: drop files or folders on the window. A manifest CSV opens its trials; a pose estimator's "
    "folder of JSON files opens as a keypoint clip (Open this folder).";

}  // namespace

int browserFormat(const std::string& name) {
  std::string ext = std::filesystem::path(name).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".c3d") return 0;
  if (ext == ".bvh") return 1;
  if (ext == ".asf" || ext == ".amc") return 2;
  if (ext == ".trc" || ext == ".tsv") return 3;  // the two tab-separated marker files
  if (ext == ".csv") return 4;
  if (isVideoFile(name)) return 5;
  if (ext == ".json") return 6;  // a pose estimator's keypoints, a keyframe file
  if (ext == ".ewm") return 7;
  return -1;
}

namespace {

void setFolder(std::array<char, 1024>& buffer, const std::string& path) {
  const std::size_t n = std::min(path.size(), buffer.size() - 1);
  std::copy_n(path.begin(), n, buffer.begin());
  buffer[n] = '\0';
}

}  // namespace

void DataPanel::refresh() {
  listedFolder = folder.data();
  entries.clear();
  selected.clear();
  listError.clear();
  std::error_code ec;
  for (std::filesystem::directory_iterator it(listedFolder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name.front() == '.') continue;
    std::error_code typeError;
    const bool isFolder = it->is_directory(typeError);
    if (isFolder || browserFormat(name) >= 0) entries.push_back({name, isFolder});
  }
  if (ec) listError = ec.message();
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.folder != b.folder ? a.folder : a.name < b.name;
  });
}

void DataPanel::draw(AppState& s, const FrameContext& ctx) {
  if (!open) return;
  if (folder[0] == '\0') {
    std::error_code ec;
    setFolder(folder, std::filesystem::current_path(ec).string());
  }
  if (listedFolder != folder.data()) refresh();
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // Most of a small window or a large UI scale's, as the gait report and the analysis.
  const float width = floatingExtent(display.x, 0.66f, 900.0f * ctx.scale, 40.0f * ctx.scale);
  const float height = floatingExtent(display.y, 0.7f, 560.0f * ctx.scale, 80.0f * ctx.scale);
  ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Data: open files and folders", &open, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  // An open refused at once (nothing to open, a bad override) gets the banner, like a failed load.
  auto attempt = [&](const std::vector<std::filesystem::path>& paths, auto&& fn) {
    try {
      fn();
    } catch (const std::exception& e) {
      status = e.what();
      actions::reportOpenError(s, paths, status);
    }
  };
  if (ImGui::BeginTabBar("##data")) {
    // [SECTION] Open: folder browser and recent files
    if (ImGui::BeginTabItem("Open")) {
      if (ImGui::Button("Up")) {
        const auto parent = std::filesystem::path(folder.data()).parent_path();
        if (!parent.empty()) setFolder(folder, parent.string());
      }
      ImGui::SameLine();
      ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Refresh").x - 3.0f * ImGui::GetStyle().FramePadding.x -
                              ImGui::GetStyle().ItemSpacing.x);
      ImGui::InputText("##folder", folder.data(), folder.size());
      ImGui::SameLine();
      if (ImGui::Button("Refresh")) refresh();
      ImGui::AlignTextToFramePadding();
      ImGui::TextDisabled("show");
      for (std::size_t i = 0; i < formats.size(); ++i) {
        sameLineOrWrap(toggleWidth(kFormatNames[i]));
        ImGui::Checkbox(kFormatNames[i], &formats[i]);
      }
      // The lists take what the buttons and the tip under them leave (each may wrap).
      const float availW = ImGui::GetContentRegionAvail().x;
      const float spacing = ImGui::GetStyle().ItemSpacing.x;
      const float buttonsW = buttonWidth("Open selected files") + buttonWidth("Open this folder") +
                             buttonWidth("Synthetic default") + 2.0f * spacing;
      const int buttonRows = buttonsW <= availW ? 1 : 2;
      const float tipH = ImGui::CalcTextSize(kOpenTip, nullptr, false, availW).y;
      const float listH = std::max(ImGui::GetContentRegionAvail().y - static_cast<float>(buttonRows + 1) * ImGui::GetFrameHeightWithSpacing() - tipH,
                                   4.0f * ImGui::GetFrameHeightWithSpacing());
      const float recentW = std::min(300.0f * ctx.scale, 0.4f * availW);
      ImGui::BeginChild("##list", ImVec2(availW - recentW, listH), true, ImGuiWindowFlags_HorizontalScrollbar);
      if (!listError.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.5f, 1.0f), "%s", listError.c_str());
      std::string enter;
      for (const auto& e : entries) {
        if (e.folder) {
          if (ImGui::Selectable(("[folder]  " + e.name).c_str(), false, ImGuiSelectableFlags_AllowDoubleClick) &&
              ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
            enter = e.name;
        } else {
          const int f = browserFormat(e.name);
          if (f < 0 || !formats[static_cast<std::size_t>(f)]) continue;
          bool& ticked = selected[e.name];
          ImGui::Checkbox(e.name.c_str(), &ticked);
        }
      }
      if (entries.empty() && listError.empty()) textDisabledWrapped("no folders or files the viewer opens here");
      ImGui::EndChild();
      if (!enter.empty()) setFolder(folder, (std::filesystem::path(listedFolder) / enter).string());
      ImGui::SameLine();
      ImGui::BeginChild("##recent", ImVec2(0.0f, listH), true, ImGuiWindowFlags_HorizontalScrollbar);
      ImGui::TextDisabled("Recent");
      ImGui::Separator();
      std::vector<std::filesystem::path> reopen;
      for (const auto& r : s.recentPaths) {
        if (ImGui::Selectable(r.filename().string().c_str())) reopen = {r};
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.string().c_str());
      }
      if (s.recentPaths.empty()) textDisabledWrapped("nothing opened yet");
      ImGui::EndChild();
      if (!reopen.empty()) attempt(reopen, [&] { actions::open(s, reopen); });

      std::vector<std::filesystem::path> chosen;
      for (const auto& [name, on] : selected)
        if (on) chosen.push_back(std::filesystem::path(listedFolder) / name);
      ImGui::BeginDisabled(chosen.empty());
      if (ImGui::Button("Open selected files")) attempt(chosen, [&] { actions::drop(s, chosen); });
      ImGui::EndDisabled();
      sameLineOrWrap(buttonWidth("Open this folder"));
      if (ImGui::Button("Open this folder")) {
        const std::vector<std::filesystem::path> here{std::filesystem::path(listedFolder)};
        attempt(here, [&] { actions::drop(s, here); });
      }
      sameLineOrWrap(buttonWidth("Synthetic default"));
      if (ImGui::Button("Synthetic default")) attempt({}, [&] { actions::open(s, {}); });
      textDisabledWrapped(kOpenTip);
      ImGui::EndTabItem();
    }
    // [SECTION] Summary: one row per trial, warnings, overrides
    if (ImGui::BeginTabItem("Summary")) {
      actions::requestDataSummary(s);
      const auto& d = s.jobs.summary.latest();
      if (s.doc.sourcePaths.empty()) {
        ImGui::TextDisabled("The synthetic default population has no files.");
      } else if (s.jobs.summary.running()) {
        ImGui::ProgressBar(s.jobs.summary.fraction(), ImVec2(-1.0f, 0.0f), "reading the files…");
      } else if (d && d->generation == s.doc.generation) {
        for (const auto& w : d->warnings) ImGui::TextColored(ImVec4(0.9f, 0.6f, 0.2f, 1.0f), "%s", w.c_str());
        const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_Borders | ImGuiTableFlags_ScrollY |
                                      ImGuiTableFlags_ScrollX | ImGuiTableFlags_Resizable | ImGuiTableFlags_SizingFixedFit;
        const float tableH = ImGui::GetContentRegionAvail().y - ImGui::GetFrameHeightWithSpacing();
        if (ImGui::BeginTable("##summary", 11, flags, ImVec2(0.0f, tableH))) {
          ImGui::TableSetupScrollFreeze(1, 1);
          for (const char* h : {"file", "format", "frames", "rate Hz", "units", "points", "cycles", "stride Hz",
                                "speed m/s", "override (unit, rate)", "warnings"})
            ImGui::TableSetupColumn(h);
          ImGui::TableHeadersRow();
          for (const auto& r : d->rows) {
            ImGui::PushID(r.file.c_str());
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(std::filesystem::path(r.file).filename().string().c_str());
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.file.c_str());
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r.format.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%d", r.frames);
            ImGui::TableNextColumn();
            ImGui::Text("%.1f", r.rateHz);
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(r.units.c_str());
            ImGui::TableNextColumn();
            ImGui::Text("%d", r.pointsFound);
            ImGui::TableNextColumn();
            if (r.ok()) ImGui::Text("%.2f", r.cycles);
            ImGui::TableNextColumn();
            if (r.ok()) ImGui::Text("%.3f", r.strideHz);
            ImGui::TableNextColumn();
            if (r.ok()) ImGui::Text("%.2f", r.speedMps);
            ImGui::TableNextColumn();
            auto& e = edits[r.file];
            ImGui::SetNextItemWidth(80.0f * ctx.scale);
            ImGui::Combo("##unit", &e.unit, kUnits, static_cast<int>(std::size(kUnits)));
            ImGui::SameLine();
            ImGui::SetNextItemWidth(90.0f * ctx.scale);
            ImGui::InputFloat("##rate", &e.rateHz, 0.0f, 0.0f, e.rateHz > 0.0f ? "%.1f Hz" : "file's");
            e.rateHz = std::clamp(e.rateHz, 0.0f, 10000.0f);
            ImGui::TableNextColumn();
            if (!r.ok()) {
              ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.5f, 1.0f), "ERROR (%s): %s", r.errorStage.c_str(), r.error.c_str());
            } else if (r.warnings.empty()) {
              ImGui::TextDisabled("none");
            }
            for (const auto& w : r.warnings) ImGui::TextColored(ImVec4(0.9f, 0.6f, 0.2f, 1.0f), "%s", w.c_str());
            ImGui::PopID();
          }
          ImGui::EndTable();
        }
        if (ImGui::Button("Apply overrides and reload")) {
          attempt(s.doc.sourcePaths, [&] {
            for (const auto& [file, e] : edits)
              actions::setFileOverride(s, file, e.unit == 0 ? std::string() : kUnits[e.unit], e.rateHz);
            actions::reloadWithOverrides(s);
            status = "reloading with " + std::to_string(s.doc.fileOverrides.size()) + " override(s)";
          });
        }
        ImGui::SameLine();
        ImGui::TextDisabled("%zu trials · %s", d->rows.size(), status.c_str());
      }
      ImGui::EndTabItem();
    }
    // [SECTION] Joint mapping: a table of a file's labels that writes a mapping file
    if (ImGui::BeginTabItem("Joint mapping")) {
      mapping.draw(s, ctx);
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
  }
  ImGui::End();
}

}  // namespace ew::ui
