// Teaching features, end to end: the guided tour runs to its end through script actions,
// the light theme brightens the panels (the projector preset changes the layout), the
// point-light display shows dots only, and F1's help overlay draws.

#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <numbers>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/walker_set.h"
#include "core/semantic/walker_attributes.h"
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
    {"tour": "next"}, {"tour": "next"},
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
  for (int i = 1; i <= 6; ++i) EXPECT_NE(r.err.find("Tour " + std::to_string(i) + "/6"), std::string::npos) << i;
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

// 1280×720 at UI scale 2 (issue 18: both views used to vanish): the side and bottom panels
// move into the drawer, one at a time, and the two views keep the rest — the walker is drawn
// in each. At 1600×900, scale 1, the full layout stays.
TEST_F(GuiTeaching, AtScaleTwoTheDrawerLeavesTheViewsTheirRoom) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"play": false},
    {"set_angle": 45},
    {"set_phase": 0.25},
    {"export_state": ")" + d + R"(/drawer.json"},
    {"drawer_tab": "coefficients"},
    {"screenshot": ")" + d + R"(/drawer.png"},
    {"export_state": ")" + d + R"(/coefficients.json"},
    {"tour": "start"}, {"tour": "next"}, {"tour": "next"}, {"tour": "next"}, {"wait_frames": 3},
    {"export_state": ")" + d + R"(/tour_analysis.json"}
  ])");
  const RunResult r = runViewer(dir, "--size 1280x720 --ui-scale 2 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(readAll(dir / "drawer.json"))["view"]["drawer"], "Controls");
  EXPECT_EQ(nlohmann::json::parse(readAll(dir / "coefficients.json"))["view"]["drawer"], "Coefficients");
  // The drawer takes the left third; the views the rest, side by side.
  const cv::Mat shot = load("drawer.png");
  const int walker2d = countPixels(crop(shot, Region{0.34, 0.3, 0.66, 0.9}), isAmber);
  // The 3D walker is small and lit pale, its joints in the error colours: its amber bones and
  // its magenta error lines.
  const int walker3d = countPixels(crop(shot, Region{0.67, 0.3, 1.0, 0.9}),
                                   [](int red, int green, int blue) { return isAmber(red, green, blue) || isMagenta(red, green, blue); });
  std::printf("walker pixels: 2D view %d (amber), 3D view %d (amber or magenta)\n", walker2d, walker3d);
  // Measured 2023 and 596; the old layout left both views 68 px high: none.
  EXPECT_GT(walker2d, 400);
  EXPECT_GT(walker3d, 75);

  // The tour's analysis step folds its text away here, so that the window it opens has room
  // above the card; at 1600×900 both fit.
  const auto folded = nlohmann::json::parse(readAll(dir / "tour_analysis.json"));
  EXPECT_EQ(folded["tour"]["step"], 3);
  EXPECT_TRUE(folded["tour"]["text_folded"].get<bool>());
  EXPECT_TRUE(folded["layout"]["overflow"].empty()) << folded["layout"]["overflow"];

  const auto full = writeScript(dir, R"([{"export_state": ")" + d + R"(/full.json"}, {"tour": "start"}, {"tour": "next"},
    {"tour": "next"}, {"tour": "next"}, {"wait_frames": 3}, {"export_state": ")" + d + R"(/full_tour.json"}])");
  const RunResult f = runViewer(dir, "--size 1600x900 --script " + quote(full.string()));
  ASSERT_EQ(f.exitCode, 0) << f.err;
  EXPECT_TRUE(nlohmann::json::parse(readAll(dir / "full.json"))["view"]["drawer"].is_null());
  EXPECT_FALSE(nlohmann::json::parse(readAll(dir / "full_tour.json"))["tour"]["text_folded"].get<bool>());
  const auto bad = writeScript(dir, R"([{"drawer_tab": "nonsense"}])");
  const RunResult b = runViewer(dir, "--size 800x600 --script " + quote(bad.string()));
  EXPECT_EQ(b.exitCode, 1);
  EXPECT_NE(b.err.find("coefficients"), std::string::npos) << b.err;
}

