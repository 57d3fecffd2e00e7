#include "ui/panels/coefficients_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/widgets/flow.h"

namespace ew::ui {

namespace {

// Mode::Clip: the fit's coefficients in SD units of the model it used (read only: the camera
// and the walker are one fit).
void drawClipCoefficients(const AppState& s, const FrameContext& ctx) {
  if (!s.clip.fit()) {
    ImGui::TextDisabled(s.clip.fits.running() ? "fitting…" : "no fit");
    return;
  }
  const EigenwalkerModel& m = *s.clip.fit()->model.model;
  const Eigen::VectorXd& k = s.clip.fit()->rec.fit.k;
  textDisabledWrapped("fitted with the camera (SD units)");
  ImGui::Separator();
  const float labelW = 88.0f * ctx.scale;
  const double total = std::max(m.spectrum.sum(), 1e-12);
  ImGui::BeginDisabled();
  for (Eigen::Index i = 0; i < k.size(); ++i) {
    float value = static_cast<float>(k[i] / std::sqrt(std::max(m.eigenvalues[i], 1e-12)));
    ImGui::PushID(static_cast<int>(i));
    ImGui::AlignTextToFramePadding();
    ImGui::Text("e%-2d", static_cast<int>(i) + 1);
    ImGui::SameLine();
    ImGui::TextDisabled("%4.1f%%", 100.0 * m.eigenvalues[i] / total);
    ImGui::SameLine(labelW);
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::SliderFloat("##k", &value, -3.0f, 3.0f, "%+.2f SD");
    ImGui::PopID();
  }
  ImGui::EndDisabled();
}

}  // namespace

void CoefficientsPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "Eigenwalker coefficients", rect)) {
    const bool explore = s.doc.mode == Mode::Explore;
    const ReconBase* r = s.derived.recon();
    const ReconDisplay* d = s.derived.display();
    const ExploreResult* e = s.derived.explore();
    if (s.doc.mode == Mode::Clip) {
      drawClipCoefficients(s, ctx);
      ImGui::End();
      return;
    }
    const int n = actions::coefficientCount(s);
    if (explore) {
      if (ImGui::Button("Reset")) actions::resetCoefficients(s);
      sameLineOrWrap(buttonWidth("Randomise"));
      if (ImGui::Button("Randomise")) actions::randomiseCoefficients(s, randomSeed++);
      sameLineOrWrap(buttonWidth("From subject"));
      if (ImGui::Button("From subject") && s.doc.selectedWalker())
        actions::coefficientsFromWalker(s);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("the selected walker's coefficients in the full model");
      semantic.drawExplore(s, ctx.scale);
      textDisabledWrapped("units: SD of each component (√λ)");
    } else if (r && r->engine != EngineKind::Eigenwalker) {
      ImGui::TextWrapped("The %s engine has no eigenwalker coefficients. Its result, summarised "
                         "as one cycle, lies here in gait space (read only):",
                         r->engine == EngineKind::Snippet ? "snippet" : "skeleton");
    } else {
      ImGui::BeginDisabled(s.doc.editedSd.empty());
      if (ImGui::Button("Back to the estimate")) actions::resetCoefficients(s);
      ImGui::EndDisabled();
      if (d && d->edited) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.72f, 0.38f, 1.0f));
        ImGui::TextWrapped("edited: the 2D and 3D views follow");
        ImGui::PopStyleColor();
      } else {
        textDisabledWrapped("estimated k, in SD units (drag to edit)");
      }
    }
    ImGui::Separator();
    const float labelW = 88.0f * ctx.scale;
    const bool readOnly = !explore && r && r->engine != EngineKind::Eigenwalker;
    ImGui::BeginDisabled(readOnly);
    for (int i = 0; i < n; ++i) {
      float value = 0.0f;
      double share = 0.0;
      if (explore && e) {
        value = i < static_cast<int>(s.doc.exploreSd.size()) ? static_cast<float>(s.doc.exploreSd[static_cast<std::size_t>(i)]) : 0.0f;
        share = e->shares(i);
      } else if (r && d) {
        value = static_cast<float>(d->kSd(i));
        share = r->model.eigenvalues(i) / std::max(r->model.spectrum.sum(), 1e-12);
      }
      ImGui::PushID(i);
      ImGui::AlignTextToFramePadding();
      ImGui::Text("e%-2d", i + 1);
      ImGui::SameLine();
      ImGui::TextDisabled("%4.1f%%", 100.0 * share);
      ImGui::SameLine(labelW);
      ImGui::SetNextItemWidth(-1.0f);
      // Out-of-range estimates are shown (clamped slider), edited values are clamped to ±3.
      if (ImGui::SliderFloat("##k", &value, -3.0f, 3.0f, "%+.2f SD")) actions::setCoefficient(s, i, value);
      ImGui::PopID();
    }
    ImGui::EndDisabled();
    if (n == 0) ImGui::TextDisabled(s.jobsBusy() ? "building models…" : "no model");
    if (!explore) semantic.drawFromView(s, ctx.scale);
  }
  ImGui::End();
}

}  // namespace ew::ui
