#include "ui/panels/controls_panel.h"

#include <cmath>

#include "core/engine/model.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/convert.h"
#include "ui/panels/clip_controls.h"
#include "ui/render/palette.h"
#include "ui/widgets/section_title.h"

namespace ew::ui {

void ControlsPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "Controls", rect)) {
    auto& doc = s.doc;
    int mode = static_cast<int>(doc.mode);
    if (ImGui::RadioButton("Reconstruct", &mode, 0)) actions::setMode(s, Mode::Reconstruct);
    ImGui::SameLine();
    if (ImGui::RadioButton("Explore gait space", &mode, 1)) actions::setMode(s, Mode::Explore);
    if (doc.clip || s.video) {
      if (ImGui::RadioButton(s.video ? "Video" : "Keypoint clip", &mode, 2)) actions::setMode(s, Mode::Clip);
    }
    if (doc.mode == Mode::Clip) {
      drawVideoControls(s, ctx.scale);
      drawClipControls(s);
      drawViewControls(s, ctx);
      ImGui::End();
      return;
    }

    if (doc.mode == Mode::Reconstruct) {
      sectionTitle("Engine");
      int engine = static_cast<int>(doc.recon.engine);
      if (ImGui::RadioButton("Eigenwalker", &engine, 0)) actions::setEngine(s, EngineKind::Eigenwalker);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Zhang & Troje 2007: one gait cycle, PCA of walkers");
      ImGui::SameLine();
      if (ImGui::RadioButton("Snippets", &engine, 1)) actions::setEngine(s, EngineKind::Snippet);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Howe, Leventon & Freeman 1999: 11-frame snippets, mixture prior,\n"
                          "learnt from the population's other subjects walked overground");
      // Three radios fit one row only in a wide panel: the third wraps otherwise.
      const ImGuiStyle& style = ImGui::GetStyle();
      const float skeletonW = ImGui::GetFrameHeight() + style.ItemInnerSpacing.x + ImGui::CalcTextSize("Skeleton").x;
      ImGui::SameLine();
      if (ImGui::GetContentRegionAvail().x < skeletonW) ImGui::NewLine();
      if (ImGui::RadioButton("Skeleton", &engine, 2)) actions::setEngine(s, EngineKind::Skeleton);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Zou et al. 2009: each frame from geometry alone, the walker's own\n"
                          "bone lengths, no training; each bone's two depths chosen over the clip");
      bool compare = doc.compareEngines;
      if (ImGui::Checkbox("Compare all three", &compare)) actions::setCompareEngines(s, compare);
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Every engine reconstructs the walker from the same view, drawn together\n"
                          "over the ground truth, with a row of errors each");
      if (doc.compareEngines) {
        for (EngineKind kind : kEngineKinds) {
          const auto k = static_cast<std::size_t>(kind);
          bool shown = doc.compareShown[k];
          ImGui::PushStyleColor(ImGuiCol_CheckMark, toImVec4(palette::kEngineRight[k]));
          ImGui::PushStyleColor(ImGuiCol_Text, toImVec4(palette::kEngineRight[k]));
          if (ImGui::Checkbox(engineName(kind), &shown)) actions::setCompareShown(s, kind, shown);
          ImGui::PopStyleColor(2);
          if (kind == EngineKind::Skeleton) break;
          // The next one on this line when it fits, else on the next.
          const auto next = static_cast<EngineKind>(static_cast<int>(kind) + 1);
          const float nextW = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x +
                              ImGui::CalcTextSize(engineName(next)).x + ImGui::GetStyle().ItemSpacing.x;
          ImGui::SameLine();
          if (ImGui::GetContentRegionAvail().x < nextW) ImGui::NewLine();
        }
      }
    }
    const bool eigenwalkerSettings = doc.mode != Mode::Reconstruct || doc.recon.engine == EngineKind::Eigenwalker;

    sectionTitle("View angle");
    float alpha = static_cast<float>(doc.recon.alphaDeg);
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderFloat("##alpha", &alpha, -180.0f, 180.0f, "α = %.1f°",
                           ImGuiSliderFlags_AlwaysClamp))
      actions::setAngle(s, alpha);
    ImGui::SetNextItemWidth(100.0f * ctx.scale);
    if (ImGui::DragFloat("fine (drag / type)", &alpha, 0.05f, -180.0f, 180.0f, "%.2f°",
                         ImGuiSliderFlags_AlwaysClamp))
      actions::setAngle(s, alpha);
    ImGui::TextDisabled("0° frontal · ±90° profiles");
    bool unknown = doc.recon.unknownAngle;
    if (ImGui::Checkbox("Unknown view angle (estimate α)", &unknown))
      actions::setUnknownAngle(s, unknown);

    ImGui::BeginDisabled(!eigenwalkerSettings);
    sectionTitle("Estimator");
    int est = doc.recon.estimator == Estimator::Lsq ? 0 : 1;
    if (ImGui::RadioButton("LSQ", &est, 0)) actions::setEstimator(s, Estimator::Lsq);
    ImGui::SameLine();
    if (ImGui::RadioButton("MAP (Bayesian prior)", &est, 1))
      actions::setEstimator(s, Estimator::Map);
    ImGui::BeginDisabled(doc.recon.estimator != Estimator::Map);
    float sigma2 = static_cast<float>(doc.recon.sigma2Mm2);
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderFloat("##sigma2", &sigma2, 1.0f, 5000.0f, "σ² = %.0f mm²",
                           ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
      actions::setSigma2(s, sigma2);
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled) && doc.heldModel())
      ImGui::SetTooltip("%s", doc.sigma2Chosen ? "σ² as you set it"
                                               : defaultSigma2Source(*doc.heldModel()).c_str());
    ImGui::EndDisabled();

    sectionTitle("Eigenwalkers");
    const int maxN = doc.heldModel() ? doc.heldModel()->componentCount() : 1;
    int n = doc.recon.components;
    const int shown = doc.mode == Mode::Explore
                          ? (s.derived.explore() ? s.derived.explore()->components : 0)
                          : (s.derived.recon() ? s.derived.recon()->components : 0);
    char fmt[64];
    std::snprintf(fmt, sizeof fmt, n == 0 ? "N = auto (%d, 95 %%%%)" : "N = %%d", shown);
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderInt("##components", &n, 0, maxN, fmt, ImGuiSliderFlags_AlwaysClamp))
      actions::setComponents(s, n);
    ImGui::EndDisabled();
    if (!eigenwalkerSettings) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
      ImGui::TextWrapped("Estimator and N are the eigenwalker's: the snippet engine is MAP with its own prior.");
      ImGui::PopStyleColor();
    }

    drawViewControls(s, ctx);
  }
  ImGui::End();
}

