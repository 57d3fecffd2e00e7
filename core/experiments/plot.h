#pragma once
// Small raster plots for the experiments (paper-style figures: axes, ticks, units,
// legend), drawn with OpenCV into PNG files. Without OpenCV at build time no plot is
// written (plotsAvailable() is false) and everything else still works.

#include <array>
#include <filesystem>
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

bool plotsAvailable();

// Write a PNG (width × height pixels). Throw Error(Io) when the file cannot be written,
// Error(BadArgument) for a size outside 320-8192 × 240-8192, series whose x, y (and spread)
// differ in length, non-finite axis limits, a log axis with a limit ≤ 0, a tick step ≤ 0,
// or bar groups with more values than series colours. Non-finite points (and x ≤ 0 on a
// log axis) are gaps: not drawn, not in the axis range.
void saveLinePlot(const std::filesystem::path& file, const LinePlot& plot, int width = 960, int height = 640);
void saveBarPlot(const std::filesystem::path& file, const BarPlot& plot, int width = 960, int height = 720);

// The figures of the experiments that ran (paper figures 2, 3, 5a–c, 6, and the noise and
// missing-joint extensions) into `dir`; returns the file names written (none without OpenCV).
std::vector<std::string> writeEvaluationPlots(const std::filesystem::path& dir,
                                              const EvaluationResults& results);

}  // namespace ew
