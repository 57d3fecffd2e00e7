// The engine selector of reconstruct mode (issue 15): the same walker reconstructed by the
// eigenwalker and by the snippet engine, the state saying which, the snippet engine's
// per-snippet angles shown, and coefficient edits left to the eigenwalker; the skeleton
// engine (issue 16) likewise, with its view read from its poses.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

using GuiEngines = GuiTest;

nlohmann::json readState(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

TEST_F(GuiEngines, SnippetEngineReconstructsTheHeldOutWalkerAndSaysSo) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"}, {"set_angle": 60}, {"play": false}, {"set_phase": 0.25},
    {"export_state": ")" + d + R"(/eigenwalker.json"},
    {"set_engine": "snippet"},
    {"screenshot": ")" + d + R"(/snippet.png"},
    {"export_state": ")" + d + R"(/snippet.json"},
    {"set_coefficient": [1, 2.5]},
    {"export_state": ")" + d + R"(/snippet_edit.json"},
    {"unknown_angle": true},
    {"screenshot": ")" + d + R"(/snippet_unknown.png"},
    {"export_state": ")" + d + R"(/snippet_unknown.json"},
    {"unknown_angle": false}, {"set_engine": "eigenwalker"},
    {"export_state": ")" + d + R"(/back.json"},
    {"expect_failure": {"set_engine": "zou"}}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto eigen = readState(dir / "eigenwalker.json"), snip = readState(dir / "snippet.json");
  EXPECT_EQ(eigen["engine"], "eigenwalker");
  EXPECT_EQ(eigen["reconstruction"]["engine"], "eigenwalker");
  EXPECT_EQ(snip["engine"], "snippet");
  const auto& rec = snip["reconstruction"];
  ASSERT_TRUE(rec.is_object()) << snip["reconstruction_error"];
  EXPECT_EQ(rec["engine"], "snippet");
  EXPECT_EQ(rec["held_out"], "SYN005");
  EXPECT_EQ(rec["prior_walkers"], 49);  // the population's other subjects
  EXPECT_GE(rec["snippets"].get<int>(), 10);
  // Measured 12.8 mm (one-cycle summary vs the walker's own, known 60°); 40 mm is three
  // times that, where a wrong axis or phase lands far above.
  EXPECT_LT(rec["mpjpe_mm"].get<double>(), 40.0);
  EXPECT_NE(rec["mpjpe_mm"], eigen["reconstruction"]["mpjpe_mm"]);
  // The snippet engine's coefficients describe its result: an edit does not change it.
  EXPECT_EQ(readState(dir / "snippet_edit.json")["reconstruction"]["mpjpe_mm"], rec["mpjpe_mm"]);
  const auto unknown = readState(dir / "snippet_unknown.json")["reconstruction"];
  EXPECT_NEAR(unknown["alpha_used_deg"].get<double>(), 60.0, 10.0);
  EXPECT_EQ(unknown["snippet_angles_deg"].size(), unknown["snippets"].get<size_t>());
  EXPECT_EQ(readState(dir / "back.json")["reconstruction"]["mpjpe_mm"], eigen["reconstruction"]["mpjpe_mm"]);
  // The 3D view draws the snippet engine's walker (amber bones).
  const cv::Mat shot = load("snippet.png");
  EXPECT_GT(countPixels(crop(shot, kReconView), isAmber), 200);
  const cv::Mat shotUnknown = load("snippet_unknown.png");
  EXPECT_GT(countPixels(crop(shotUnknown, kReconView), isAmber), 200);
}

// A motion-capture file opened with nothing else is reconstructed against the default model of
// real walkers; the snippet engine learns its prior from the same walkers (the model's, without
// this subject), not from the synthetic walkers shown before: the engines compared on the same
// reference. Measured on subject 2014001 at 30°: MPJPE 14.4 mm with the real walkers' prior,
// 27.9 mm with the synthetic one.
TEST_F(GuiEngines, TheSnippetPriorIsLearntFromTheWalkersTheModelHolds) {
  EW_REQUIRE_SHARED_DATA();
  const auto c3d = sharedDataDir() / "schreiber-moissenet-2019" / "2014001" / "2014001_C4_05.c3d";
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"open": [")" + c3d.string() + R"("]},
    {"set_engine": "snippet"},
    {"export_state": ")" + d + R"(/real.json"}
  ])");
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto state = readState(dir / "real.json");
  ASSERT_EQ(state["model"]["source"], "default");
  const auto& rec = state["reconstruction"];
  ASSERT_TRUE(rec.is_object()) << state["reconstruction_error"];
  EXPECT_EQ(rec["engine"], "snippet");
  EXPECT_EQ(rec["prior_walkers"], 23);  // the default model's 24 walkers but SM2014001
  EXPECT_LT(rec["mpjpe_mm"].get<double>(), 20.0);
}

TEST_F(GuiEngines, SkeletonEngineReconstructsTheHeldOutWalkerFromGeometryAlone) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"}, {"set_angle": 60}, {"play": false}, {"set_phase": 0.25},
    {"export_state": ")" + d + R"(/eigenwalker.json"},
    {"set_engine": "skeleton"},
    {"screenshot": ")" + d + R"(/skeleton.png"},
    {"export_state": ")" + d + R"(/skeleton.json"},
    {"set_coefficient": [1, 2.5]},
    {"export_state": ")" + d + R"(/skeleton_edit.json"},
    {"unknown_angle": true},
    {"export_state": ")" + d + R"(/skeleton_unknown.json"}
  ])");
  const RunResult r = runViewer(dir, "--size 1280x800 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto eigen = readState(dir / "eigenwalker.json"), skel = readState(dir / "skeleton.json");
  EXPECT_EQ(skel["engine"], "skeleton");
  const auto& rec = skel["reconstruction"];
  ASSERT_TRUE(rec.is_object()) << skel["reconstruction_error"];
  EXPECT_EQ(rec["engine"], "skeleton");
  EXPECT_EQ(rec["skeleton_frames"], 64);  // two cycles of SYN005's 0.94 Hz stride at 30 Hz
  // Measured: 39.0 mm (one-cycle summary against the walker's own at the known 60°); the
  // evaluate experiment's mean over the real subjects at 60° is 47 mm (docs/RESULTS.md).
  // 100 mm is over twice both, where a mirrored walker or a wrong view lands far above.
  EXPECT_LT(rec["mpjpe_mm"].get<double>(), 100.0);
  EXPECT_NE(rec["mpjpe_mm"], eigen["reconstruction"]["mpjpe_mm"]);
  EXPECT_EQ(readState(dir / "skeleton_edit.json")["reconstruction"]["mpjpe_mm"], rec["mpjpe_mm"]);
  EXPECT_NEAR(readState(dir / "skeleton_unknown.json")["reconstruction"]["alpha_used_deg"].get<double>(), 60.0, 10.0);
  const cv::Mat shot = load("skeleton.png");
  // 1280×800 lays the panels out in the drawer: the 3D view from the state's layout.
  EXPECT_GT(countPixels(crop(shot, viewRegion(skel, "reconstruction", 1280, 800)), isAmber), 200);
}

}  // namespace
}  // namespace ew::test::gui
