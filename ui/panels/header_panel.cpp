#include "ui/panels/header_panel.h"

#include <cstdio>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"

namespace ew::ui {

void HeaderPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "##header", rect, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar)) {
    if (s.fonts.large) ImGui::PushFont(s.fonts.large);
    ImGui::TextColored(ImVec4(1.0f, 0.72f, 0.38f, 1.0f), "Eigenwalker");
    if (s.fonts.large) ImGui::PopFont();
    ImGui::SameLine(0.0f, 18.0f * ctx.scale);
    if (ImGui::Button("Open…")) s.panels.data.open = !s.panels.data.open;
    ImGui::SameLine();
    if (ImGui::Button("Export…")) s.panels.exports.open = !s.panels.exports.open;
    ImGui::SameLine();
    if (ImGui::Button("Analysis")) s.panels.analysis.open = !s.panels.analysis.open;
    ImGui::SameLine();
    if (ImGui::Button("Tour")) {
      if (s.panels.tour.active) {
        actions::tourEnd(s);
      } else if (s.doc.ready()) {
        actions::tourStart(s);
      }
    }
    ImGui::SameLine();
    if (ImGui::Button("?")) s.panels.help.open = !s.panels.help.open;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Keyboard and mouse (F1)");
    ImGui::SameLine(0.0f, 18.0f * ctx.scale);
    ImGui::AlignTextToFramePadding();
    if (s.doc.population) {
      ImGui::TextDisabled("data:");
      ImGui::SameLine();
      ImGui::Text("%s (%d walkers)", s.doc.population->label.c_str(), s.doc.population->walkerCount());
    }
    if (s.doc.mode == Mode::Reconstruct) {
      if (const auto* r = s.derived.recon()) {
        ImGui::SameLine(0.0f, 24.0f * ctx.scale);
        ImGui::TextDisabled("model:");
        ImGui::SameLine();
        ImGui::Text("%d walkers, %s held out  ·  N = %d%s (%.1f %% of variance)", r->modelWalkers,
                    r->heldOutSubject.c_str(), r->components, r->autoComponents ? " auto" : "",
                    100.0 * r->explained);
      }
    } else if (const auto* e = s.derived.explore()) {
      ImGui::SameLine(0.0f, 24.0f * ctx.scale);
      ImGui::TextDisabled("model:");
      ImGui::SameLine();
      ImGui::Text("all %d walkers  ·  N = %d (%.1f %% of variance)", e->modelWalkers, e->components,
                  100.0 * e->explained);
    }

    // Right side: progress, or an export error (a failed open has its banner over the views).
    const float right = ImGui::GetWindowContentRegionMax().x;
    if (s.exports.video) {
      const auto& v = *s.exports.video;
      const float w = 420.0f * ctx.scale;
      const std::string what = "Video: frame " + std::to_string(v.framesDone()) + " of " +
                               std::to_string(v.frameCount());
      ImGui::SameLine(right - w - 70.0f * ctx.scale);
      ImGui::PushStyleColor(ImGuiCol_PlotHistogram, ImVec4(0.32f, 0.88f, 0.76f, 0.9f));
      ImGui::ProgressBar(v.fraction(), ImVec2(w, 0.0f), what.c_str());
      ImGui::PopStyleColor();
      ImGui::SameLine();
      if (ImGui::SmallButton("Cancel")) actions::cancelVideoExport(s);
    } else if (s.jobs.busy()) {
      const bool loading = s.jobs.load.running();
      const bool analysing = !loading && !s.jobs.models.running() && s.jobs.analysis.running();
      const float fraction = loading     ? s.jobs.load.fraction()
                             : analysing ? s.jobs.analysis.fraction()
                                         : s.jobs.models.fraction();
      const std::string what = loading     ? s.jobs.load.title() + ": " + s.jobs.load.what()
                               : analysing ? s.jobs.analysis.title()
                                           : s.jobs.models.title() + ": " + s.jobs.models.what();
      const float w = 420.0f * ctx.scale;
      ImGui::SameLine(right - w);
      ImGui::PushStyleColor(ImGuiCol_PlotHistogram, ImVec4(0.32f, 0.88f, 0.76f, 0.9f));
      ImGui::ProgressBar(fraction, ImVec2(w, 0.0f), what.c_str());
      ImGui::PopStyleColor();
    } else if (!s.exports.lastError.empty()) {
      const float w = 560.0f * ctx.scale;
      ImGui::SameLine(right - w);
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.5f, 1.0f), "%s", s.exports.lastError.substr(0, 80).c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", s.exports.lastError.c_str());
      ImGui::SameLine();
      if (ImGui::SmallButton("Dismiss##export")) s.exports.lastError.clear();
    } else if (!s.derived.error().empty()) {
      ImGui::SameLine(right - 560.0f * ctx.scale);
      ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.5f, 1.0f), "%s", s.derived.error().substr(0, 80).c_str());
    }
  }
  ImGui::End();
}

}  // namespace ew::ui