// Semantic axes (issue 18): the speed slider moves the explorer's walker to the speed it
// names and quickens its stride; an unknown axis is an error naming it; in reconstruct mode the
// attributes predicted from the 2D view stand beside the walker's own.
TEST_F(GuiTeaching, SemanticAxesMoveTheWalkerAndReadAttributesFromTheView) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"set_theme": "dark"},
    {"select_subject": "SYN005"},
    {"set_angle": 60},
    {"export_state": ")" + d + R"(/recon.json"},
    {"set_mode": "explore"},
    {"export_state": ")" + d + R"(/mean.json"},
    {"set_semantic": {"attribute": "speed_mps", "value": 1.75}},
    {"export_state": ")" + d + R"(/fast.json"},
    {"undo": null},
    {"export_state": ")" + d + R"(/undone.json"},
    {"redo": null},
    {"expect_failure": {"set_semantic": {"attribute": "wingspan", "value": 2}}},
    {"play": false},
    {"screenshot": ")" + d + R"(/explore.png"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("no semantic axis 'wingspan'"), std::string::npos) << r.err;
  const auto axis = [](const nlohmann::json& state, const std::string& name) {
    for (const auto& a : state["semantic"]["axes"])
      if (a["attribute"] == name) return a;
    return nlohmann::json();
  };
  const auto mean = nlohmann::json::parse(readAll(dir / "mean.json"));
  const auto fast = nlohmann::json::parse(readAll(dir / "fast.json"));
  ASSERT_FALSE(axis(fast, "speed_mps").is_null()) << fast["semantic"].dump();
  // The slider moved the walker by 1.75 m/s − its reading along the axis; the predictor reads
  // that move as gain × the move (semantic_axes.h).
  const double r0 = axis(mean, "speed_mps")["reading"].get<double>();
  EXPECT_NEAR(axis(fast, "speed_mps")["reading"].get<double>(), r0 + axis(fast, "speed_mps")["gain"].get<double>() * (1.75 - r0), 1e-6);
  EXPECT_GT(axis(fast, "speed_mps")["loo_r2"].get<double>(), 0.7);
  EXPECT_GT(fast["semantic"]["explore_stride_hz"].get<double>(), mean["semantic"]["explore_stride_hz"].get<double>());
  EXPECT_GT(axis(fast, "measured_speed_mps")["reading"].get<double>(), axis(mean, "measured_speed_mps")["reading"].get<double>() + 0.1);
  // Undo takes the move back, coefficients and stride frequency both.
  const auto undone = nlohmann::json::parse(readAll(dir / "undone.json"));
  EXPECT_DOUBLE_EQ(axis(undone, "speed_mps")["reading"].get<double>(), r0);
  EXPECT_DOUBLE_EQ(undone["semantic"]["explore_stride_hz"].get<double>(), mean["semantic"]["explore_stride_hz"].get<double>());

  const auto recon = nlohmann::json::parse(readAll(dir / "recon.json"));
  bool height = false;
  for (const auto& f : recon["semantic"]["from_view"]) {
    if (f["attribute"] != "height_m") continue;
    height = true;
    // The synthetic population's height axis: LOO RMSE about 0.03 m (docs/RESULTS.md).
    EXPECT_NEAR(f["from_2d"].get<double>(), f["truth"].get<double>(), 0.1) << f.dump();
  }
  EXPECT_TRUE(height) << recon["semantic"].dump();
}

// With the default model of real walkers held over the synthetic population, the axes are
// the model's walkers' (what can be measured on them), not the population's generating
// attributes read in a model they were not drawn from (the mean real walker read "1.18" on a
// 0/1 female axis and "0.86 m/s" where it measures 1.2). At the mean walker each reading is
// the walkers' mean: the ridge's intercept is unpenalised and the walkers' features are
// centred on the mean walker (semantic_axes.h).
TEST_F(GuiTeaching, SemanticAxesOfTheDefaultModelAreLearntFromItsWalkers) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"set_model": "default"},
    {"set_mode": "explore"},
    {"export_state": ")" + d + R"(/mean.json"}
  ])");
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto semantic = nlohmann::json::parse(readAll(dir / "mean.json"))["semantic"];
  EXPECT_EQ(semantic["axes_from"], "the default model's 24 walkers");
  std::map<std::string, double> readings;
  for (const auto& a : semantic["axes"]) readings[a["attribute"].get<std::string>()] = a["reading"].get<double>();
  for (const char* manifest : {"female", "speed_mps", "height_m"}) EXPECT_EQ(readings.count(manifest), 0u) << manifest;
  std::map<std::string, double> sum;
  const EigenwalkerModel& model = defaultRealModel();
  for (const Walker& w : storedWalkers(model, "default"))
    for (const auto& [name, value] : measureWalkerAttributes(w.fit.w, w.fit.omegaRadS / (2.0 * std::numbers::pi), w.id))
      sum[name] += value;
  for (const char* name : {"measured_speed_mps", "measured_height_m", "measured_cadence_spm"}) {
    ASSERT_EQ(readings.count(name), 1u) << name << ": " << semantic.dump();
    EXPECT_NEAR(readings[name], sum[name] / model.walkerCount(), 1e-6 * std::abs(sum[name])) << name;
  }
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
