// Teaching features, end to end: the guided tour runs to its end through script actions,
// the light theme brightens the panels (the projector preset changes the layout), the
// point-light display shows dots only, and F1's help overlay draws.

#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

using GuiTeaching = GuiTest;

double brightness(const cv::Mat& bgr) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  return cv::mean(grey)[0];
}

// The subjects panel (top left), away from the 3D views, which stay dark in every theme.
constexpr Region kSubjectsPanel{0.005, 0.08, 0.17, 0.45};

TEST_F(GuiTeaching, TourRunsToTheEndAndThemesChangeTheLook) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"play": false},
    {"tour": "start"},
    {"screenshot": ")" + d + R"(/tour1.png"},
    {"tour": "next"}, {"tour": "next"}, {"tour": "back"}, {"tour": "next"}, {"tour": "next"}, {"tour": "next"},
    {"screenshot": ")" + d + R"(/tour5.png"},
    {"tour": "next"},
    {"play": false},
    {"screenshot": ")" + d + R"(/dark.png"},
    {"set_theme": "light"},
    {"screenshot": ")" + d + R"(/light.png"},
    {"set_theme": "projector"},
    {"screenshot": ")" + d + R"(/projector.png"},
    {"set_theme": "dark"},
    {"show_panel": ["help", true]},
    {"screenshot": ")" + d + R"(/help.png"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (int i = 1; i <= 5; ++i) EXPECT_NE(r.err.find("Tour " + std::to_string(i) + "/5"), std::string::npos) << i;
  EXPECT_NE(r.err.find("Tour ended"), std::string::npos) << r.err;

  const cv::Mat tour1 = load("tour1.png"), tour5 = load("tour5.png"), dark = load("dark.png");
  const cv::Mat light = load("light.png"), projector = load("projector.png"), help = load("help.png");
  ASSERT_FALSE(tour1.empty() || tour5.empty() || dark.empty() || light.empty() || projector.empty() || help.empty());

  // Step 1 is the explorer (a synthesised walker in 3D); the tour window sits at the bottom.
  EXPECT_GT(countPixels(crop(tour1, kReconView), isAmber), 400);
  const Region bottom{0.3, 0.8, 0.7, 0.98};
  EXPECT_GT(meanAbsDiff(crop(tour1, bottom), crop(dark, bottom)), 3.0) << "no tour window";

  // Themes: the light theme's panels are much brighter; the projector preset changes the layout.
  const double bDark = brightness(crop(dark, kSubjectsPanel)), bLight = brightness(crop(light, kSubjectsPanel));
  std::printf("panel brightness: dark %.1f, light %.1f\n", bDark, bLight);
  EXPECT_GT(bLight, bDark + 100.0);
  EXPECT_GT(meanAbsDiff(dark, projector), 5.0);

  // Help overlay in the middle of the window.
  const Region middle{0.35, 0.35, 0.65, 0.65};
  EXPECT_GT(meanAbsDiff(crop(help, middle), crop(dark, middle)), 5.0);
}

TEST_F(GuiTeaching, PointLightDisplayHidesTheSkeleton) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"play": false},
    {"set_phase": 0.25},
    {"screenshot": ")" + d + R"(/figure.png"},
    {"overlay": ["point_lights", true]},
    {"screenshot": ")" + d + R"(/dots.png"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const cv::Mat figure = load("figure.png"), dots = load("dots.png");
  ASSERT_FALSE(figure.empty() || dots.empty());
  const int amberBefore = countPixels(crop(figure, kReconView), isAmber);
  const int amberAfter = countPixels(crop(dots, kReconView), isAmber);
  const int lightsAfter = countPixels(crop(dots, kReconView), isPointLight);
  std::printf("3D view: amber %d -> %d, point-lights %d\n", amberBefore, amberAfter, lightsAfter);
  EXPECT_GT(amberBefore, 400);
  EXPECT_LT(amberAfter, amberBefore / 10);
  EXPECT_GT(lightsAfter, 40);
  EXPECT_LT(countPixels(crop(dots, kReconView), isGhostBlue), countPixels(crop(figure, kReconView), isGhostBlue));
}

TEST_F(GuiTeaching, BadThemeAndTourArgumentsAreErrors) {
  auto script = writeScript(dir, R"([{"set_theme": "neon"}])");
  RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script.string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("neon"), std::string::npos) << r.err;
  script = writeScript(dir, R"([{"tour": "next"}])");
  r = runViewer(dir, "--size 800x600 --script " + quote(script.string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("not started"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ew::test::gui
