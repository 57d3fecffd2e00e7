// The gait report window, end to end (issue 17): shown by a script on the default synthetic
// population, it measures the selected walker, its reconstruction and the population band;
// the report exports as CSV and JSON, the reconstruction as TRC (read back by the project's
// own TRC reader) and MOT; in explore mode a coefficient changes the measured walker.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/eigenwalker/default_model.h"
#include "core/io/c3d_reader.h"
#include "core/io/trc_reader.h"
#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

using GuiGait = GuiTest;

// measure → reconstruction column of a report CSV's first table.
std::map<std::string, double> reconstructionColumn(const std::string& csv) {
  std::map<std::string, double> out;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line) && !line.empty()) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    if (cells.size() >= 3 && !cells[2].empty()) out[cells[0]] = std::stod(cells[2]);
  }
  return out;
}

// The report's blue motion-capture curves (the ghost's blue, opaque).
bool isReportBlue(int r, int g, int b) { return b > 200 && r < 140 && g > 120 && g < 200; }

TEST_F(GuiGait, MeasuresTheWalkerAndItsReconstructionAndExportsThem) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"play": false},
    {"set_angle": 45},
    {"screenshot": ")" + d + R"(/without.png"},
    {"show_panel": ["gait", true]},
    {"screenshot": ")" + d + R"(/with.png"},
    {"export_gait_report": ")" + d + R"(/report.csv"},
    {"export_gait_report": ")" + d + R"(/report.json"},
    {"export_gait_report": ")" + d + R"(/walk.trc"},
    {"export_gait_report": ")" + d + R"(/walk.c3d"},
    {"export_state": ")" + d + R"(/state.json"},
    {"set_mode": "explore"},
    {"export_gait_report": ")" + d + R"(/explore_mean.csv"},
    {"set_coefficient": [1, 2.0]},
    {"export_gait_report": ")" + d + R"(/explore_e1.csv"},
    {"show_panel": ["gait", false]}
  ])");
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;

  // The window draws its curves: the motion capture's blue appears where the views were.
  const cv::Mat without = load("without.png"), with = load("with.png");
  const Region plots{0.2, 0.55, 0.8, 0.9};
  const int blueWith = countPixels(crop(with, plots), isReportBlue);
  const int blueWithout = countPixels(crop(without, plots), isReportBlue);
  std::printf("report-blue pixels: %d with the gait window, %d without\n", blueWith, blueWithout);
  EXPECT_GT(blueWith, 400);
  EXPECT_GT(blueWith, 2 * blueWithout + 200);

  const auto state = nlohmann::json::parse(readAll(dir / "state.json"));
  const auto& gait = state["gait"];
  EXPECT_EQ(gait["band_walkers"], 50);  // the whole default population measured
  const auto& cadence = gait["measures"]["cadence_spm"];
  // The reconstruction is fitted to the walker's own view: the same cadence to a step a minute.
  EXPECT_NEAR(cadence["reconstruction"].get<double>(), cadence["motion_capture"].get<double>(), 1.0);
  EXPECT_GT(cadence["population_sd"].get<double>(), 1.0);
  const auto& stride = gait["measures"]["stride_length_m"];
  EXPECT_NEAR(stride["reconstruction"].get<double>(), stride["motion_capture"].get<double>(),
              0.15 * stride["motion_capture"].get<double>());

  const std::string csv = readAll(dir / "report.csv");
  EXPECT_EQ(csv.rfind("measure,motion_capture,reconstruction,population_mean,population_sd\n", 0), 0u);
  EXPECT_NE(csv.find("\ncurve,cycle_pct,motion_capture_deg,reconstruction_deg,population_mean_deg,population_sd_deg\n"),
            std::string::npos);
  const auto json = nlohmann::json::parse(readAll(dir / "report.json"));
  EXPECT_EQ(json["engine"], "eigenwalker");
  EXPECT_EQ(json["curves"]["knee_angle_r"]["reconstruction_deg"].size(), 101u);

  // The reconstruction as OpenSim files: the TRC reads back as 15 joints walking forward.
  const RawTrial trc = readTrc(dir / "walk.trc");
  EXPECT_EQ(trc.kind, PointKind::CanonicalJoints);
  EXPECT_DOUBLE_EQ(trc.rateHz, 100.0);
  const int pelvisX = 3 * 2;  // pelvis, OpenSim X = forward
  const double travelled = trc.positionsMm(trc.frameCount() - 1, pelvisX) - trc.positionsMm(0, pelvisX);
  EXPECT_GT(travelled, 3000.0);  // four strides of about 1.4 m
  // And as C3D: the same 15 joints (float precision) and the walk's gait events.
  const RawTrial c3d = readC3d(dir / "walk.c3d");
  EXPECT_DOUBLE_EQ(c3d.rateHz, 100.0);
  EXPECT_EQ(c3d.frameCount(), trc.frameCount());
  EXPECT_GE(c3d.events.size(), 6u);  // four strides: a strike and a foot off per foot per stride
  const std::string mot = readAll(dir / "walk.mot");
  EXPECT_NE(mot.find("inDegrees=yes\n"), std::string::npos);
  EXPECT_NE(mot.find("endheader\ntime\t"), std::string::npos);

  // Explore mode: the synthesised walker is measured, and the first eigenwalker changes it.
  const auto mean = reconstructionColumn(readAll(dir / "explore_mean.csv"));
  const auto moved = reconstructionColumn(readAll(dir / "explore_e1.csv"));
  ASSERT_TRUE(mean.count("stride_length_m") && moved.count("stride_length_m"));
  std::printf("explore: stride length %.3f m at the mean, %.3f m at e1 = +2 SD\n", mean.at("stride_length_m"),
              moved.at("stride_length_m"));
  EXPECT_GT(std::abs(moved.at("stride_length_m") - mean.at("stride_length_m")) +
                std::abs(moved.at("knee_flexion_range_deg") - mean.at("knee_flexion_range_deg")) / 100.0,
            0.01);
}

