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

}  // namespace
}  // namespace ew::test::gui
