// Presentation mode, end to end (issue 18): only the two views and the bar under them, the
// guided tour still running in it, and the way back to the workspace; its screenshots at the
// sizes and themes teaching happens at.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

using GuiPresentation = GuiTest;

nlohmann::json readJson(const std::filesystem::path& file) { return nlohmann::json::parse(readAll(file)); }

std::vector<std::string> drawnPanels(const nlohmann::json& state) {
  return state["layout"]["drawn"].get<std::vector<std::string>>();
}

// [x, y, width, height] of a laid-out rectangle.
struct Rect {
  double x, y, w, h;
};
Rect rectOf(const nlohmann::json& state, const char* name) {
  const auto& r = state["layout"][name];
  return {r[0].get<double>(), r[1].get<double>(), r[2].get<double>(), r[3].get<double>()};
}

TEST_F(GuiPresentation, ShowsOnlyTheTwoViewsAndTheTourStillRuns) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"play": false},
    {"set_phase": 0.25},
    {"export_state": ")" + d + R"(/workspace.json"},
    {"presentation": true},
    {"wait_frames": 1},
    {"export_state": ")" + d + R"(/present.json"},
    {"screenshot": ")" + d + R"(/present.png"},
    {"tour": "start"},
    {"tour": "next"},
    {"play": false},
    {"wait_frames": 1},
    {"export_state": ")" + d + R"(/tour.json"},
    {"screenshot": ")" + d + R"(/tour.png"},
    {"tour": "end"},
    {"presentation": false},
    {"wait_frames": 1},
    {"export_state": ")" + d + R"(/back.json"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;

  const auto workspace = readJson(dir / "workspace.json"), present = readJson(dir / "present.json");
  const auto tour = readJson(dir / "tour.json"), back = readJson(dir / "back.json");
  EXPECT_FALSE(workspace["view"]["presentation"].get<bool>());
  EXPECT_TRUE(present["view"]["presentation"].get<bool>());
  EXPECT_TRUE(present["layout"]["presentation"].get<bool>());
  // Nothing but the views and the bar: no header, drawer, panels or metrics strip.
  EXPECT_EQ(drawnPanels(present), (std::vector<std::string>{"input", "reconstruction", "presentation_bar"}));
  const auto before = drawnPanels(workspace);
  for (const char* panel : {"header", "subjects", "controls", "metrics", "playback", "coefficients"})
    EXPECT_NE(std::find(before.begin(), before.end(), panel), before.end()) << panel;
  // The views side by side over the whole width, far larger than in the workspace.
  const Rect input = rectOf(present, "input"), recon = rectOf(present, "reconstruction");
  const Rect bar = rectOf(present, "presentation_bar");
  EXPECT_DOUBLE_EQ(input.x, 0.0);
  EXPECT_NEAR(input.w + recon.w, 1600.0, 0.5);
  EXPECT_NEAR(recon.x, input.x + input.w, 0.5);
  EXPECT_NEAR(bar.y, input.y + input.h, 0.5);
  EXPECT_GT(input.w, 1.5 * rectOf(workspace, "input").w);

  // The tour advances in presentation mode, which it leaves on; its card sits above the bar.
  EXPECT_NE(r.err.find("Tour 2/6"), std::string::npos) << r.err;
  EXPECT_TRUE(tour["view"]["presentation"].get<bool>());
  EXPECT_EQ(drawnPanels(tour), drawnPanels(present));
  const cv::Mat shot = load("present.png"), touring = load("tour.png");
  ASSERT_FALSE(shot.empty() || touring.empty());
  const double barTop = bar.y / 900.0;
  const Region aboveBar{0.3, barTop - 0.12, 0.7, barTop - 0.01};
  EXPECT_GT(meanAbsDiff(crop(touring, aboveBar), crop(shot, aboveBar)), 3.0) << "no tour card above the bar";

  // The walker in both views: point-lights on the left, the amber reconstruction on the right.
  const int lights = countPixels(crop(shot, Region{0.05, 0.1, 0.45, 0.85}), isPointLight);
  const int amber = countPixels(crop(shot, Region{0.55, 0.1, 0.95, 0.85}), isAmber);
  std::printf("presentation: point-lights %d, amber %d\n", lights, amber);
  EXPECT_GT(lights, 100);
  EXPECT_GT(amber, 400);

  // Back to the workspace, every panel as before.
  EXPECT_FALSE(back["view"]["presentation"].get<bool>());
  EXPECT_EQ(drawnPanels(back), before);
}

// The screenshots to look at (EIGENWALKER_KEEP_GUI_OUTPUT=1 keeps them): presentation mode at
// 1024×768, 1280×720 at UI scale 2 and 1920×1080, each in the dark, light and projector themes.
// Each must show the walker in both views.
TEST_F(GuiPresentation, HoldsAtTeachingSizesInEveryTheme) {
  struct Size {
    const char* name;
    const char* args;
  };
  for (const Size& size : {Size{"1024x768", "--size 1024x768"}, Size{"1280x720_scale2", "--size 1280x720 --ui-scale 2"},
                           Size{"1920x1080", "--size 1920x1080"}}) {
    const auto d = dir.string() + "/" + size.name;
    std::filesystem::create_directories(d);
    std::string actions = R"([{"select_subject": "SYN005"}, {"play": false}, {"set_phase": 0.25}, {"set_angle": 30},
                             {"presentation": true})";
    for (const char* theme : {"dark", "light", "projector"})
      actions += std::string(R"(, {"set_theme": ")") + theme + R"("}, {"screenshot": ")" + d + "/" + theme + R"(.png"})";
    const auto script = writeScript(d, actions + "]");
    const RunResult r = runViewer(d, std::string(size.args) + " --script " + quote(script.string()));
    ASSERT_EQ(r.exitCode, 0) << size.name << ": " << r.err;
    for (const char* theme : {"dark", "light", "projector"}) {
      const cv::Mat shot = load(std::string(size.name) + "/" + theme + ".png");
      ASSERT_FALSE(shot.empty());
      const int lights = countPixels(crop(shot, Region{0.02, 0.1, 0.48, 0.85}), isPointLight);
      const int amber = countPixels(crop(shot, Region{0.52, 0.1, 0.98, 0.85}), isAmber);
      std::printf("%s %s: point-lights %d, amber %d\n", size.name, theme, lights, amber);
      EXPECT_GT(lights, 40) << size.name << " " << theme;
      EXPECT_GT(amber, 150) << size.name << " " << theme;
    }
  }
}

}  // namespace
}  // namespace ew::test::gui
