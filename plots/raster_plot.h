#pragma once
// The experiments' figures (core/experiments/plot.h) drawn into PNG files with OpenCV: the
// raster back end, kept out of core (core is Eigen only). The CLI's `evaluate` writes its
// figures with rasterPlotWriter().

#include <filesystem>

#include "core/experiments/plot.h"

namespace ew {

// Write a PNG (width × height pixels). Throw Error(Io) when the file cannot be written,
// Error(BadArgument) for a size outside 320-8192 × 240-8192, series whose x, y (and spread)
// differ in length, non-finite axis limits, a log axis with a limit ≤ 0, a tick step ≤ 0,
// or bar groups with more values than series colours. Non-finite points (and x ≤ 0 on a
// log axis) are gaps: not drawn, not in the axis range.
void saveLinePlot(const std::filesystem::path& file, const LinePlot& plot, int width = 960, int height = 640);
void saveBarPlot(const std::filesystem::path& file, const BarPlot& plot, int width = 960, int height = 720);

// saveLinePlot and saveBarPlot at their default sizes.
PlotWriter rasterPlotWriter();

}  // namespace ew
