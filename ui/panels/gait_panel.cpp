#include "ui/panels/gait_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/engines/engine.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/held_model.h"
#include "ui/convert.h"
#include "ui/panels/panel_window.h"
#include "ui/render/palette.h"
#include "ui/widgets/flow.h"
#include "ui/widgets/plot.h"

namespace ew::ui {

namespace {

ImU32 mocapColour() { return toImU32(glm::vec4(palette::kGhostRight.x, palette::kGhostRight.y, palette::kGhostRight.z, 1.0f)); }
ImU32 reconColour(int engine = -1) {
  return toImU32(engine < 0 ? palette::kReconRight : palette::kEngineRight[static_cast<std::size_t>(engine)]);
}
ImU32 bandColour() { return ImGui::GetColorU32(ImGuiCol_TextDisabled); }

// What the report compares: the walker's own fit and what the viewer shows beside it.
struct ShownColumn {
  std::string name, label;
  int engine = -1;
  const Eigen::VectorXd* w = nullptr;
  std::optional<double> speedMps;  // a clip's fit knows its speed through the camera
};
struct Shown {
  const Eigen::VectorXd* mocapW = nullptr;  // null in explore mode
  std::vector<ShownColumn> columns;
  double strideHz = 0.0;
  std::optional<double> speedMps;
  std::string walker;
};

// A keypoint clip's or tracked video's walker: the eigenwalker fitted through the estimated
// camera, at the stride and speed that fit found (no motion capture to set beside it).
std::optional<Shown> shownClip(const AppState& s) {
  const ClipResult* clip = s.clip.fit().get();
  if (!clip || clip->rec.fit.w.size() == 0 || !(clip->rec.fit.strideHz > 0.0)) return std::nullopt;
  const CameraFit& f = clip->rec.fit;
  Shown out;
  out.strideHz = f.strideHz;
  out.walker = clip->settings.path.filename().string();
  // Walking in place, the speed is the stance feet's: the report reads it off them itself.
  out.columns.push_back({"reconstruction", "through the estimated camera", -1, &f.w,
                         f.inPlace ? std::nullopt : std::optional<double>(f.speedMps)});
  return out;
}

std::optional<Shown> shownWalkers(const AppState& s) {
  Shown out;
  if (s.doc.mode == Mode::Clip) return shownClip(s);
  if (s.doc.mode == Mode::Explore) {
    const ExploreResult* e = s.derived.explore();
    if (!e) return std::nullopt;
    out.columns.push_back({"synthesised", "synthesised", -1, &e->w, std::nullopt});
    out.strideHz = e->strideHz;
    out.walker = "synthesised from the sliders";
    return out;
  }
  if (s.doc.mode != Mode::Reconstruct) return std::nullopt;
  const ReconBase* r = s.derived.recon();
  const ReconDisplay* d = s.derived.display();
  const Walker* w = s.doc.selectedWalker();
  if (!r || !d || !w) return std::nullopt;
  out.mocapW = &r->wTrue;
  out.strideHz = r->strideHz;
  if (const WalkerFacts* f = s.doc.selectedFacts()) out.speedMps = f->speedMps;
  out.walker = w->id;
  char label[96];
  if (const CompareResult* c = s.doc.compareEngines ? s.derived.compare() : nullptr) {
    for (const auto& e : c->engines) {
      const auto k = static_cast<std::size_t>(e.engine);
      if (!e.display || !s.doc.compareShown[k]) continue;
      std::snprintf(label, sizeof label, "%s at %.0f°", engineName(e.engine), e.base->alphaUsedDeg);
      out.columns.push_back({engineName(e.engine), label, static_cast<int>(k), &e.display->w, std::nullopt});
    }
    return out;
  }
  std::snprintf(label, sizeof label, "%s at %.0f°", engineName(r->engine), r->alphaUsedDeg);
  out.columns.push_back({"reconstruction", label, -1, &d->w, std::nullopt});
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
  cached = measureFourierWalker(*w, strideHz, speed, name);
}

std::string valueText(double v, int decimals) {
  if (!std::isfinite(v)) return "–";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// One cell's text and its colour.
struct TableCell {
  std::string text;
  ImU32 colour = 0;
};

// The table's headings and cells, column by column: the measure, motion capture (when there is
// any), each column shown, the population's band.
struct TableText {
  std::vector<std::string> headings;
  std::vector<std::vector<TableCell>> rows;
};

TableText tableText(const GaitPanel& p, bool withMocap) {
  TableText t;
  t.headings.push_back("measure");
  if (withMocap) t.headings.push_back("motion capture");  // explore mode and clips have none
  for (const auto& c : p.columns) t.headings.push_back(c.label);
  t.headings.push_back("population mean ± SD");
  const auto& rows = gaitRows();
  for (size_t r = 0; r < rows.size(); ++r) {
    const double mean = p.band ? p.band->rowMean[r] : NAN, sd = p.band ? p.band->rowSd[r] : NAN;
    std::vector<TableCell> row;
    row.push_back({rows[r].label, ImGui::GetColorU32(ImGuiCol_Text)});
    if (withMocap) row.push_back({valueText(gaitRowValue(p.mocap, rows[r].key), rows[r].decimals), mocapColour()});
    for (const auto& c : p.columns) {
      const double b = gaitRowValue(c.summary, rows[r].key);
      // Outside the population's mean ± 2 SD: marked, as a gait report flags a measure.
      const bool outside = std::isfinite(b) && std::isfinite(sd) && sd > 0 && std::abs(b - mean) > 2.0 * sd;
      row.push_back({valueText(b, rows[r].decimals) + (outside ? "  (beyond 2 SD)" : ""), reconColour(c.engine)});
    }
    row.push_back({valueText(mean, rows[r].decimals) + " ± " + valueText(sd, rows[r].decimals), bandColour()});
    t.rows.push_back(std::move(row));
  }
  return t;
}

// Each column's width for its widest text, padding included.
std::vector<float> naturalWidths(const TableText& t) {
  const float pad = 2.0f * ImGui::GetStyle().CellPadding.x;
  std::vector<float> widths;
  for (const auto& h : t.headings) widths.push_back(ImGui::CalcTextSize(h.c_str()).x + pad);
  for (const auto& row : t.rows)
    for (size_t c = 0; c < row.size(); ++c)
      widths[c] = std::max(widths[c], ImGui::CalcTextSize(row[c].text.c_str()).x + pad);
  return widths;
}

// The columns share the window's width as their text does. A window too narrow for the text
// (a small one, a large UI scale) scrolls the table sideways with the measure's column held,
// rather than cutting values, headings or "beyond 2 SD" short.
void drawTable(const GaitPanel& p, bool withMocap) {
  const TableText t = tableText(p, withMocap);
  const std::vector<float> widths = naturalWidths(t);
  float total = 0.0f;
  for (float w : widths) total += w;
  const ImGuiStyle& style = ImGui::GetStyle();
  const bool fits = total <= ImGui::GetContentRegionAvail().x;
  ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV;
  ImVec2 outer(0.0f, 0.0f);
  if (fits) {
    flags |= ImGuiTableFlags_SizingStretchProp;
  } else {
    flags |= ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_ScrollX;
    const float rowH = ImGui::GetTextLineHeight() + 2.0f * style.CellPadding.y;
    outer.y = static_cast<float>(t.rows.size() + 1) * rowH + style.ScrollbarSize + 2.0f * style.CellPadding.y;
  }
  const int n = static_cast<int>(t.headings.size());
  if (!ImGui::BeginTable("gait_table", n, flags, outer)) return;
  if (!fits) ImGui::TableSetupScrollFreeze(1, 0);
  for (int c = 0; c < n; ++c)
    ImGui::TableSetupColumn(t.headings[static_cast<size_t>(c)].c_str(),
                            fits ? ImGuiTableColumnFlags_WidthStretch : ImGuiTableColumnFlags_WidthFixed,
                            fits ? widths[static_cast<size_t>(c)] : 0.0f);
  ImGui::TableHeadersRow();
  for (const auto& row : t.rows) {
    ImGui::TableNextRow();
    for (const TableCell& cell : row) {
      ImGui::TableNextColumn();
      ImGui::PushStyleColor(ImGuiCol_Text, cell.colour);
      ImGui::TextUnformatted(cell.text.c_str());
      ImGui::PopStyleColor();
    }
  }
  ImGui::EndTable();
}

struct CurveCell {
  const char* base;   // "knee_angle"
  const char* title;  // "knee flexion (°)"
};

void drawCurve(const GaitPanel& p, const CurveCell& cell, const ImVec2& size, float scale) {
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
  const auto add = [&](const GaitSummary& s, const std::string& label, ImU32 colour) {
    for (const auto& c : s.curves)
      if (c.name == name && c.meanDeg.size() == 101)
        series.push_back({label, x, std::span<const double>(c.meanDeg.data(), 101), colour, 2.0f});
  };
  add(p.mocap, "motion capture", mocapColour());
  for (const auto& col : p.columns) add(col.summary, col.label, reconColour(col.engine));
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
void drawLegend(const GaitPanel& gp, bool withMocap, float scale) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float h = ImGui::GetTextLineHeight();
  bool first = true;
  auto entry = [&](ImU32 colour, const char* label, bool band) {
    const float w = 24.0f * scale;
    const float entryW = w + 6.0f * scale + ImGui::CalcTextSize(label).x;
    if (!first) sameLineOrWrap(entryW, 18.0f * scale);
    first = false;
    const ImVec2 p = ImGui::GetCursorScreenPos();
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
  for (const auto& c : gp.columns) entry(reconColour(c.engine), c.label.c_str(), false);
  entry(bandColour(), "population mean ± SD", true);
}

void drawExport(AppState& s, GaitPanel& p, float scale) {
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
    ImGui::SetTooltip("the reconstruction (in compare mode the selected engine's) walked over the floor at its\n"
                      "measured speed, as an OpenSim marker file, and its joint angles as an OpenSim motion file");
  sameLineOrWrap(buttonWidth("C3D"));
  if (ImGui::Button("C3D")) run("C3D", [&] { actions::exportGaitReport(s, base + ".c3d"); });
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("the same walk with its gait events, as a C3D file for gait labs' tools (Visual3D, Mokka)");
  if (!p.status.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", p.status.c_str());
  }
}

}  // namespace

const GaitSummary& GaitPanel::recon() const {
  static const GaitSummary none;
  if (columns.empty()) return none;
  for (const auto& c : columns)
    if (c.name == "reconstruction" || c.name == "synthesised") return c.summary;
  return columns.front().summary;
}

std::vector<GaitColumn> GaitPanel::exportColumns() const {
  std::vector<GaitColumn> out;
  for (const auto& c : columns) out.push_back({c.name, &c.summary});
  return out;
}

// The band is of the walkers the report's walker is measured against: the model held when it
// is not the population's own (the default model of real walkers, an opened .ewm), else the
// loaded population (whose every walker is exact, not a model's part of it).
void GaitPanel::updateBand(const AppState& s) {
  const EigenwalkerModel* held = heldModelOtherThanThePopulations(s.doc);
  const bool fromModel = held != nullptr;
  if (!fromModel && !s.doc.population) return;
  auto key = std::make_tuple(s.doc.generation, static_cast<int>(s.doc.modelSource),
                             static_cast<const void*>(fromModel ? held : nullptr), heldModelName(s.doc));
  if (band && key == bandKey) return;
  band = std::make_shared<const GaitBand>(fromModel ? modelGaitBand(*held, heldModelPhrase(s.doc))
                                                    : populationGaitBand(*s.doc.population));
  bandKey = std::move(key);
}

void GaitPanel::update(AppState& s) {
  const auto shown = shownWalkers(s);
  updateBand(s);
  if (!shown) {
    refresh(mocap, mocapW, nullptr, 0.0, std::nullopt, "");
    columns.clear();
    return;
  }
  refresh(mocap, mocapW, shown->mocapW, shown->strideHz, shown->speedMps, shown->walker);
  std::vector<Column> next;
  for (const auto& c : shown->columns) {
    Column col{c.name, c.label, c.engine, {}, {}};
    // Reuse a column already measured for the same walker.
    for (auto& old : columns)
      if (old.name == c.name) col.w = std::move(old.w), col.summary = std::move(old.summary);
    refresh(col.summary, col.w, c.w, shown->strideHz, c.speedMps, shown->walker + " (" + c.label + ")");
    next.push_back(std::move(col));
  }
  columns = std::move(next);
}

void GaitPanel::draw(AppState& s, const FrameContext& ctx) {
  if (!open) return;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  // Wide enough for the table and two plots a row, whatever the window: most of a small one.
  const float width = floatingExtent(display.x, 0.7f, 960.0f * ctx.scale, 40.0f * ctx.scale);
  ImGui::SetNextWindowSize(ImVec2(width, display.y * 0.86f), ImGuiCond_Appearing);
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.53f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::Begin("Gait report", &open, ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  update(s);
  const auto shown = shownWalkers(s);
  if (!shown) {
    textDisabledWrapped(s.doc.mode == Mode::Clip ? "no walker fitted to the clip yet (it is fitted when the keypoints "
                                                   "are read or the video is tracked)"
                                                 : "no walker to measure yet");
    ImGui::End();
    return;
  }
  ImGui::Text("%s", shown->walker.c_str());
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("Each walker's two-harmonic fit walked %.0f cycles, events from its kinematics; the band is "
                     "%s (docs/GAIT.md).",
                     kReportCycles, band ? band->from.c_str() : "not measured yet");
  ImGui::PopStyleColor();
  if (!mocap.error.empty() && shown->mocapW) ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "motion capture: %s", mocap.error.c_str());
  for (const auto& c : columns)
    if (!c.summary.error.empty()) ImGui::TextColored(ImVec4(1, 0.5f, 0.4f, 1), "%s: %s", c.label.c_str(), c.summary.error.c_str());
  drawTable(*this, shown->mocapW != nullptr);
  ImGui::AlignTextToFramePadding();
  ImGui::TextDisabled("curves of the");
  ImGui::SameLine();
  int side = leftSide ? 1 : 0;
  ImGui::RadioButton("right side", &side, 0);
  ImGui::SameLine();
  ImGui::RadioButton("left side", &side, 1);
  leftSide = side == 1;
  ImGui::Dummy(ImVec2(0.0f, 0.0f));  // the legend starts its own line (its entries are SameLine)
  drawLegend(*this, shown->mocapW != nullptr, ctx.scale);
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
    drawCurve(*this, cells[k], ImVec2(cellW, cellH), ctx.scale);
  }
  drawExport(s, *this, ctx.scale);
  ImGui::End();
}

}  // namespace ew::ui
