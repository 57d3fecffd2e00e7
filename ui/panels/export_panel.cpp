#include "ui/panels/export_panel.h"

#include <imgui.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <optional>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"

namespace ew::ui {

namespace {

std::filesystem::path target(const ExportPanel& p, const std::string& suffix) {
  return std::filesystem::path(p.folder.data()) / (std::string(p.baseName.data()) + suffix);
}

void sectionTitle(const char* title) {
  ImGui::Spacing();
  ImGui::TextDisabled("%s", title);
  ImGui::Separator();
}

}  // namespace

void ExportPanel::draw(AppState& s, const FrameContext& ctx) {
  if (!open) return;
  ImGui::SetNextWindowSize(ImVec2(520.0f * ctx.scale, 0.0f), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(ImGui::GetIO().DisplaySize.x * 0.5f, ImGui::GetIO().DisplaySize.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Export", &open, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  auto attempt = [&](const char* what, auto&& fn) {
    try {
      fn();
      status = std::string(what) + ": done";
    } catch (const std::exception& e) {
      status = std::string(what) + " failed: " + e.what();
      s.log.error(status);
    }
  };
  ImGui::InputText("folder", folder.data(), folder.size());
  ImGui::InputText("file name", baseName.data(), baseName.size());

  sectionTitle("Screenshot (PNG, also F12)");
  if (ImGui::Button("Window")) attempt("PNG", [&] { actions::requestPng(s, target(*this, ".png"), CaptureView::Window); });
  ImGui::SameLine();
  if (ImGui::Button("2D input view"))
    attempt("PNG", [&] { actions::requestPng(s, target(*this, "_input.png"), CaptureView::Input); });
  ImGui::SameLine();
  if (ImGui::Button("3D view"))
    attempt("PNG", [&] { actions::requestPng(s, target(*this, "_reconstruction.png"), CaptureView::Reconstruction); });

  sectionTitle("Video (both views side by side)");
  ImGui::SetNextItemWidth(120.0f * ctx.scale);
  ImGui::InputInt("gait cycles", &videoCycles);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120.0f * ctx.scale);
  ImGui::InputInt("fps", &videoFps);
  ImGui::SetNextItemWidth(120.0f * ctx.scale);
  ImGui::InputInt("width", &videoWidth, 2, 64);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120.0f * ctx.scale);
  ImGui::InputInt("height", &videoHeight, 2, 64);
  videoCycles = std::clamp(videoCycles, 1, 200);
  videoFps = std::clamp(videoFps, 1, 240);
  ImGui::RadioButton(".avi (MJPG)", &videoFormat, 0);
  ImGui::SameLine();
  ImGui::RadioButton(".mp4 (mp4v)", &videoFormat, 1);
  ImGui::Checkbox("captions, metrics and legends", &videoCaptions);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Each view's title, what it shows and its legend, burnt into the frames");
  if (s.exports.video) {
    ImGui::ProgressBar(s.exports.video->fraction(), ImVec2(-1.0f, 0.0f));
    if (ImGui::Button("Cancel")) actions::cancelVideoExport(s);
  } else if (ImGui::Button("Export video")) {
    attempt("video", [&] {
      VideoSettings v;
      v.path = target(*this, videoFormat == 0 ? ".avi" : ".mp4");
      v.cycles = videoCycles;
      v.fps = videoFps;
      v.width = videoWidth;
      v.height = videoHeight;
      v.captions = videoCaptions;
      actions::startVideoExport(s, v);
    });
    if (s.exports.video) status = "video: rendering…";
  }

  sectionTitle("Walker and model");
  ImGui::SetNextItemWidth(120.0f * ctx.scale);
  ImGui::InputInt("cycles (0 = trial duration)", &motionCycles);
  motionCycles = std::clamp(motionCycles, 0, 1000);
  const std::optional<double> cycles =
      motionCycles > 0 ? std::optional<double>(motionCycles) : std::nullopt;
  if (ImGui::Button("CSV (15 joints)")) attempt("CSV", [&] { actions::exportCsv(s, target(*this, ".csv"), cycles); });
  ImGui::SameLine();
  if (ImGui::Button("BVH")) attempt("BVH", [&] { actions::exportBvh(s, target(*this, ".bvh"), cycles); });
  ImGui::SameLine();
  if (ImGui::Button("Model")) attempt("model", [&] { actions::exportModel(s, target(*this, ".ewm")); });

  sectionTitle("For students");
  if (ImGui::Button("Web page (HTML)"))
    attempt("web page", [&] { actions::exportWalkerHtml(s, target(*this, ".html")); });
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the 2D view's walker as one HTML file any browser opens, offline: it walks\n"
                      "at the view's angle, elevation and direction, with play, α and speed controls");
  if (!status.empty()) {
    ImGui::Separator();
    ImGui::TextWrapped("%s", status.c_str());
  }
  if (!s.exports.lastError.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.5f, 1.0f), "%s", s.exports.lastError.c_str());
  ImGui::End();
}

}  // namespace ew::ui