void ControlsPanel::drawViewControls(AppState& s, const FrameContext& /*ctx*/) {
  {
    sectionTitle("3D camera");
    const float bw =
        (ImGui::GetContentRegionAvail().x - 3.0f * ImGui::GetStyle().ItemSpacing.x) / 4.0f;
    if (ImGui::Button("3/4", ImVec2(bw, 0))) actions::setCamera(s, "three_quarter");
    ImGui::SameLine();
    if (ImGui::Button("Front", ImVec2(bw, 0))) actions::setCamera(s, "front");
    ImGui::SameLine();
    if (ImGui::Button("Side", ImVec2(bw, 0))) actions::setCamera(s, "side");
    ImGui::SameLine();
    if (ImGui::Button("Top", ImVec2(bw, 0))) actions::setCamera(s, "top");
    ImGui::TextDisabled("drag: orbit · right-drag: pan · wheel: zoom\ndouble-click: reset");

    sectionTitle("Overlays");
    auto& o = s.view.overlays;
    if (ImGui::BeginTable("overlays", 2)) {
      auto box = [](const char* label, bool* v) {
        ImGui::TableNextColumn();
        ImGui::Checkbox(label, v);
      };
      box("depth error colour", &o.depthErrorColour);
      box("error lines", &o.errorLines);
      box("error bars", &o.errorBars);
      box("metrics", &o.metrics);
      box("ground truth ghost", &o.ghost);
      box("camera glyph", &o.cameraGlyph);
      box("floor grid", &o.grid);
      box("2D reprojection", &o.reprojection);
      box("2D stick figure", &o.stickFigure);
      box("2D trails", &o.trails);
      box("point-lights only", &o.pointLights);
      ImGui::EndTable();
    }

    sectionTitle("Display");
    int theme = static_cast<int>(s.view.theme);
    ImGui::RadioButton("dark", &theme, 0);
    ImGui::SameLine();
    ImGui::RadioButton("light", &theme, 1);
    ImGui::SameLine();
    ImGui::RadioButton("projector", &theme, 2);
    s.view.theme = static_cast<Theme>(theme);
    float scale = pendingUiScale > 0.0f ? pendingUiScale : s.view.uiScale;
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderFloat("##uiscale", &scale, 0.75f, 2.5f, "UI scale %.2f×"))
      pendingUiScale = scale;
    if (pendingUiScale > 0.0f && ImGui::IsItemDeactivated()) {
      s.view.uiScale = pendingUiScale;
      pendingUiScale = 0.0f;
    }
  }
}

}  // namespace ew::ui
