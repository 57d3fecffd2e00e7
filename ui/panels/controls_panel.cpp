#include "ui/panels/controls_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "core/eigenwalker/model.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/convert.h"
#include "ui/panels/clip_controls.h"
#include "ui/panels/stage_controls.h"
#include "ui/render/palette.h"
#include "ui/widgets/flow.h"
#include "ui/widgets/section_title.h"

namespace ew::ui {

void ControlsPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "Controls", rect)) {
    auto& doc = s.doc;
    int mode = static_cast<int>(doc.mode);
    const char* modes[] = {"Reconstruct", "Explore gait space",
                           s.video.session ? "Video" : "Keypoint clip"};
    if (radioRow(modes, s.clip.settings || s.video.session ? 3 : 2, &mode))
      actions::setMode(s, static_cast<Mode>(mode));
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
      const char* tips[] = {"Zhang & Troje 2007: one gait cycle, PCA of walkers",
                            "Howe, Leventon & Freeman 1999: 11-frame snippets, mixture prior,\n"
                            "learnt from the population's other subjects walked overground",
                            "Zou et al. 2009: each frame from geometry alone, the walker's own\n"
                            "bone lengths, no training; each bone's two depths chosen over the clip"};
      for (int i = 0; i < 3; ++i) {
        const char* label = i == 0 ? "Eigenwalker" : i == 1 ? "Snippets" : "Skeleton";
        if (i > 0) sameLineOrWrap(toggleWidth(label));
        if (radioWrapped(label, engine == i) && engine != i) actions::setEngine(s, static_cast<EngineKind>(i));
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tips[i]);
      }
      bool compare = doc.compareEngines;
      if (checkboxWrapped("Compare all three", &compare)) actions::setCompareEngines(s, compare);
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
          sameLineOrWrap(toggleWidth(engineName(static_cast<EngineKind>(static_cast<int>(kind) + 1))));
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
    // The fine field's label beside it when the panel has room, else in its tooltip.
    const float fineW = 100.0f * ctx.scale;
    const bool fineLabel = fineW + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize("fine (drag / type)").x <=
                           ImGui::GetContentRegionAvail().x;
    ImGui::SetNextItemWidth(fineLabel ? fineW : -1.0f);
    if (ImGui::DragFloat(fineLabel ? "fine (drag / type)" : "##fine", &alpha, 0.05f, -180.0f, 180.0f, "%.2f°",
                         ImGuiSliderFlags_AlwaysClamp))
      actions::setAngle(s, alpha);
    if (!fineLabel && ImGui::IsItemHovered()) ImGui::SetTooltip("fine: drag, or double-click to type");
    textDisabledWrapped("0° frontal · ±90° profiles");
    bool unknown = doc.recon.unknownAngle;
    if (checkboxWrapped("Unknown view angle (estimate α)", &unknown))
      actions::setUnknownAngle(s, unknown);

    ImGui::BeginDisabled(!eigenwalkerSettings);
    sectionTitle("Estimator");
    int est = doc.recon.estimator == Estimator::Lsq ? 0 : 1;
    const char* estimators[] = {"LSQ", "MAP (Bayesian prior)"};
    if (radioRow(estimators, 2, &est)) actions::setEstimator(s, est == 0 ? Estimator::Lsq : Estimator::Map);
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
    constexpr const char* kPresets[] = {"three_quarter", "front", "side", "top"};
    const int preset = buttonRow({{"3/4", true}, {"Front", true}, {"Side", true}, {"Top", true}});
    if (preset >= 0) actions::setCamera(s, kPresets[preset]);
    textDisabledWrapped("drag: orbit · right-drag: pan · wheel: zoom · double-click: reset");

    sectionTitle("Overlays");
    auto& o = s.view.overlays;
    const std::pair<const char*, bool*> boxes[] = {
        {"depth error colour", &o.depthErrorColour}, {"error lines", &o.errorLines},
        {"error bars", &o.errorBars},                {"metrics", &o.metrics},
        {"ground truth ghost", &o.ghost},            {"camera glyph", &o.cameraGlyph},
        {"floor grid", &o.grid},                     {"2D reprojection", &o.reprojection},
        {"2D stick figure", &o.stickFigure},         {"2D trails", &o.trails},
        {"point-lights only", &o.pointLights}};
    // Two columns when the longest label fits half the panel, else one.
    float longest = 0.0f;
    for (const auto& [label, value] : boxes) longest = std::max(longest, toggleWidth(label));
    const int columns = 2.0f * (longest + 2.0f * ImGui::GetStyle().CellPadding.x) <= ImGui::GetContentRegionAvail().x ? 2 : 1;
    if (ImGui::BeginTable("overlays", columns)) {
      for (const auto& [label, value] : boxes) {
        ImGui::TableNextColumn();
        checkboxWrapped(label, value);
      }
      ImGui::EndTable();
    }

    sectionTitle("Classroom displays");
    drawStageControls(s);

    sectionTitle("Display");
    int theme = static_cast<int>(s.view.theme);
    const char* themes[] = {"dark", "light", "projector"};
    if (radioRow(themes, 3, &theme)) s.view.theme = static_cast<Theme>(theme);
    float scale = pendingUiScale > 0.0f ? pendingUiScale : s.view.uiScale;
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderFloat("##uiscale", &scale, 0.75f, 2.5f, "UI scale %.2f×"))
      pendingUiScale = scale;
    if (pendingUiScale > 0.0f && ImGui::IsItemDeactivated()) {
      s.view.uiScale = pendingUiScale;
      pendingUiScale = 0.0f;
    }
    if (s.view.uiScaleLimit > 0.0f) {
      char note[96];
      std::snprintf(note, sizeof note, "shown at %.2f×: the window is too small for more", s.view.uiScaleLimit);
      textDisabledWrapped(note);
    }
  }
}

}  // namespace ew::ui
