#include "ui/app/theme.h"
#include "ui/panels/analysis_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <vector>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/convert.h"
#include "ui/render/palette.h"
#include "ui/widgets/flow.h"
#include "ui/widgets/plot.h"

namespace ew::ui {

namespace {

const ImU32 kLsqColour = toImU32(palette::kLsq);
const ImU32 kMapColour = toImU32(palette::kMap);

double sweepValue(const SigmaSweepRow& row, ErrorMetric m) {
  switch (m) {
    case ErrorMetric::AbsMm2: return row.meanAbsErrorMm2;
    case ErrorMetric::Relative: return row.meanRelError;
    case ErrorMetric::MpjpeMm: return row.mpjpeMm;
  }
  return 0.0;
}

std::string axisLabel(ErrorMetric m) {
  const std::string unit = metricUnit(m);
  return std::string(metricName(m)) + (unit.empty() ? " (relative)" : " (" + unit + ")");
}

}  // namespace

void AnalysisPanel::drawControls(AppState& s, float scale) {
  ImGui::AlignTextToFramePadding();
  ImGui::TextDisabled("metric");
  int m = static_cast<int>(metric);
  const char* metrics[] = {"E_a (mm²)", "E_r", "MPJPE (mm)"};
  for (int k = 0; k < 3; ++k) {
    sameLineOrWrap(toggleWidth(metrics[k]));
    ImGui::RadioButton(metrics[k], &m, k);
  }
  metric = static_cast<ErrorMetric>(m);
  sameLineOrWrap(toggleWidth("LSQ"));
  ImGui::Checkbox("LSQ", &showLsq);
  sameLineOrWrap(toggleWidth("MAP"));
  ImGui::Checkbox("MAP", &showMap);
  sameLineOrWrap(toggleWidth("other engines"));
  ImGui::Checkbox("other engines", &showEngines);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("The snippet and skeleton engines at every view (leave-one-subject-out, each walker walked\n"
                      "2 cycles at 1.3 m/s): MPJPE and E_a. On in compare mode.");
  sameLineOrWrap(220.0f * scale + ImGui::GetStyle().ItemSpacing.x + buttonWidth("Export CSV"));
  ImGui::SetNextItemWidth(220.0f * scale);
  ImGui::InputText("##csv", csvPath.data(), csvPath.size());
  ImGui::SameLine();
  if (ImGui::Button("Export CSV")) {
    try {
      actions::exportAnalysisCsv(s, csvPath.data());
      status = std::string("wrote ") + csvPath.data();
    } catch (const std::exception& e) {
      status = std::string("CSV export failed: ") + e.what();
      s.log.error(status);
    }
  }
}

void AnalysisPanel::draw(AppState& s, const FrameContext& ctx) {
  if (!open) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // Most of a small window or a large UI scale's width, as the gait report.
  const float width = floatingExtent(display.x, 0.62f, 900.0f * ctx.scale, 40.0f * ctx.scale);
  if (s.panels.tour.active && s.panels.tour.lastHeight > 0.0f) {
    // During the tour: between the header and the tour's window.
    const float tourBottom = s.panels.tour.bottom > 0.0f ? s.panels.tour.bottom : display.y;
    const float top = 52.0f * ctx.scale, bottom = tourBottom - s.panels.tour.lastHeight - 28.0f * ctx.scale;
    ImGui::SetNextWindowSize(ImVec2(width, std::max(200.0f, bottom - top)), ImGuiCond_Always);
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, top), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  } else {
    const float height = floatingExtent(display.y, 0.78f, 640.0f * ctx.scale, 80.0f * ctx.scale);
    ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.53f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  }
  // Scrolls only when the plots' least sizes do not fit (a short window, a large UI scale).
  if (!ImGui::Begin("Analysis: error against view angle (leave-one-subject-out)", &open,
                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  actions::requestAnalysis(s);
  const auto result = s.jobs.analysis.find(actions::analysisKey(s));
  // The selected walker's own curves when it is one of the analysed subjects.
  const std::string subject = actions::analysisSubject(s);

  drawControls(s, ctx.scale);
  if (s.jobs.analysis.running()) {
    ImGui::ProgressBar(s.jobs.analysis.fraction(), ImVec2(-1.0f, 0.0f),
                       ("computing: " + s.jobs.analysis.what()).c_str());
  } else if (!s.jobs.analysis.error().empty()) {
    ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.5f, 1.0f), "%s", ("Analysis failed: " + s.jobs.analysis.error()).c_str());
  } else if (result) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%zu held-out subjects of %s · σ² = %.0f mm² · N = %s · %.1f s (cached by inputs)%s%s",
                       result->subjects.size(), result->from.c_str(), result->key.sigma2Mm2,
                       result->key.components > 0 ? std::to_string(result->key.components).c_str() : "95 % per fold",
                       result->seconds, status.empty() ? "" : " · ", status.c_str());
    if (!result->engines.empty() && metric == ErrorMetric::Relative)
      ImGui::TextWrapped("E_r needs the variance of the missing depth of the eigenwalker's model: the other engines "
                         "show MPJPE and E_a");
    ImGui::PopStyleColor();
  }
  if (!result) {
    if (!s.jobs.analysis.running() && s.jobs.analysis.error().empty()) ImGui::TextDisabled("waiting for data…");
    ImGui::End();
    return;
  }

  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float gap = 10.0f * ctx.scale;
  // The two small plots side by side while each keeps 300 px of the UI's width, else one
  // under the other; no plot shorter than its axes and legend need.
  const bool sideBySide = 0.5f * (avail.x - gap) >= 300.0f * ctx.scale;
  const float topH = std::max(avail.y * (sideBySide ? 0.58f : 0.4f), 180.0f * ctx.scale);

  // Error against view angle.
  std::vector<std::vector<double>> ys;
  std::vector<PlotSeries> series;
  ys.reserve(8);  // the series hold spans into ys: no reallocation
  const std::span<const double> angles(result->anglesDeg);
  for (const char* method : {"lsq", "map"}) {
    const bool lsq = std::string(method) == "lsq";
    if ((lsq && !showLsq) || (!lsq && !showMap)) continue;
    const ImU32 colour = lsq ? kLsqColour : kMapColour;
    ys.push_back(errorCurve(*result, subject, method, metric));
    series.push_back({subject + (lsq ? " LSQ" : " MAP"), angles, ys.back(), colour, 2.6f, false, true});
    ys.push_back(errorCurve(*result, "", method, metric));
    series.push_back({std::string("mean of all subjects ") + (lsq ? "LSQ" : "MAP"), angles, ys.back(),
                      (colour & 0x00FFFFFF) | 0xB0000000, 2.0f, true, false});
  }
  // The other engines' curves: their 15° points only (the angles between are NaN).
  std::vector<std::vector<double>> xs;
  xs.reserve(4);  // the series hold spans into xs too
  const auto addEngineCurve = [&](const std::string& who, EngineKind engine, const std::string& label, ImU32 colour,
                                  float thickness, bool dashed, bool points) {
    const std::vector<double> y = engineErrorCurve(*result, who, engine, metric);
    xs.emplace_back();
    ys.emplace_back();
    for (std::size_t i = 0; i < y.size(); ++i)
      if (std::isfinite(y[i])) xs.back().push_back(result->anglesDeg[i]), ys.back().push_back(y[i]);
    series.push_back({label, xs.back(), ys.back(), colour, thickness, dashed, points});
  };
  for (EngineKind engine : {EngineKind::Snippet, EngineKind::Skeleton}) {
    if (result->engines.empty() || metric == ErrorMetric::Relative) break;
    const ImU32 colour = toImU32(palette::kEngineRight[static_cast<std::size_t>(engine)]);
    if (!subject.empty()) addEngineCurve(subject, engine, subject + " " + engineName(engine), colour, 2.6f, false, true);
    addEngineCurve("", engine, std::string("mean of all subjects ") + engineName(engine),
                   (colour & 0x00FFFFFF) | 0xB0000000, 2.0f, true, false);
  }
  PlotSpec angleSpec;
  angleSpec.xLabel = "view angle α (°; 0 = frontal, ±90 = profile)";
  angleSpec.yLabel = axisLabel(metric);
  angleSpec.xUnit = "°";
  angleSpec.legendBottom = true;
  char alphaLabel[32];
  std::snprintf(alphaLabel, sizeof alphaLabel, "α = %.0f°", s.doc.recon.alphaDeg);
  if (std::abs(s.doc.recon.alphaDeg) <= 90.0)
    angleSpec.markers.push_back({s.doc.recon.alphaDeg, alphaLabel, ImGui::ColorConvertFloat4ToU32(goodTextColour())});
  drawPlot("##angle", ImVec2(avail.x, topH), angleSpec, series, ctx.scale);

  // σ² sweep and spectrum side by side.
  const float rest = avail.y - topH - gap * 0.5f - 2.0f * ImGui::GetStyle().ItemSpacing.y - 2.0f;
  const float bottomH = std::max(sideBySide ? rest : 0.5f * (rest - ImGui::GetStyle().ItemSpacing.y), 120.0f * ctx.scale);
  const float halfW = sideBySide ? 0.5f * (avail.x - gap) : avail.x;
  std::vector<double> sx, mapY, lsqY;
  for (const auto& row : result->sigmaSweep) {
    if (row.method == "map") {
      sx.push_back(row.sigma2Mm2);
      mapY.push_back(sweepValue(row, metric));
    }
  }
  for (const auto& row : result->sigmaSweep)
    if (row.method == "lsq") lsqY.push_back(sweepValue(row, metric));
  lsqY.resize(sx.size(), lsqY.empty() ? std::nan("") : lsqY.front());
  std::vector<PlotSeries> sigmaSeries{{"MAP, mean", sx, mapY, kMapColour, 2.4f, false, true},
                                      {"LSQ (no σ²)", sx, lsqY, kLsqColour, 2.0f, true, false}};
  PlotSpec sigmaSpec;
  sigmaSpec.xLabel = "MAP prior σ² (mm², log)";
  // The two small plots name their curves in their axis labels rather than a legend, which
  // would take most of their height in a short window (the colours are the top plot's).
  sigmaSpec.yLabel = "MAP " + axisLabel(metric) + ", mean over subjects and angles; LSQ dashed";
  sigmaSpec.xLog = true;
  sigmaSpec.legend = false;
  char sigmaLabel[40];
  std::snprintf(sigmaLabel, sizeof sigmaLabel, "σ² = %.0f", s.doc.recon.sigma2Mm2);
  sigmaSpec.markers.push_back({s.doc.recon.sigma2Mm2, sigmaLabel, ImGui::ColorConvertFloat4ToU32(goodTextColour())});
  ImGui::Dummy(ImVec2(0.0f, gap * 0.5f));
  drawPlot("##sigma", ImVec2(halfW, bottomH), sigmaSpec, sigmaSeries, ctx.scale);

  std::vector<double> cx, ev;
  for (const auto& row : result->spectrum) {
    cx.push_back(row.component);
    ev.push_back(row.eigenvalueMm2);
  }
  std::vector<PlotSeries> spectrumSeries{{"eigenvalue λ_n", cx, ev, ImGui::GetColorU32(ImGuiCol_Text), 2.0f, false, true}};
  PlotSpec spectrumSpec;
  spectrumSpec.xLabel = "component n";
  spectrumSpec.yLabel = "eigenvalue λ_n (mm², log; model of every walker)";
  spectrumSpec.yLog = true;
  spectrumSpec.valueFormat = "%.4g mm²";
  spectrumSpec.legend = false;
  if (const auto* r = s.derived.recon()) {
    char nLabel[32];
    std::snprintf(nLabel, sizeof nLabel, "N = %d", r->components);
    spectrumSpec.markers.push_back({static_cast<double>(r->components), nLabel, ImGui::ColorConvertFloat4ToU32(goodTextColour())});
  }
  if (sideBySide) ImGui::SameLine(0.0f, gap);
  drawPlot("##spectrum", ImVec2(halfW, bottomH), spectrumSpec, spectrumSeries, ctx.scale);
  ImGui::End();
}

}  // namespace ew::ui
