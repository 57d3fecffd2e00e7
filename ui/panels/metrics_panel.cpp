#include "ui/panels/metrics_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/app/app_state.h"
#include "ui/app/theme.h"

namespace ew::ui {

namespace {

// A narrow strip (a small window or a large UI scale) drops a metric's note, then the metrics
// that do not fit at all, rather than cutting them at the edge.
// The strip's first metric starts its row (`first`); the others follow on the same line.
void metric(const AppState& s, bool first, const char* label, const char* value, const char* note, float width,
            const ImVec4& colour = ImGui::GetStyleColorVec4(ImGuiCol_Text)) {
  if (!first) ImGui::SameLine();
  const float avail = ImGui::GetContentRegionAvail().x;
  if (s.fonts.large) ImGui::PushFont(s.fonts.large);
  const float valueW = ImGui::CalcTextSize(value).x;
  if (s.fonts.large) ImGui::PopFont();
  const float noteW = ImGui::CalcTextSize(note).x + ImGui::GetStyle().ItemSpacing.x;
  if (std::max(ImGui::CalcTextSize(label).x, valueW) > avail) return;
  ImGui::BeginGroup();
  ImGui::TextDisabled("%s", label);
  if (s.fonts.large) ImGui::PushFont(s.fonts.large);
  ImGui::TextColored(colour, "%s", value);
  if (s.fonts.large) ImGui::PopFont();
  // Five metrics at their minimum width do not fit: notes go, so that every value can stay.
  const float strip = ImGui::GetWindowContentRegionMax().x - ImGui::GetWindowContentRegionMin().x;
  const bool notes = 5.0f * width <= strip + 1.0f;
  if (notes && valueW + noteW <= avail) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", note);
  }
  ImGui::EndGroup();
  ImGui::SameLine(0.0f, 0.0f);
  const float used = ImGui::GetItemRectSize().x;
  // The slot filled to its width, but never past the strip's edge (the last slot).
  const float room = std::max(0.0f, ImGui::GetContentRegionAvail().x);
  if (used < width && room > 0.0f) ImGui::Dummy(ImVec2(std::min(width - used, room), 1.0f));
}

// A keypoint clip: the walk in metres and seconds (the prior knows how big people are) and
// how well the walker drawn back through the camera meets the keypoints.
void clipMetrics(const AppState& s, float width) {
  const ClipReconstruction& rec = s.clip->rec;
  const CameraFit& f = rec.fit;
  char v[64], n[96];
  std::snprintf(v, sizeof v, "%.2f m", f.headHeightMm / 1000.0);
  metric(s, true, "height  head above ankles", v, "", width);
  std::snprintf(v, sizeof v, "%.2f m/s", f.speedMps);
  metric(s, false, "speed", v, rec.trial.rateAssumed ? "(30 fps?)" : "", width);
  std::snprintf(v, sizeof v, "%.2f m", f.strideLengthM);
  std::snprintf(n, sizeof n, "%.2f Hz", f.strideHz);
  metric(s, false, "stride length", v, n, width);
  std::snprintf(v, sizeof v, "%.0f /min", f.cadenceStepsPerMin);
  metric(s, false, "cadence  steps", v, "", width);
  std::snprintf(v, sizeof v, "%.1f px", f.reprojectionRmsPx);
  n[0] = '\0';
  if (f.outlierSamples > 0) std::snprintf(n, sizeof n, "%d glitches out", f.outlierSamples);
  metric(s, false, "reprojection  RMS", v, n, width);
}

}  // namespace

void MetricsPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "##metrics", rect, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar)) {
    const ReconBase* r = s.derived.recon();
    const ReconDisplay* d = s.derived.display();
    if (s.doc.mode == Mode::Explore) {
      ImGui::TextDisabled("Gait-space explorer");
      // The longest explanation the strip has room for.
      for (const char* text : {"Drag the eigenwalker sliders: the walker is the mean walker plus Σ k_n e_n, animated in 3D "
                               "and projected at α on the left. Errors are shown in reconstruct mode.",
                               "The walker is the mean walker plus Σ k_n e_n: drag the eigenwalker sliders.",
                               "Mean walker + Σ k_n e_n"}) {
        const float w = ImGui::GetContentRegionAvail().x;
        if (ImGui::CalcTextSize(text, nullptr, false, w).y <= ImGui::GetContentRegionAvail().y) {
          ImGui::TextWrapped("%s", text);
          break;
        }
      }
    } else if (s.doc.mode == Mode::Clip && s.view.overlays.metrics) {
      if (s.clip) {
        clipMetrics(s, std::max(150.0f * ctx.scale, (ImGui::GetContentRegionAvail().x - 8.0f) / 5.0f));
      } else {
        ImGui::TextDisabled(s.jobs.clip.running() ? "fitting the camera…" : "no fit");
      }
    } else if (!s.view.overlays.metrics) {
      ImGui::TextDisabled("metrics hidden (overlay \"metrics\")");
    } else if (r && d) {
      const float w = std::max(150.0f * ctx.scale, (ImGui::GetContentRegionAvail().x - 8.0f) / 5.0f);
      char v[64], n[64];
      // Over the measured joints, as `reconstruct` reports: a model-estimated joint has no truth.
      std::snprintf(v, sizeof v, "%.0f mm²", d->absScoredMm2);
      std::snprintf(n, sizeof n, "(√ %.1f mm)", std::sqrt(std::max(d->absScoredMm2, 0.0)));
      metric(s, true, "E_a  depth error", v, n, w);
      std::snprintf(v, sizeof v, "%.3f", d->relScored);
      std::snprintf(n, sizeof n, "σ_m² %.0f mm²", d->errors.sigmaM2Mm2);
      metric(s, false, "E_r  relative", v, n, w);
      std::snprintf(v, sizeof v, "%.1f mm", d->mpjpeMm);
      // Joints estimated from a model are scored apart (their ground truth is the model's).
      if (d->mpjpeModelEstimatedMm) {
        std::snprintf(n, sizeof n, "%d measured joints · est. (%.1f)", d->jointsScored,
                      *d->mpjpeModelEstimatedMm);
      } else {
        n[0] = '\0';
      }
      metric(s, false, "MPJPE  3D", v, n, w);
      std::snprintf(v, sizeof v, "%.1f mm", d->residualRmsMm);
      metric(s, false, "2D residual  RMS", v, d->edited ? "(edited k)" : "", w,
             d->edited ? ImVec4(1.0f, 0.72f, 0.38f, 1.0f) : ImGui::GetStyleColorVec4(ImGuiCol_Text));
      if (s.doc.recon.unknownAngle) {
        std::snprintf(v, sizeof v, "%.1f°", r->alphaUsedDeg);
        std::snprintf(n, sizeof n, "error %.1f°", d->angleErrorDeg);
        metric(s, false, "est. α  (true α hidden)", v, n, w,
               d->angleErrorDeg > 10.0 ? ImVec4(1.0f, 0.45f, 0.55f, 1.0f) : goodTextColour());
      } else {
        std::snprintf(v, sizeof v, "%.1f°", r->alphaTrueDeg);
        metric(s, false, "α  known", v, "", w);
      }
    } else {
      ImGui::TextDisabled(s.jobs.busy() ? "working…" : "no reconstruction");
    }
  }
  ImGui::End();
}

}  // namespace ew::ui
