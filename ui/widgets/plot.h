#pragma once
// A small line-plot widget on the ImGui draw list: frame, grid, "nice" ticks with units on
// both axes, optional log y, a legend, vertical markers, and a hover read-out (a vertical
// cursor and each series' value at the nearest x). Stateless: everything comes in the
// spec and the series each frame.

#include <imgui.h>

#include <span>
#include <string>
#include <vector>

namespace ew::ui {

struct PlotSeries {
  std::string label;
  std::span<const double> x, y;  // same length; NaN values break the line
  ImU32 colour = IM_COL32(255, 255, 255, 255);
  float thickness = 2.0f;        // × the UI scale; 0: no line (points only)
  bool dashed = false;
  bool points = false;           // a dot at each sample
  // Optional band drawn under the line (e.g. a normative mean ± SD): same length as x.
  std::span<const double> bandLow = {}, bandHigh = {};
};

struct PlotMarker {
  double x = 0.0;
  std::string label;
  ImU32 colour = IM_COL32(255, 255, 255, 200);
};

struct PlotSpec {
  std::string xLabel, yLabel;   // with units, e.g. "view angle α (°)", "E_a (mm²)"
  std::string xUnit;            // appended to tick labels, e.g. "°"
  bool xLog = false;            // log10 x axis (positive x only)
  bool yLog = false;            // log10 y axis (positive y only)
  bool yFromZero = true;        // linear y: include 0
  std::vector<PlotMarker> markers;
  const char* valueFormat = "%.3g";  // hover read-out
  bool legendBottom = false;    // legend in the bottom-right corner instead of the top-right
  bool legend = true;           // false: no legend (the caller draws one for several plots)
};

// Draws the plot filling `size` at the cursor (an ImGui item: hover works like a button).
void drawPlot(const char* id, const ImVec2& size, const PlotSpec& spec, std::span<const PlotSeries> series,
              float scale);

// Up to ~`target` round tick values covering [lo, hi] (steps of 1, 2 or 5 × 10^k).
std::vector<double> niceTicks(double lo, double hi, int target);

}  // namespace ew::ui
