// The analysis window, end to end: shown by a script, it computes the leave-one-subject-out
// curves in the background and draws them (LSQ curves in their blue); the curves export
// as CSV with one row per view angle.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

using GuiAnalysis = GuiTest;

// The LSQ curves' blue (110, 170, 255).
bool isLsqBlue(int r, int g, int b) { return std::abs(r - 110) < 30 && std::abs(g - 170) < 30 && b > 225; }

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(cell);
  return out;
}

TEST_F(GuiAnalysis, DrawsTheCurvesAndExportsThemAsCsv) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"play": false},
    {"screenshot": ")" + d + R"(/without.png"},
    {"show_panel": ["analysis", true]},
    {"set_analysis_metric": "E_a"},
    {"set_angle": 45},
    {"screenshot": ")" + d + R"(/with.png"},
    {"export_analysis_csv": ")" + d + R"(/analysis.csv"},
    {"show_panel": ["analysis", false]}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;

  const cv::Mat without = cv::imread(d + "/without.png"), with = cv::imread(d + "/with.png");
  ASSERT_FALSE(without.empty() || with.empty());
  const Region plot{0.2, 0.2, 0.8, 0.6};
  const int blueWith = countPixels(crop(with, plot), isLsqBlue);
  const int blueWithout = countPixels(crop(without, plot), isLsqBlue);
  std::printf("LSQ-blue pixels: %d with the analysis window, %d without\n", blueWith, blueWithout);
  EXPECT_GT(blueWith, 300) << "no LSQ curves drawn";
  EXPECT_GT(blueWith, 3 * blueWithout + 100);

  std::ifstream in(dir / "analysis.csv");
  ASSERT_TRUE(in) << "analysis.csv missing";
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("# eigenwalker analysis", 0), 0u) << line;
  std::getline(in, line);
  const auto header = split(line);
  ASSERT_EQ(header.size(), 13u) << line;  // angle + {subject, mean} × {lsq, map} × 3 metrics
  EXPECT_EQ(header[0], "angle_deg");
  EXPECT_EQ(header[1], "SYN005_lsq_abs_error_mm2");
  int rows = 0;
  double lsqMean = 0.0, mapMean = 0.0;
  while (std::getline(in, line) && !line.empty()) {
    const auto cells = split(line);
    ASSERT_EQ(cells.size(), header.size()) << line;
    EXPECT_NEAR(std::stod(cells[0]), -90.0 + 5.0 * rows, 1e-9);
    for (const auto& c : cells) EXPECT_TRUE(std::isfinite(std::stod(c))) << line;
    lsqMean += std::stod(cells[2]);  // mean_lsq_abs_error_mm2
    mapMean += std::stod(cells[8]);  // mean_map_abs_error_mm2
    ++rows;
  }
  EXPECT_EQ(rows, 37);
  // The prior helps on average (METHOD §6, Zhang & Troje 2007 Fig. 4).
  EXPECT_LT(mapMean, lsqMean);
  std::getline(in, line);
  EXPECT_EQ(line.rfind("sigma2_mm2,method", 0), 0u) << line;
}

// A motion-capture file opened with nothing else is reconstructed against the default model of
// real walkers; the analysis holds out that model's walkers in turn (not the synthetic walkers
// shown before), its spectrum is the model's, and the file's subject, one of them, has its own
// curves.
TEST_F(GuiAnalysis, AFileInspectedAgainstTheDefaultModelIsAnalysedAmongItsWalkers) {
  EW_REQUIRE_SHARED_DATA();
  const auto c3d = test::sharedDataDir() / "schreiber-moissenet-2019" / "2014001" / "2014001_C4_05.c3d";
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"open": [")" + c3d.string() + R"("]},
    {"export_analysis_csv": ")" + d + R"(/analysis.csv"}
  ])");
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream in(dir / "analysis.csv");
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  const auto header = split(line);
  ASSERT_EQ(header.size(), 13u) << line;
  EXPECT_EQ(header[1], "SM2014001_lsq_abs_error_mm2");  // the model's name for the subject
  double mapMpjpe = 0.0;
  int rows = 0;
  while (std::getline(in, line) && !line.empty()) {
    mapMpjpe += std::stod(split(line)[12]);  // mean_map_mpjpe_mm
    ++rows;
  }
  ASSERT_EQ(rows, 37);
  // The real walkers held out in turn: about 23 mm (measured 2026-11-27); the synthetic
  // population's would be its own.
  EXPECT_GT(mapMpjpe / rows, 15.0);
  EXPECT_LT(mapMpjpe / rows, 35.0);
  while (std::getline(in, line) && line.rfind("component", 0) != 0) {
  }
  int components = 0;
  while (std::getline(in, line) && !line.empty()) ++components;
  EXPECT_EQ(components, 23);  // the model's spectrum: R − 1 of its 24 walkers
}