// A motion-capture file opened with nothing else loaded is inspected against the default model
// of real walkers; its report's band is of that model's walkers, not of the synthetic walkers
// shown before it (whose hips read about 14° more flexed at heel strike than this subject's).
TEST_F(GuiGait, AFileInspectedAgainstTheDefaultModelIsBandedByItsRealWalkers) {
  EW_REQUIRE_SHARED_DATA();
  const auto c3d = sharedDataDir() / "schreiber-moissenet-2019" / "2014001" / "2014001_C4_05.c3d";
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"open": [")" + c3d.string() + R"("]},
    {"show_panel": ["gait", true]},
    {"export_gait_report": ")" + d + R"(/report.json"},
    {"export_state": ")" + d + R"(/state.json"}
  ])");
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto state = nlohmann::json::parse(readAll(dir / "state.json"));
  ASSERT_EQ(state["model"]["source"], "default");
  const auto& gait = state["gait"];
  EXPECT_EQ(gait["band_walkers"], 24);
  EXPECT_NE(gait["band"].get<std::string>().find("default model"), std::string::npos) << gait["band"];
  // The band's speed is the mean of the speeds the model records for its walkers.
  const EigenwalkerModel& model = defaultRealModel();
  double sum = 0.0;
  for (const auto& v : model.speedsMps) sum += v.value_or(NAN);
  EXPECT_NEAR(gait["measures"]["speed_mps"]["population_mean"].get<double>(), sum / 24.0, 1e-6);
  const auto report = nlohmann::json::parse(readAll(dir / "report.json"));
  EXPECT_EQ(report["band"], gait["band"]);
  // This subject's hip at heel strike lies within the real walkers' band (2 SD), as it did not
  // within the synthetic walkers'.
  const auto& hip = report["curves"]["hip_flexion_r"];
  const double own = hip["motion_capture_deg"][0], mean = hip["population_mean_deg"][0], sd = hip["population_sd_deg"][0];
  std::printf("hip flexion at heel strike: %.1f°, band %.1f ± %.1f°\n", own, mean, sd);
  EXPECT_LT(std::abs(own - mean), 2.0 * sd);
}

}  // namespace
}  // namespace ew::test::gui

