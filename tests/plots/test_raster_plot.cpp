// The raster back end of the experiments' figures (plots/raster_plot.h): what it refuses,
// and what it draws from data with gaps.

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

#include "core/common/nan.h"
#include "plots/raster_plot.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using test::throwsError;

constexpr double kInf = std::numeric_limits<double>::infinity();

class PlotPreconditions : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::makeTempDir("plot_preconditions"); }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  fs::path dir_;
};

TEST_F(PlotPreconditions, SeriesOfMismatchedLengthsAreRefused) {
  LinePlot p;
  p.title = "t";
  p.series.push_back({"a", {1, 2, 3}, {1, 2}, {}, {0, 0, 0}, false, false});
  EXPECT_TRUE(throwsError([&] { saveLinePlot(dir_ / "p.png", p); }, ErrorKind::BadArgument,
                          {"p.png", "plot 't': series 'a' has 3 x, 2 y and 0 spread values"}));
  p.series[0] = {"b", {1, 2}, {1, 2}, {0.5}, {0, 0, 0}, false, false};
  EXPECT_TRUE(throwsError([&] { saveLinePlot(dir_ / "p.png", p); }, ErrorKind::BadArgument,
                          {"plot 't': series 'b' has 2 x, 2 y and 1 spread values"}));
}

TEST_F(PlotPreconditions, ImageSizeAndAxisOptionsAreBounded) {
  LinePlot p;
  p.title = "t";
  p.series.push_back({"a", {1, 2}, {1, 2}, {}, {0, 0, 0}, false, false});
  EXPECT_TRUE(throwsError([&] { saveLinePlot(dir_ / "p.png", p, 100, 80); }, ErrorKind::BadArgument,
                          {"plot 't': the size must be"}));
  p.xTickStep = 0.0;
  EXPECT_TRUE(throwsError([&] { saveLinePlot(dir_ / "p.png", p); }, ErrorKind::BadArgument,
                          {"plot 't': the x tick step must be positive and finite"}));
  p.xTickStep.reset();
  p.logX = true;
  p.xMin = 0.0;
  EXPECT_TRUE(throwsError([&] { saveLinePlot(dir_ / "p.png", p); }, ErrorKind::BadArgument,
                          {"plot 't': a log-scale x axis needs a positive xMin"}));
}

// A log axis over x = 0 looped forever (10^floor(log10 0) = 0, times 10 stays 0); NaN and
// infinite points were converted to pixels. They are now gaps, and the plot is written.
TEST_F(PlotPreconditions, NonFiniteAndNonPositiveLogPointsAreGaps) {
  LinePlot p;
  p.title = "gaps";
  p.logX = true;
  p.series.push_back({"a",
                      {0.0, 1.0, 10.0, 100.0, kNaN},
                      {1.0, kNaN, 3.0, kInf, 5.0},
                      {},
                      {0, 0, 0},
                      false,
                      true});
  p.series.push_back({"b", {1.0, 10.0}, {2.0, 2.5}, {0.1, kNaN}, {255, 0, 0}, true, false});
  saveLinePlot(dir_ / "gaps.png", p);
  EXPECT_GT(fs::file_size(dir_ / "gaps.png"), 0u);
}

// An infinite bar made the tick loop add an infinite step forever.
TEST_F(PlotPreconditions, NonFiniteBarsAreLeftOut) {
  BarPlot p{"bars",
            "value",
            {"lsq", "map"},
            {{0, 0, 255}, {255, 0, 0}},
            {{"a", {1.0, kInf}}, {"b", {kNaN, 2.0}}},
            kInf,
            "ref"};
  saveBarPlot(dir_ / "bars.png", p);
  EXPECT_GT(fs::file_size(dir_ / "bars.png"), 0u);
  p.seriesColors.pop_back();
  EXPECT_TRUE(throwsError([&] { saveBarPlot(dir_ / "bars.png", p); }, ErrorKind::BadArgument,
                          {"plot 'bars': 2 series labels but 1 colours"}));
}

// The noise figure read each row's level with std::stod: a row whose condition is not a
// number threw std::invalid_argument, not an ew::Error. Such rows have no x: left out.
TEST_F(PlotPreconditions, NoiseRowsWithoutANumericLevelAreLeftOut) {
  EvaluationResults r;
  r.ran.insert(Experiment::Noise);
  r.noise.push_back({"S0", "10", 0.0, "lsq", 5.0, 0.1, 50.0, 3.0});
  r.noise.push_back({"S0", "ten", 0.0, "lsq", 5.0, 0.1, 50.0, 3.0});
  r.noise.push_back({"S0", "", 0.0, "map", 5.0, 0.1, 50.0, 3.0});
  const auto names = writeEvaluationPlots(dir_, r, rasterPlotWriter());
  ASSERT_EQ(names.size(), 1u);
  EXPECT_GT(fs::file_size(dir_ / names[0]), 0u);
}

}  // namespace
}  // namespace ew
