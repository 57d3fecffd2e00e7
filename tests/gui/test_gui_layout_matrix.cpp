// Issue 18's layout matrix, in the real viewer: at the teaching sizes where the layout is
// tightest (a small window, a large UI scale, the projector theme) no window or table column
// has content cut at its edge, and no caption, legend or colour bar covers the walker of its
// view, and no window reaches past the screen's edge — in both modes, with every drawer tab
// shown in turn, with the three engines' gait report, the analysis, data, model and export
// windows open, with the quiz window, on the guided tour's second card, and in presentation
// mode (with the classroom displays on too). The viewer reports what it laid out (export_state's
// layout.overflow and layout.overlays); the whole matrix's screenshots are
// docs/screenshots/layout_matrix_*.png (docs/tools/layout_contact_sheet.sh).

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/gui/gui_run.h"
#include "tests/gui/layout_checks.h"

namespace ew::test::gui {
namespace {

using GuiLayoutMatrix = GuiTest;

TEST_F(GuiLayoutMatrix, NothingIsCutAndNothingCoversTheWalker) {
  // (The tests' X screen is 1920×1080: the 3840×2160 cells are in the contact sheets.)
  const std::vector<std::string>& tabs = drawerTabs();
  for (const LayoutCell& c : teachingCells()) {
    const std::string cell = std::string(c.size) + " scale " + c.scale + " " + c.theme;
    std::string script = R"([{"set_theme": ")" + std::string(c.theme) +
                         R"("}, {"select_subject": "SYN005"}, {"set_angle": 45}, {"play": false}, {"set_phase": 0.3})";
    std::vector<std::string> states;
    for (const char* mode : {"reconstruct", "explore"}) {
      script += std::string(R"(, {"set_mode": ")") + mode + R"("})";
      for (const auto& tab : tabs) {
        states.push_back(std::string(mode) + "_" + tab);
        script += R"(, {"drawer_tab": ")" + tab + R"("}, {"wait_frames": 2}, {"export_state": ")" +
                  (dir / (states.back() + ".json")).string() + R"("})";
      }
    }
    // The gait report of the three engines: the widest table the viewer draws.
    states.push_back("gait_report");
    script += R"(, {"set_mode": "reconstruct"}, {"compare_engines": true}, {"show_panel": ["gait", true]},
                 {"wait_frames": 3}, {"export_state": ")" +
              (dir / "gait_report.json").string() + R"("}, {"show_panel": ["gait", false]}, {"compare_engines": false})";
    states.push_back("analysis");
    script += R"(, {"show_panel": ["analysis", true]}, {"wait_frames": 3}, {"export_state": ")" +
              (dir / "analysis.json").string() + R"("}, {"show_panel": ["analysis", false]})";
    for (const char* panel : {"data", "model", "export"}) {
      states.push_back(std::string("panel_") + panel);
      script += std::string(R"(, {"show_panel": [")") + panel + R"(", true]}, {"wait_frames": 3}, {"export_state": ")" +
                (dir / (states.back() + ".json")).string() + R"("}, {"show_panel": [")" + panel + R"(", false]})";
    }
    // The quiz window with a few answers plotted, over explore mode's views.
    states.push_back("quiz");
    script += R"(, {"set_mode": "explore"}, {"quiz_start": {}}, {"quiz_answer": "left"}, {"quiz_answer": "right"},
                 {"quiz_answer": "left"}, {"wait_frames": 3}, {"export_state": ")" +
              (dir / "quiz.json").string() + R"("}, {"quiz_stop": true}, {"show_panel": ["quiz", false]},
                 {"set_mode": "reconstruct"})";
    // The tour's second card: its longest title and a step that points into the drawer.
    states.push_back("tour");
    script += R"(, {"tour": "start"}, {"tour": "next"}, {"wait_frames": 3}, {"export_state": ")" +
              (dir / "tour.json").string() + R"("}, {"tour": "end"})";
    states.push_back("presentation");
    script += R"(, {"set_mode": "reconstruct"}, {"presentation": true}, {"wait_frames": 2}, {"export_state": ")" +
              (dir / "presentation.json").string() + R"("})";
    // The classroom displays' longest captions and legends, in presentation mode.
    states.push_back("presentation_displays");
    script += R"(, {"mask_dots": 100}, {"depth_reversed": true}, {"inverted": true}, {"stage_elevation": 10},
                 {"wait_frames": 2}, {"export_state": ")" +
              (dir / "presentation_displays.json").string() + R"("}])";
    const RunResult r = runViewer(dir, std::string("--size ") + c.size + " --ui-scale " + c.scale + " --script " +
                                           quote(writeScript(dir, script).string()));
    ASSERT_EQ(r.exitCode, 0) << cell << "\n" << r.err;
    for (const auto& s : states) {
      const nlohmann::json state = nlohmann::json::parse(readAll(dir / (s + ".json")));
      // A quiz hides the 3D view's walker (the room answers from the 2D view).
      if (s == "quiz")
        expectLayoutHolds(state, cell + ", " + s, {"input"});
      else
        expectLayoutHolds(state, cell + ", " + s);
    }
  }
}

// A UI scale the window cannot hold is limited (to keep 560×384 of the UI's pixels), and the
// state says so; at a size that holds it, it is not.
TEST_F(GuiLayoutMatrix, AScaleTooLargeForTheWindowIsLimited) {
  const auto script = writeScript(dir, R"([{"export_state": ")" + (dir / "small.json").string() + R"("}])");
  const RunResult r = runViewer(dir, "--size 1024x768 --ui-scale 2 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto small = nlohmann::json::parse(readAll(dir / "small.json"));
  EXPECT_EQ(small["view"]["ui_scale"], 2.0);
  EXPECT_EQ(small["view"]["ui_scale_limit"], 1.75);  // ⌊1024 / 560 × 8⌋ / 8
  const auto script2 = writeScript(dir, R"([{"export_state": ")" + (dir / "large.json").string() + R"("}])");
  const RunResult r2 = runViewer(dir, "--size 1920x1080 --ui-scale 2 --script " + quote(script2.string()));
  ASSERT_EQ(r2.exitCode, 0) << r2.err;
  EXPECT_TRUE(nlohmann::json::parse(readAll(dir / "large.json"))["view"]["ui_scale_limit"].is_null());
}

// A window too narrow for every header button puts the rest under More…; its menu opens (the
// symbols spelt out) and the layout holds with it open. A window wide enough has no such menu.
TEST_F(GuiLayoutMatrix, TheHeadersMoreMenuOpensWhereButtonsDoNotFit) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([{"header_more": true}, {"wait_frames": 2},
    {"export_state": ")" + d + R"(/more.json"}, {"screenshot": ")" + d + R"(/more.png"}])");
  const RunResult r = runViewer(dir, "--size 1024x768 --ui-scale 2 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto state = nlohmann::json::parse(readAll(dir / "more.json"));
  const auto& drawn = state["layout"]["drawn"];
  EXPECT_NE(std::find(drawn.begin(), drawn.end(), "header_more"), drawn.end()) << drawn;
  expectLayoutHolds(state, "1024x768 scale 2, More… open");

  const auto wide = writeScript(dir, R"([{"expect_failure": {"header_more": true}},
    {"export_state": ")" + d + R"(/wide.json"}])");
  const RunResult r2 = runViewer(dir, "--size 1920x1080 --script " + quote(wide.string()));
  ASSERT_EQ(r2.exitCode, 0) << r2.err;
  EXPECT_NE(r2.err.find("no More… menu"), std::string::npos) << r2.err;
}

}  // namespace
}  // namespace ew::test::gui
