#pragma once
// The experiments' figures as data (paper-style: axes, ticks, units, legend). Drawing them
// is not core's: a PlotWriter does it (plots/raster_plot.h draws PNGs with OpenCV; the CLI
// passes it). Without a writer no figure is written and everything else still works.

#include <array>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/experiments/experiments.h"

namespace ew {

using Rgb = std::array<int, 3>;

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
  std::vector<double> spread;  // optional ± band around y (same length), e.g. one SD
  Rgb color{0, 0, 0};
  bool dashed = false;
  bool markers = false;
  bool lines = true;  // false: points only (a scatter); needs markers
};

struct LinePlot {
  std::string title, xLabel, yLabel;
  std::vector<PlotSeries> series;
  bool logX = false;
  std::optional<double> xMin, xMax, yMin, yMax;  // default: the data's range (y from 0)
  // A series with an empty label is drawn but not listed in the legend.
  std::optional<double> xTickStep;
  std::vector<std::string> notes;  // short lines printed under the legend
};

struct BarGroup {
  std::string label;            // one row of horizontal bars
  std::vector<double> values;   // one per series
};

struct BarPlot {
  std::string title, valueLabel;
  std::vector<std::string> seriesLabels;
  std::vector<Rgb> seriesColors;
  std::vector<BarGroup> groups;
  std::optional<double> referenceValue;  // vertical dashed line (e.g. nothing missing)
  std::string referenceLabel;
};

// Writes a figure to a file (PNG for the raster writer). Empty members: no figures.
struct PlotWriter {
  std::function<void(const std::filesystem::path&, const LinePlot&)> line;
  std::function<void(const std::filesystem::path&, const BarPlot&)> bar;
  explicit operator bool() const { return line && bar; }
};

// The figures of the experiments that ran (paper figures 2, 3, 5a–c, 6, and the noise and
// missing-joint extensions) into `dir` with `writer`; returns the file names written (none
// without a writer).
std::vector<std::string> writeEvaluationPlots(const std::filesystem::path& dir,
                                              const EvaluationResults& results, const PlotWriter& writer);

}  // namespace ew
