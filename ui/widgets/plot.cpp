#include "ui/widgets/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace ew::ui {

std::vector<double> niceTicks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo) || target < 1) return ticks;
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  if (!(step > 0.0) || !std::isfinite(step)) return ticks;
  const double first = std::ceil(lo / step - 1e-9) * step;
  for (int i = 0; i < 1000; ++i) {
    const double v = first + i * step;
    if (v > hi + step * 1e-9) break;
    ticks.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
  }
  return ticks;
}

namespace {

std::string tickLabel(double v, const std::string& unit, bool /*log*/) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%g%s", v, unit.c_str());
  return buf;
}

void dashedLine(ImDrawList* dl, ImVec2 a, ImVec2 b, ImU32 c, float t, float dash);

// `text` cut to `width` with an ellipsis (an axis label longer than a small plot is wide).
std::string elided(const std::string& text, float width) {
  if (ImGui::CalcTextSize(text.c_str()).x <= width) return text;
  const char* ellipsis = "…";
  const float room = width - ImGui::CalcTextSize(ellipsis).x;
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    std::size_t n = 1;  // one UTF-8 character
    while (i + n < text.size() && (static_cast<unsigned char>(text[i + n]) & 0xC0) == 0x80) ++n;
    if (ImGui::CalcTextSize((out + text.substr(i, n)).c_str()).x > room) break;
    out += text.substr(i, n);
    i += n;
  }
  return out + ellipsis;
}

// Every k-th of `ticks` (k ≥ 1), so that labels `extent` px apart in the plot stay `need` px apart.
std::vector<double> thinned(const std::vector<double>& ticks, float extent, float need) {
  if (ticks.size() < 3 || need <= 0.0f) return ticks;
  const float spacing = extent / static_cast<float>(ticks.size() - 1);
  const auto k = static_cast<std::size_t>(std::ceil(need / std::max(spacing, 1.0f)));
  if (k <= 1) return ticks;
  std::vector<double> out;
  for (std::size_t i = 0; i < ticks.size(); i += k) out.push_back(ticks[i]);
  return out;
}

// The legend's entries flowed into rows across `width` (a legend below the plot).
struct LegendRows {
  std::vector<int> rowOf;  // per series
  int rows = 0;
};
LegendRows flowLegend(std::span<const PlotSeries> series, float width, float swatch, float pad) {
  LegendRows out;
  float x = 0.0f;
  for (const auto& s : series) {
    const float w = swatch + pad + ImGui::CalcTextSize(s.label.c_str()).x + 2.0f * pad;
    if (out.rows == 0 || (x > 0.0f && x + w > width)) {
      ++out.rows;
      x = 0.0f;
    }
    out.rowOf.push_back(out.rows - 1);
    x += w;
  }
  return out;
}

void legendSwatch(ImDrawList* dl, const PlotSeries& s, ImVec2 s0, ImVec2 s1, float scale) {
  if (s.dashed) {
    dashedLine(dl, s0, s1, s.colour, s.thickness * scale, 4.0f * scale);
  } else if (s.thickness > 0.0f) {
    dl->AddLine(s0, s1, s.colour, s.thickness * scale);
  }
  // A dot for a series drawn with dots (alone, for a scatter, which has no line to show).
  if (s.points) dl->AddCircleFilled(ImVec2(0.5f * (s0.x + s1.x), 0.5f * (s0.y + s1.y)), 3.0f * scale, s.colour);
}

void dashedLine(ImDrawList* dl, ImVec2 a, ImVec2 b, ImU32 c, float t, float dash) {
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float len = std::sqrt(dx * dx + dy * dy);
  if (len <= 0.0f) return;
  for (float s = 0.0f; s < len; s += 2.0f * dash) {
    const float e = std::min(s + dash, len);
    dl->AddLine(ImVec2(a.x + dx * s / len, a.y + dy * s / len), ImVec2(a.x + dx * e / len, a.y + dy * e / len), c, t);
  }
}

}  // namespace