// "other engines": the snippet and skeleton engines' curves (core/experiments/
// engine_view_curves.h) drawn in their compare-mode colours and exported beside the
// eigenwalker's.
TEST_F(GuiAnalysis, OtherEnginesCurvesAreDrawnAndExported) {
  // Ten synthetic walkers: a snippet prior per fold makes these curves slow (23 s for the
  // default 50 on this machine, docs/VIEWER_DESIGN.md); ten folds show the same.
  const auto syn = dir / "syn";
  const std::string synth = quote(EW_CLI_PATH) + " synth --out " + quote(syn.string()) +
                            " --count 10 --seed 7 --force > /dev/null 2>&1";
  ASSERT_EQ(std::system(synth.c_str()), 0);
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"open": ")" + (syn / "walkers.csv").string() + R"("},
    {"select_subject": "SYN005"},
    {"play": false},
    {"analysis_engines": true},
    {"show_panel": ["analysis", true]},
    {"wait_frames": 3},
    {"export_analysis_csv": ")" + d + R"(/analysis.csv"},
    {"screenshot": ")" + d + R"(/engines.png"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // The snippet engine's bluish green (kEngineRight[1]: 13, 156, 97) in the angle plot.
  const cv::Mat shot = cv::imread(d + "/engines.png");
  ASSERT_FALSE(shot.empty());
  const int green = countPixels(crop(shot, Region{0.2, 0.2, 0.8, 0.6}), [](int red, int g, int b) {
    return std::abs(red - 13) < 30 && std::abs(g - 156) < 30 && std::abs(b - 97) < 30;
  });
  EXPECT_GT(green, 300) << "no snippet curve drawn";

  std::ifstream in(dir / "analysis.csv");
  std::string line;
  std::getline(in, line);
  std::getline(in, line);
  const auto header = split(line);
  ASSERT_EQ(header.size(), 21u) << line;  // 13 + {subject, mean} × {snippet, skeleton} × {E_a, MPJPE}
  EXPECT_EQ(header[13], "SYN005_snippet_abs_error_mm2");
  EXPECT_EQ(header[20], "mean_skeleton_mpjpe_mm");
  int computed = 0;
  while (std::getline(in, line) && !line.empty()) {
    const auto cells = split(line);
    ASSERT_EQ(cells.size(), header.size()) << line;
    // The other engines every 15°, NaN between.
    const bool onGrid = std::fmod(std::stod(cells[0]) + 90.0, 15.0) == 0.0;
    EXPECT_EQ(std::isfinite(std::stod(cells[16])), onGrid) << line;
    if (!onGrid) continue;
    ++computed;
    // MPJPE (mm) of the subject and the mean, snippet and skeleton. Measured on the synthetic
    // population: tens of mm; a broken projection or a wrong view would be hundreds.
    for (size_t c : {15u, 16u, 19u, 20u}) {
      EXPECT_GT(std::stod(cells[c]), 5.0) << header[c] << " " << line;
      EXPECT_LT(std::stod(cells[c]), 200.0) << header[c] << " " << line;
    }
  }
  EXPECT_EQ(computed, 13);
}

TEST_F(GuiAnalysis, UnknownPanelAndMetricAreErrors) {
  const auto script = writeScript(dir, R"([{"show_panel": ["nonsense", true]}])");
  RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script.string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("nonsense"), std::string::npos) << r.err;
  const auto script2 = writeScript(dir, R"([{"set_analysis_metric": "speed"}])");
  r = runViewer(dir, "--size 800x600 --script " + quote(script2.string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("E_a"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ew::test::gui
