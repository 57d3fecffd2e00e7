// The viewer, end to end, on the synthetic default population: the real app under
// xvfb-run with scripts, its screenshots measured with OpenCV.

#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <regex>
#include <string>

#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

using GuiDefault = GuiTest;

TEST_F(GuiDefault, ScriptScreenshotsShowBothViewsAndFollowTheInputs) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"set_method": "map"},
    {"set_angle": 30},
    {"play": false},
    {"set_phase": 0.25},
    {"screenshot": ")" + d + R"(/base.png"},
    {"set_angle": 90},
    {"screenshot": ")" + d + R"(/alpha90.png"},
    {"set_angle": 30},
    {"overlay": ["ghost", false]},
    {"overlay": ["error_lines", false]},
    {"overlay": ["depth_error", false]},
    {"screenshot": ")" + d + R"(/overlays_off.png"},
    {"set_mode": "explore"},
    {"set_coefficient": [1, 2.5]},
    {"screenshot": ")" + d + R"(/explore.png"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;

  const cv::Mat base = load("base.png"), alpha90 = load("alpha90.png");
  const cv::Mat off = load("overlays_off.png"), explore = load("explore.png");
  ASSERT_FALSE(base.empty() || alpha90.empty() || off.empty() || explore.empty());
  EXPECT_EQ(base.cols, 1600);
  EXPECT_EQ(base.rows, 900);

  // Both views are drawn, with their figures: point-lights on the left, the amber
  // reconstruction and the blue ghost on the right.
  const int lights = countPixels(crop(base, kInputView), isPointLight);
  const int amber = countPixels(crop(base, kReconView), isAmber);
  const int ghost = countPixels(crop(base, kReconView), isGhostBlue);
  const int magenta = countPixels(crop(base, kReconView), isMagenta);
  std::printf("point-lights %d, amber %d, ghost %d, magenta %d\n", lights, amber, ghost, magenta);
  EXPECT_GT(lights, 60) << "no point-lights in the 2D view";
  EXPECT_GT(amber, 400) << "no reconstruction in the 3D view";
  EXPECT_GT(ghost, 150) << "no ground-truth ghost in the 3D view";
  EXPECT_LT(countPixels(crop(base, kReconView), isPointLight), lights) << "views swapped?";

  // Changing α changes the 2D view (a profile instead of an oblique view).
  EXPECT_GT(meanAbsDiff(crop(base, kInputView), crop(alpha90, kInputView)), 0.5);

  // Overlays switch off: the ghost and the error lines disappear, the figure stays.
  EXPECT_LT(countPixels(crop(off, kReconView), isGhostBlue), ghost / 5 + 20);
  EXPECT_LE(countPixels(crop(off, kReconView), isMagenta), magenta);
  EXPECT_GT(countPixels(crop(off, kReconView), isAmber), 400);

  // Explore mode draws a synthesised walker in both views.
  EXPECT_GT(countPixels(crop(explore, kReconView), isAmber), 400);
  EXPECT_GT(countPixels(crop(explore, kInputView), isPointLight), 60);
}

TEST_F(GuiDefault, UnknownActionIsAnError) {
  const auto script = writeScript(dir, R"([{"set_angle": 10}, {"fly_away": true}])");
  const RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script.string()));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("unknown action \"fly_away\""), std::string::npos) << r.err;
}

TEST_F(GuiDefault, FailedActionIsAnError) {
  const auto script = writeScript(dir, R"([{"select_subject": "NOBODY"}])");
  const RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script.string()));
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("NOBODY"), std::string::npos) << r.err;
}

TEST_F(GuiDefault, OpeningAMissingFileIsAnErrorNotACrash) {
  const auto script = writeScript(dir, R"([{"open": "/nonexistent/walkers.csv"}, {"wait_frames": 1}])");
  const RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script.string()));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("nonexistent"), std::string::npos) << r.err;
}

TEST_F(GuiDefault, BenchFramesPrintsFrameTimesAsJson) {
  const auto script = writeScript(dir, R"([{"unknown_angle": true}])");
  const RunResult r =
      runViewer(dir, "--size 1280x720 --bench-frames 20 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto last = r.out.substr(r.out.rfind('{'));
  const auto json = nlohmann::json::parse(last);
  EXPECT_EQ(json.at("frames").get<int>(), 20);
  EXPECT_GT(json.at("median_ms").get<double>(), 0.0);
  EXPECT_GE(json.at("p95_ms").get<double>(), json.at("median_ms").get<double>());
  EXPECT_GE(json.at("max_ms").get<double>(), json.at("p95_ms").get<double>());
}

// Repainting only what changed (ui/render/compositor.h) must give the very pixels of a
// full redraw. --check-repaint paints every frame again, whole, over what was painted and
// compares the two; the script changes a bit (playback), a lot (α, theme, mode) and
// makes a window appear and vanish.
void expectRepaintsMatchAFullRedraw(const std::filesystem::path& dir, const std::string& env) {
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"}, {"play": true}, {"wait_frames": 20},
    {"play": false}, {"set_phase": 0.25}, {"set_angle": 60}, {"wait_frames": 2},
    {"show_panel": ["help", true]}, {"wait_frames": 2}, {"show_panel": ["help", false]}, {"wait_frames": 2},
    {"set_theme": "light"}, {"wait_frames": 2},
    {"set_mode": "explore"}, {"set_coefficient": [1, 2]}, {"play": true}, {"wait_frames": 10},
    {"overlay": ["ghost", false]}, {"wait_frames": 2}
  ])");
  const RunResult r =
      runViewer(dir, "--size 1366x768 --check-repaint --script " + quote(script.string()), env);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  std::smatch m;
  const std::regex summary(R"(repaint check: (\d+) frames, (\d+) of them repainted in part, (\d+) differ)");
  ASSERT_TRUE(std::regex_search(r.out, m, summary)) << r.out;
  EXPECT_GE(std::stoi(m[1].str()), 40);
  EXPECT_GE(std::stoi(m[2].str()), 20) << "hardly any partial repaints: nothing was checked";
  EXPECT_EQ(std::stoi(m[3].str()), 0) << r.err;
}

TEST_F(GuiDefault, RepaintingWhatChangedMatchesAFullRedraw) {
  expectRepaintsMatchAFullRedraw(dir, kNoSettings);
}

TEST_F(GuiDefault, RepaintingWhatChangedMatchesAFullRedrawWhenSwapping) {
  expectRepaintsMatchAFullRedraw(dir, std::string(kNoSettings) + " EIGENWALKER_PRESENT=swap");
}

TEST_F(GuiDefault, FullRedrawStillWorks) {
  const auto script = writeScript(dir, R"([{"select_subject": "SYN005"}, {"play": false}, {"set_phase": 0.25}])");
  const RunResult r = runViewer(dir, "--size 1600x900 --full-redraw --check-repaint --screenshot " +
                                         quote((dir / "full.png").string()) + " --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find(" 0 of them repainted in part, 0 differ"), std::string::npos) << r.out;
  const cv::Mat full = load("full.png");
  ASSERT_FALSE(full.empty());
  EXPECT_GT(countPixels(crop(full, kReconView), isAmber), 400);
  EXPECT_GT(countPixels(crop(full, kInputView), isPointLight), 60);
}

}  // namespace
}  // namespace ew::test::gui