namespace {

bool hasBand(const PlotSeries& s) { return s.bandLow.size() == s.x.size() && s.bandHigh.size() == s.x.size() && !s.x.empty(); }

// The band under a series: one translucent quad per sample interval where both ends are finite.
template <class ToX, class ToY>
void drawBand(ImDrawList* dl, const PlotSeries& s, const ToX& X, const ToY& Y) {
  if (!hasBand(s)) return;
  const ImU32 fill = (s.colour & ~IM_COL32_A_MASK) | (static_cast<ImU32>(56) << IM_COL32_A_SHIFT);
  for (std::size_t i = 0; i + 1 < s.x.size(); ++i) {
    const double lo0 = s.bandLow[i], hi0 = s.bandHigh[i], lo1 = s.bandLow[i + 1], hi1 = s.bandHigh[i + 1];
    if (!std::isfinite(lo0) || !std::isfinite(hi0) || !std::isfinite(lo1) || !std::isfinite(hi1)) continue;
    dl->AddQuadFilled(ImVec2(X(s.x[i]), Y(hi0)), ImVec2(X(s.x[i + 1]), Y(hi1)), ImVec2(X(s.x[i + 1]), Y(lo1)),
                      ImVec2(X(s.x[i]), Y(lo0)), fill);
  }
}

}  // namespace