namespace ew::test::gui {
namespace {

using GuiCompare = GuiTest;

// The engines' colours in compare mode (ui/render/palette.h kEngineRight): the snippet
// engine's bluish green (13, 156, 97) and the skeleton engine's magenta (252, 15, 184), lit
// (the renderer shades them, keeping their proportions). The green by its proportions, to
// part it from the camera's teal (82, 224, 194), whose blue is 87 % of its green.
bool isSnippetGreen(int r, int g, int b) { return g > 70 && 10 * r < 4 * g && 4 * b < 3 * g && 10 * b > 3 * g; }
bool isSkeletonMagenta(int r, int g, int b) { return r > 140 && b > 90 && r - g > 100 && b - g > 70 && b < r; }

TEST_F(GuiCompare, EveryEngineReconstructsTheWalkerDrawnTogetherWithItsErrors) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"play": false},
    {"set_angle": 45},
    {"set_phase": 0.25},
    {"compare_engines": true},
    {"screenshot": ")" + d + R"(/compare.png"},
    {"show_engine": ["skeleton", false]},
    {"show_engine": ["snippet", false]},
    {"screenshot": ")" + d + R"(/no_skeleton.png"},
    {"show_engine": ["skeleton", true]},
    {"show_engine": ["snippet", true]},
    {"show_panel": ["gait", true]},
    {"export_gait_report": ")" + d + R"(/compare.csv"},
    {"screenshot": ")" + d + R"(/compare_gait.png"},
    {"export_state": ")" + d + R"(/state.json"},
    {"compare_engines": false},
    {"export_gait_report": ")" + d + R"(/single.csv"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;

  const auto state = nlohmann::json::parse(readAll(dir / "state.json"));
  ASSERT_TRUE(state["compare"].is_array()) << state.dump();
  ASSERT_EQ(state["compare"].size(), 3u);
  std::map<std::string, double> mpjpe;
  for (const auto& e : state["compare"]) {
    ASSERT_TRUE(e.contains("mpjpe_mm")) << e.dump();
    mpjpe[e["engine"]] = e["mpjpe_mm"];
    EXPECT_DOUBLE_EQ(e["alpha_used_deg"].get<double>(), 45.0);
  }
  std::printf("compare at 45°: eigenwalker %.1f, snippet %.1f, skeleton %.1f mm\n", mpjpe["eigenwalker"],
              mpjpe["snippet"], mpjpe["skeleton"]);
  // Measured 17.6 / 12.3 / 43.1 mm: each well under the hundreds a wrong axis or branch gives.
  for (const auto& [engine, mm] : mpjpe) EXPECT_LT(mm, 80.0) << engine;

  // Drawn together: the snippet's green and the skeleton's magenta in the 3D view (measured 108
  // and 1128 pixels at phase 0.25: the snippet walker lies close over the others; the phase is
  // set, since a paused walker's phase is otherwise wherever loading left it); hiding them
  // removes them.
  const cv::Mat all = load("compare.png"), hidden = load("no_skeleton.png");
  const int green = countPixels(crop(all, kReconView), isSnippetGreen);
  const int magenta = countPixels(crop(all, kReconView), isSkeletonMagenta);
  const int greenHidden = countPixels(crop(hidden, kReconView), isSnippetGreen);
  const int magentaHidden = countPixels(crop(hidden, kReconView), isSkeletonMagenta);
  std::printf("3D view: %d green, %d magenta; %d green and %d magenta with both hidden\n", green, magenta, greenHidden,
              magentaHidden);
  EXPECT_GT(green, 90);
  EXPECT_GT(magenta, 300);
  EXPECT_LT(greenHidden, green / 5);
  EXPECT_LT(magentaHidden, magenta / 5);

  // The gait report has a column per engine, and one again when compare mode is off.
  const std::string compareCsv = readAll(dir / "compare.csv"), single = readAll(dir / "single.csv");
  EXPECT_EQ(compareCsv.rfind("measure,motion_capture,eigenwalker,snippet,skeleton,population_mean,population_sd\n", 0),
            0u);
  EXPECT_EQ(single.rfind("measure,motion_capture,reconstruction,population_mean,population_sd\n", 0), 0u);
  const auto& columns = state["gait"]["columns"];
  for (const char* e : {"eigenwalker", "snippet", "skeleton"})
    EXPECT_TRUE(columns.contains(e) && columns[e]["cadence_spm"].is_number()) << columns.dump();
}

// With the view unknown, the profile panel shows the eigenwalker's J(α) with every engine's
// α̂ over it: the snippet engine's (a dashed line and a dot per snippet, green) and the
// skeleton engine's (magenta), whichever engine is selected; the state has each engine's α̂.
TEST_F(GuiCompare, TheViewProfileShowsEveryEnginesEstimate) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"play": false},
    {"set_angle": 45},
    {"unknown_angle": true},
    {"compare_engines": true},
    {"screenshot": ")" + d + R"(/profile.png"},
    {"export_state": ")" + d + R"(/state.json"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto state = nlohmann::json::parse(readAll(dir / "state.json"));
  ASSERT_EQ(state["compare"].size(), 3u);
  for (const auto& e : state["compare"]) {
    // Measured 44.5 / 49.7 / 45.0°; a mirror or facing confusion is 90° or more away.
    EXPECT_NEAR(e["alpha_used_deg"].get<double>(), 45.0, 15.0) << e.dump();
  }
  // The profile panel: the bottom strip, between the joint-error panel and the log.
  const Region profile{0.46, 0.76, 0.82, 1.0};
  const cv::Mat shot = load("profile.png");
  const int green = countPixels(crop(shot, profile), isSnippetGreen);
  const int magenta = countPixels(crop(shot, profile), isSkeletonMagenta);
  std::printf("profile panel: %d green, %d magenta pixels\n", green, magenta);
  EXPECT_GT(green, 40);
  EXPECT_GT(magenta, 20);
}

}  // namespace
}  // namespace ew::test::gui
