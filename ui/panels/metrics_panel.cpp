#include "ui/panels/metrics_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/app/app_state.h"
#include "ui/app/theme.h"
#include "ui/panels/metric_items.h"

namespace ew::ui {

namespace {

ImVec4 toneColour(MetricTone tone) {
  switch (tone) {
    case MetricTone::Good: return goodTextColour();
    case MetricTone::Bad: return ImVec4(1.0f, 0.45f, 0.55f, 1.0f);
    case MetricTone::Edited: return ImVec4(1.0f, 0.72f, 0.38f, 1.0f);
    case MetricTone::Normal: break;
  }
  return ImGui::GetStyleColorVec4(ImGuiCol_Text);
}

float valueWidth(const AppState& s, const char* value) {
  if (s.fonts.large) ImGui::PushFont(s.fonts.large);
  const float w = ImGui::CalcTextSize(value).x;
  if (s.fonts.large) ImGui::PopFont();
  return w;
}

// How much of each metric the strip has room for: its note and its SD, its SD, or the value
// alone (then a metric that does not fit at all is left out, rather than cut at the edge).
enum class MetricDetail { NotesAndSds, Sds, Values };

const std::string& shownValue(const MetricItem& m, MetricDetail d) {
  return d != MetricDetail::Values && !m.withSd.empty() ? m.withSd : m.value;
}

// The most detail with which every metric fits the strip, each in a slot of at least `width`.
MetricDetail detailThatFits(const AppState& s, const std::vector<MetricItem>& items, float width) {
  const float strip = ImGui::GetWindowContentRegionMax().x - ImGui::GetWindowContentRegionMin().x;
  for (const MetricDetail d : {MetricDetail::NotesAndSds, MetricDetail::Sds}) {
    float total = 0.0f;
    for (const MetricItem& m : items) {
      float valueAndNote = valueWidth(s, shownValue(m, d).c_str());
      if (d == MetricDetail::NotesAndSds)
        valueAndNote += ImGui::GetStyle().ItemSpacing.x + ImGui::CalcTextSize(m.note.c_str()).x;
      total += std::max({width, ImGui::CalcTextSize(m.label.c_str()).x, valueAndNote});
    }
    if (total <= strip + 1.0f) return d;
  }
  return MetricDetail::Values;
}

// A narrow strip (a small window or a large UI scale) drops the metrics' notes, then their SDs
// (detailThatFits), then a metric that does not fit at all, rather than cutting it at the edge.
// The strip's first metric starts its row (`first`); the others follow on the same line.
void metric(const AppState& s, bool first, const char* label, const char* value, const char* note, float width,
            bool notes, const ImVec4& colour = ImGui::GetStyleColorVec4(ImGuiCol_Text)) {
  if (!first) ImGui::SameLine();
  const float avail = ImGui::GetContentRegionAvail().x;
  const float valueW = valueWidth(s, value);
  const float noteW = ImGui::CalcTextSize(note).x + ImGui::GetStyle().ItemSpacing.x;
  if (std::max(ImGui::CalcTextSize(label).x, valueW) > avail) return;
  ImGui::BeginGroup();
  ImGui::TextDisabled("%s", label);
  if (s.fonts.large) ImGui::PushFont(s.fonts.large);
  ImGui::TextColored(colour, "%s", value);
  if (s.fonts.large) ImGui::PopFont();
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

}  // namespace

void MetricsPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "##metrics", rect, ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar)) {
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
    } else if (!s.view.overlays.metrics) {
      ImGui::TextDisabled("metrics hidden (overlay \"metrics\")");
    } else if (const std::vector<MetricItem> items = metricItems(s); !items.empty()) {
      const float w = std::max(150.0f * ctx.scale, (ImGui::GetContentRegionAvail().x - 8.0f) / 5.0f);
      const MetricDetail detail = detailThatFits(s, items, w);
      for (std::size_t k = 0; k < items.size(); ++k)
        metric(s, k == 0, items[k].label.c_str(), shownValue(items[k], detail).c_str(), items[k].note.c_str(), w,
               detail == MetricDetail::NotesAndSds, toneColour(items[k].tone));
    } else if (s.doc.mode == Mode::Clip) {
      ImGui::TextDisabled(s.clip.fits.running() ? "fitting the camera…" : "no fit");
    } else {
      ImGui::TextDisabled(s.jobsBusy() ? "working…" : "no reconstruction");
    }
  }
  ImGui::End();
}

}  // namespace ew::ui