void drawPlot(const char* id, const ImVec2& size, const PlotSpec& spec, std::span<const PlotSeries> series,
              float scale) {
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, ImVec2(std::max(size.x, 10.0f), std::max(size.y, 10.0f)));
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float textH = ImGui::GetTextLineHeight();
  const ImU32 textC = ImGui::GetColorU32(ImGuiCol_Text);
  const ImU32 dimC = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  const ImU32 gridC = ImGui::GetColorU32(ImGuiCol_Border, 0.45f);
  const ImU32 frameC = ImGui::GetColorU32(ImGuiCol_FrameBg);

  // Data range.
  double xlo = std::numeric_limits<double>::infinity(), xhi = -xlo, ylo = xlo, yhi = -xlo;
  for (const auto& s : series) {
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      const double x = s.x[i], y = s.y[i];
      if (!std::isfinite(x) || !std::isfinite(y) || (spec.yLog && y <= 0.0) || (spec.xLog && x <= 0.0)) continue;
      xlo = std::min(xlo, x);
      xhi = std::max(xhi, x);
      ylo = std::min(ylo, y);
      yhi = std::max(yhi, y);
      if (hasBand(s) && std::isfinite(s.bandLow[i]) && std::isfinite(s.bandHigh[i])) {
        ylo = std::min(ylo, s.bandLow[i]);
        yhi = std::max(yhi, s.bandHigh[i]);
      }
    }
  }
  if (!std::isfinite(xlo)) {
    dl->AddText(ImVec2(p0.x + 8.0f * scale, p0.y + 8.0f * scale), dimC, "no data");
    return;
  }
  auto tx = [&](double v) { return spec.xLog ? std::log10(v) : v; };
  auto ty = [&](double v) { return spec.yLog ? std::log10(v) : v; };
  double x0 = tx(xlo), x1 = tx(xhi), y0 = ty(ylo), y1 = ty(yhi);
  if (spec.yLog) {
    y0 = std::floor(y0);
    y1 = std::ceil(y1);
    if (y1 <= y0) y1 = y0 + 1.0;
  } else {
    if (spec.yFromZero) y0 = std::min(y0, 0.0);
    if (y1 <= y0) y1 = y0 + 1.0;
    const auto t = niceTicks(y0, y1, 5);
    const double step = t.size() > 1 ? t[1] - t[0] : (y1 - y0);
    y1 = std::ceil(y1 / step - 1e-9) * step;
    y0 = std::floor(y0 / step + 1e-9) * step;
  }
  if (spec.xLog) {
    x0 = std::floor(x0);
    x1 = std::ceil(x1);
  }
  if (x1 <= x0) x1 = x0 + 1.0;
  // A scatter (points without a line) keeps its outermost dots whole: a margin each side.
  const bool scatter =
      std::any_of(series.begin(), series.end(), [](const PlotSeries& s) { return s.points && s.thickness <= 0.0f; });
  if (scatter && !spec.xLog) {
    const double margin = 0.04 * (x1 - x0);
    x0 -= margin;
    x1 += margin;
  }

  // Plot area: y tick labels on the left, x tick labels and the x label below, the y label above.
  std::vector<double> yTicks;
  if (spec.yLog) {
    for (double e = y0; e <= y1 + 1e-9; e += 1.0) yTicks.push_back(std::pow(10.0, e));
  } else {
    yTicks = niceTicks(y0, y1, std::max(2, static_cast<int>(size.y / (textH * 2.6f))));
  }
  float labelW = 0.0f;
  for (double v : yTicks) labelW = std::max(labelW, ImGui::CalcTextSize(tickLabel(v, "", spec.yLog).c_str()).x);
  // The legend stands inside the plot while it leaves most of the plot clear; else it goes in
  // rows under the x axis's label, and the plot gives up the height.
  const float swatch = 22.0f * scale, lpad = 6.0f * scale, rowH = textH + 2.0f * scale;
  float legendTextW = 0.0f;
  for (const auto& sr : series) legendTextW = std::max(legendTextW, ImGui::CalcTextSize(sr.label.c_str()).x);
  const bool legendShown = !series.empty() && spec.legend;
  const float insideW = legendTextW + swatch + 3.0f * lpad, insideH = static_cast<float>(series.size()) * rowH + lpad;
  const float fullPlotW = size.x - labelW - 16.0f * scale, fullPlotH = size.y - 3.0f * textH - 14.0f * scale;
  const bool legendBelow = legendShown && (insideW > 0.45f * fullPlotW || insideH > 0.33f * fullPlotH);
  const LegendRows legendRows = legendBelow ? flowLegend(series, size.x, swatch, lpad) : LegendRows{};
  const float belowH = legendBelow ? static_cast<float>(legendRows.rows) * rowH + 4.0f * scale : 0.0f;
  const ImVec2 a{p0.x + labelW + 8.0f * scale, p0.y + textH + 6.0f * scale};
  const ImVec2 b{p0.x + size.x - 8.0f * scale, p0.y + size.y - 2.0f * textH - 8.0f * scale - belowH};
  if (b.x - a.x < 20.0f || b.y - a.y < 20.0f) return;
  auto X = [&](double v) { return a.x + static_cast<float>((tx(v) - x0) / (x1 - x0)) * (b.x - a.x); };
  auto Y = [&](double v) { return b.y - static_cast<float>((ty(v) - y0) / (y1 - y0)) * (b.y - a.y); };
  // Decades too close for their labels: every second (third, …) one.
  if (spec.yLog) yTicks = thinned(yTicks, b.y - a.y, 1.2f * textH);

  dl->AddRectFilled(a, b, frameC);
  dl->AddText(ImVec2(p0.x, p0.y), dimC, elided(spec.yLabel, size.x).c_str());
  for (double v : yTicks) {
    const float y = Y(v);
    dl->AddLine(ImVec2(a.x, y), ImVec2(b.x, y), gridC);
    const std::string l = tickLabel(v, "", spec.yLog);
    dl->AddText(ImVec2(a.x - 4.0f * scale - ImGui::CalcTextSize(l.c_str()).x, y - 0.5f * textH), dimC, l.c_str());
  }
  std::vector<double> xTicks;
  if (spec.xLog) {
    for (double e = x0; e <= x1 + 1e-9; e += 1.0) xTicks.push_back(std::pow(10.0, e));
  } else {
    xTicks = niceTicks(x0, x1, std::max(2, static_cast<int>((b.x - a.x) / (70.0f * scale))));
  }
  float tickW = 0.0f;
  for (double v : xTicks) tickW = std::max(tickW, ImGui::CalcTextSize(tickLabel(v, spec.xUnit, spec.xLog).c_str()).x);
  xTicks = thinned(xTicks, b.x - a.x, tickW + 8.0f * scale);
  for (double v : xTicks) {
    const float x = X(v);
    dl->AddLine(ImVec2(x, a.y), ImVec2(x, b.y), gridC);
    const std::string l = tickLabel(v, spec.xUnit, spec.xLog);
    const float w = ImGui::CalcTextSize(l.c_str()).x;
    dl->AddText(ImVec2(std::clamp(x - 0.5f * w, p0.x, p0.x + size.x - w), b.y + 3.0f * scale), dimC, l.c_str());
  }
  const std::string xLabel = elided(spec.xLabel, size.x);
  const float xlw = ImGui::CalcTextSize(xLabel.c_str()).x;
  dl->AddText(ImVec2(std::max(p0.x, 0.5f * (a.x + b.x - xlw)), b.y + textH + 5.0f * scale), dimC, xLabel.c_str());

  dl->PushClipRect(a, b, true);
  for (const auto& m : spec.markers) {
    const float x = X(m.x);
    dashedLine(dl, ImVec2(x, a.y), ImVec2(x, b.y), m.colour, 1.5f * scale, 5.0f * scale);
    if (!m.label.empty()) {
      const float w = ImGui::CalcTextSize(m.label.c_str()).x;
      const float lx = x + 4.0f * scale + w > b.x ? x - 4.0f * scale - w : x + 4.0f * scale;
      dl->AddText(ImVec2(lx, a.y + 2.0f * scale), m.colour, m.label.c_str());
    }
  }
  for (const auto& s : series) drawBand(dl, s, X, Y);
  std::vector<ImVec2> run;
  for (const auto& s : series) {
    const std::size_t n = std::min(s.x.size(), s.y.size());
    auto flush = [&] {
      if (run.size() >= 2 && s.thickness > 0.0f) {
        if (s.dashed) {
          for (std::size_t i = 0; i + 1 < run.size(); ++i)
            dashedLine(dl, run[i], run[i + 1], s.colour, s.thickness * scale, 6.0f * scale);
        } else {
          dl->AddPolyline(run.data(), static_cast<int>(run.size()), s.colour, 0, s.thickness * scale);
        }
      }
      run.clear();
    };
    for (std::size_t i = 0; i < n; ++i) {
      const double x = s.x[i], y = s.y[i];
      if (!std::isfinite(x) || !std::isfinite(y) || (spec.yLog && y <= 0.0) || (spec.xLog && x <= 0.0)) {
        flush();
        continue;
      }
      run.push_back(ImVec2(X(x), Y(y)));
      if (s.points) dl->AddCircleFilled(run.back(), 2.5f * scale, s.colour);
    }
    flush();
  }
  dl->PopClipRect();
  dl->AddRect(a, b, gridC);

  if (legendShown && legendBelow) {
    // Rows under the x axis's label, each entry a swatch and its name.
    float x = p0.x;
    int row = 0;
    for (std::size_t i = 0; i < series.size(); ++i) {
      if (legendRows.rowOf[i] != row) row = legendRows.rowOf[i], x = p0.x;
      const float y = b.y + 2.0f * textH + 10.0f * scale + static_cast<float>(row) * rowH;
      legendSwatch(dl, series[i], ImVec2(x, y + 0.5f * textH), ImVec2(x + swatch, y + 0.5f * textH), scale);
      dl->AddText(ImVec2(x + swatch + lpad, y), textC, series[i].label.c_str());
      x += swatch + lpad + ImGui::CalcTextSize(series[i].label.c_str()).x + 2.0f * lpad;
    }
  } else if (legendShown) {
    // Top right (or bottom right), inside the plot.
    const float top = spec.legendBottom ? b.y - lpad - insideH : a.y + lpad + textH;
    const ImVec2 la{b.x - insideW, top};
    const ImVec2 lb{b.x - lpad, top + insideH};
    dl->AddRectFilled(la, lb, ImGui::GetColorU32(ImGuiCol_PopupBg, 0.85f), 4.0f * scale);
    float y = la.y + lpad;
    for (const auto& sr : series) {
      const ImVec2 s0{la.x + lpad, y + 0.5f * textH}, s1{la.x + lpad + swatch, y + 0.5f * textH};
      legendSwatch(dl, sr, s0, s1, scale);
      dl->AddText(ImVec2(s1.x + lpad, y), textC, sr.label.c_str());
      y += rowH;
    }
  }

  // Hover read-out: the nearest sample of each series to the cursor's x.
  if (hovered) {
    const ImVec2 mouse = ImGui::GetMousePos();
    if (mouse.x >= a.x && mouse.x <= b.x) {
      dl->AddLine(ImVec2(mouse.x, a.y), ImVec2(mouse.x, b.y), dimC, 1.0f * scale);
      std::string text;
      for (const auto& s : series) {
        const std::size_t n = std::min(s.x.size(), s.y.size());
        std::size_t best = n;
        float bestD = std::numeric_limits<float>::infinity();
        for (std::size_t i = 0; i < n; ++i) {
          if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
          const float d = std::abs(X(s.x[i]) - mouse.x);
          if (d < bestD) {
            bestD = d;
            best = i;
          }
        }
        if (best == n) continue;
        char value[64], line[256];
        std::snprintf(value, sizeof value, spec.valueFormat, s.y[best]);
        std::snprintf(line, sizeof line, "%s%s: %s at %g%s", text.empty() ? "" : "\n", s.label.c_str(), value,
                      s.x[best], spec.xUnit.c_str());
        text += line;
      }
      if (!text.empty()) ImGui::SetTooltip("%s", text.c_str());
    }
  }
}

}  // namespace ew::ui
