#include "ui/panels/gait_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/engines/engine.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/convert.h"
#include "ui/render/palette.h"
#include "ui/widgets/plot.h"

namespace ew::ui {

namespace {

ImU32 mocapColour() { return toImU32(glm::vec4(palette::kGhostRight.x, palette::kGhostRight.y, palette::kGhostRight.z, 1.0f)); }
ImU32 reconColour() { return toImU32(palette::kReconRight); }
ImU32 bandColour() { return ImGui::GetColorU32(ImGuiCol_TextDisabled); }

// What the report compares: the walker's own fit and what the viewer shows beside it.
struct Shown {
  const Eigen::VectorXd* mocapW = nullptr;  // null in explore mode
  const Eigen::VectorXd* reconW = nullptr;
  double strideHz = 0.0;
  std::optional<double> speedMps;
  std::string walker, reconLabel;
};

std::optional<Shown> shownWalkers(const AppState& s) {
  Shown out;
  if (s.doc.mode == Mode::Explore) {
    const ExploreResult* e = s.derived.explore();
    if (!e) return std::nullopt;
    out.reconW = &e->w;
    out.strideHz = e->strideHz;
    out.walker = "synthesised from the sliders";
    out.reconLabel = "synthesised";
    return out;
  }
  if (s.doc.mode != Mode::Reconstruct) return std::nullopt;
  const ReconBase* r = s.derived.recon();
  const ReconDisplay* d = s.derived.display();
  const Walker* w = s.doc.selectedWalker();
  if (!r || !d || !w) return std::nullopt;
  out.mocapW = &r->wTrue;
  out.reconW = &d->w;
  out.strideHz = r->strideHz;
  if (const WalkerFacts* f = s.doc.selectedFacts()) out.speedMps = f->speedMps;
  out.walker = w->id;
  char label[96];
  std::snprintf(label, sizeof label, "%s at %.0f°", engineName(r->engine), r->alphaUsedDeg);
  out.reconLabel = label;
  return out;
}

void refresh(GaitSummary& cached, Eigen::VectorXd& key, const Eigen::VectorXd* w, double strideHz,
             std::optional<double> speed, const std::string& name) {
  if (!w) {
    cached = {};
    key.resize(0);
    return;
  }
  if (key.size() == w->size() && key == *w) return;
  key = *w;
  cached = summarizeFourierWalker(*w, strideHz, speed, name);
}

std::string valueText(double v, int decimals) {
  if (!std::isfinite(v)) return "–";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

void drawTable(const GaitPanel& p, const std::string& reconLabel, bool withMocap) {
  const auto& rows = gaitRows();
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
  if (!ImGui::BeginTable("gait_table", 4, flags)) return;
  ImGui::TableSetupColumn("measure", ImGuiTableColumnFlags_WidthStretch, 1.6f);
  ImGui::TableSetupColumn(withMocap ? "motion capture" : "–", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn(reconLabel.c_str(), ImGuiTableColumnFlags_WidthStretch, 1.2f);
  ImGui::TableSetupColumn("population mean ± SD", ImGuiTableColumnFlags_WidthStretch, 1.3f);
  ImGui::TableHeadersRow();
  for (size_t r = 0; r < rows.size(); ++r) {
    const double mean = p.band ? p.band->rowMean[r] : NAN, sd = p.band ? p.band->rowSd[r] : NAN;
    const double a = gaitRowValue(p.mocap, rows[r].key), b = gaitRowValue(p.recon, rows[r].key);
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(rows[r].label);
    ImGui::TableNextColumn();
    ImGui::PushStyleColor(ImGuiCol_Text, mocapColour());
    ImGui::TextUnformatted(withMocap ? valueText(a, rows[r].decimals).c_str() : "");
    ImGui::PopStyleColor();
    ImGui::TableNextColumn();
    // Outside the population's mean ± 2 SD: marked, as a gait report flags a measure.
    const bool outside = std::isfinite(b) && std::isfinite(sd) && sd > 0 && std::abs(b - mean) > 2.0 * sd;
    ImGui::PushStyleColor(ImGuiCol_Text, reconColour());
    ImGui::TextUnformatted((valueText(b, rows[r].decimals) + (outside ? "  (beyond 2 SD)" : "")).c_str());
    ImGui::PopStyleColor();
    ImGui::TableNextColumn();
    ImGui::TextDisabled("%s ± %s", valueText(mean, rows[r].decimals).c_str(), valueText(sd, rows[r].decimals).c_str());
  }
  ImGui::EndTable();
}

struct CurveCell {
  const char* base;   // "knee_angle"
  const char* title;  // "knee flexion (°)"
};

void drawCurve(const GaitPanel& p, const CurveCell& cell, const std::string& reconLabel, const ImVec2& size,
               float scale) {
  const std::string name = std::string(cell.base) + (p.leftSide ? "_l" : "_r");
  std::vector<double> x(101);
  for (int k = 0; k <= 100; ++k) x[static_cast<size_t>(k)] = k;
  std::vector<double> lo, hi;
  std::vector<PlotSeries> series;
  const Eigen::VectorXd* mean = p.band ? p.band->curveMeanOf(name) : nullptr;
  const Eigen::VectorXd* sd = p.band ? p.band->curveSdOf(name) : nullptr;
  if (mean && sd && mean->size() == 101) {
    lo.resize(101);
    hi.resize(101);
    for (int k = 0; k <= 100; ++k) lo[static_cast<size_t>(k)] = (*mean)[k] - (*sd)[k], hi[static_cast<size_t>(k)] = (*mean)[k] + (*sd)[k];
    PlotSeries band{"population ± SD", x, std::span<const double>(mean->data(), 101), bandColour(), 1.0f, true};
    band.bandLow = lo;
    band.bandHigh = hi;
    series.push_back(band);
  }
  for (const auto* s : {&p.mocap, &p.recon}) {
    for (const auto& c : s->curves) {
      if (c.name != name || c.meanDeg.size() != 101) continue;
      const bool isMocap = s == &p.mocap;
      series.push_back({isMocap ? "motion capture" : reconLabel, x, std::span<const double>(c.meanDeg.data(), 101),
                        isMocap ? mocapColour() : reconColour(), 2.0f});
    }
  }
  PlotSpec spec;
  const char* longLabel = "gait cycle (%, foot strike to foot strike)";
  spec.xLabel = ImGui::CalcTextSize(longLabel).x < size.x - 60.0f * scale ? longLabel : "gait cycle (%)";
  spec.yLabel = cell.title;
  spec.xUnit = "%";
  spec.yFromZero = false;
  spec.valueFormat = "%.1f°";
  spec.legend = false;  // one legend above the four plots
  drawPlot(name.c_str(), size, spec, series, scale);
}

// One legend for the four plots: a swatch and a name per series.
void drawLegend(const std::string& reconLabel, bool withMocap, float scale) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float h = ImGui::GetTextLineHeight();
  bool first = true;
  auto entry = [&](ImU32 colour, const char* label, bool band) {
    if (!first) ImGui::SameLine(0.0f, 18.0f * scale);
    first = false;
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float w = 24.0f * scale;
    if (band) {
      dl->AddRectFilled(ImVec2(p.x, p.y + 0.2f * h), ImVec2(p.x + w, p.y + 0.8f * h),
                        (colour & ~IM_COL32_A_MASK) | (static_cast<ImU32>(70) << IM_COL32_A_SHIFT));
    }
    dl->AddLine(ImVec2(p.x, p.y + 0.5f * h), ImVec2(p.x + w, p.y + 0.5f * h), colour, 2.0f * scale);
    ImGui::Dummy(ImVec2(w, h));
    ImGui::SameLine(0.0f, 6.0f * scale);
    ImGui::TextUnformatted(label);
  };
  if (withMocap) entry(mocapColour(), "motion capture", false);
  entry(reconColour(), reconLabel.c_str(), false);
  entry(bandColour(), "population mean ± SD", true);
}

void drawExport(AppState& s, GaitPanel& p, const std::string& walker, const std::string& engine, float scale) {
  ImGui::AlignTextToFramePadding();
  ImGui::TextDisabled("export to");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(220.0f * scale);
  ImGui::InputText("##gait_path", p.basePath.data(), p.basePath.size());
  ImGui::SameLine();
  const std::string base(p.basePath.data());
  auto run = [&](const char* what, const auto& fn) {
    try {
      fn();
    } catch (const std::exception& e) {
      p.status = std::string(what) + " failed: " + e.what();
      s.log.error(p.status);
    }
  };
  if (ImGui::Button("CSV")) run("CSV", [&] { actions::exportGaitReport(s, base + ".csv"); });
  ImGui::SameLine();
  if (ImGui::Button("JSON")) run("JSON", [&] { actions::exportGaitReport(s, base + ".json"); });
  ImGui::SameLine();
  if (ImGui::Button("TRC + MOT")) run("TRC + MOT", [&] { actions::exportGaitReport(s, base + ".trc"); });
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the reconstruction walked over the floor at its measured speed (%s), as an OpenSim marker\n"
                      "file, and its joint angles as an OpenSim motion file", engine.c_str());
  (void)walker;
  if (!p.status.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", p.status.c_str());
  }
}

}  // namespace

void GaitPanel::update(AppState& s) {
  const auto shown = shownWalkers(s);
  if (s.doc.population && (bandGeneration != s.doc.generation || !band)) {
    band = std::make_shared<const GaitBand>(populationGaitBand(*s.doc.population));
    bandGeneration = s.doc.generation;
  }
  if (!shown) {
    refresh(mocap, mocapW, nullptr, 0.0, std::nullopt, "");
    refresh(recon, reconW, nullptr, 0.0, std::nullopt, "");
    return;
  }
  refresh(mocap, mocapW, shown->mocapW, shown->strideHz, shown->speedMps, shown->walker);
  refresh(recon, reconW, shown->reconW, shown->strideHz, std::nullopt, shown->walker + " (" + shown->reconLabel + ")");
}

void GaitPanel::draw(AppState& s, const FrameContext& ctx) {
  if (!open) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // Wide enough for the table and two plots a row, whatever the window: most of a small one.
  const float width = std::min(display.x - 40.0f * ctx.scale, std::max(display.x * 0.7f, 960.0f * ctx.scale));
  ImGui::SetNextWindowSize(ImVec2(width, display.y * 0.86f), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.53f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Gait report", &open, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  update(s);
  const auto shown = shownWalkers(s);
  if (!shown) {
    ImGui::TextDisabled(s.doc.mode == Mode::Clip ? "keypoint clips: not yet (the 3D CSV of `reconstruct` goes "
                                                   "through `eigenwalker-cli gait`)"
                                                 : "no walker to measure yet");
    ImGui::End();
    return;
  }
  ImGui::Text("%s", shown->walker.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("Each walker's two-harmonic fit walked %.0f cycles, events from its kinematics; the band is "
                     "%d walkers of the loaded population (docs/GAIT.md).",
                     kReportCycles, band ? band->walkers : 0);
  ImGui::PopStyleColor();
  if (!mocap.error.empty() && shown->mocapW) ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "motion capture: %s", mocap.error.c_str());
  if (!recon.error.empty()) ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "%s: %s", shown->reconLabel.c_str(), recon.error.c_str());
  drawTable(*this, shown->reconLabel, shown->mocapW != nullptr);
  ImGui::AlignTextToFramePadding();
  ImGui::TextDisabled("curves of the");
  ImGui::SameLine();
  int side = leftSide ? 1 : 0;
  ImGui::RadioButton("right side", &side, 0);
  ImGui::SameLine();
  ImGui::RadioButton("left side", &side, 1);
  leftSide = side == 1;
  ImGui::Dummy(ImVec2(0.0f, 0.0f));  // the legend starts its own line (its entries are SameLine)
  drawLegend(shown->reconLabel, shown->mocapW != nullptr, ctx.scale);
  const float exportH = ImGui::GetFrameHeightWithSpacing() + 4.0f * ctx.scale;
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  // Two rows of two plots; one row of four when two rows would be too flat to read.
  const float plotsH = avail.y - exportH;
  const int perRow = 0.5f * (plotsH - ImGui::GetStyle().ItemSpacing.y) < 150.0f * ctx.scale ? 4 : 2;
  const float cellW = std::max(100.0f * ctx.scale, (avail.x - spacing * static_cast<float>(perRow - 1)) / static_cast<float>(perRow));
  const float rows = static_cast<float>(4 / perRow);
  const float cellH = std::max(110.0f * ctx.scale, (plotsH - ImGui::GetStyle().ItemSpacing.y * (rows - 1.0f)) / rows);
  const CurveCell cells[] = {{"hip_flexion", "hip flexion (°)"}, {"knee_angle", "knee flexion (°)"},
                             {"arm_flex", "shoulder flexion (°)"}, {"elbow_flex", "elbow flexion (°)"}};
  for (int k = 0; k < 4; ++k) {
    if (k % perRow != 0) ImGui::SameLine();
    drawCurve(*this, cells[k], shown->reconLabel, ImVec2(cellW, cellH), ctx.scale);
  }
  drawExport(s, *this, shown->walker, shown->reconLabel, ctx.scale);
  ImGui::End();
}

}  // namespace ew::ui
