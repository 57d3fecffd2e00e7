// The keyboard, end to end (issue 18): script action "key" presses a key as the frame loop
// answers it (ui/app/shortcuts.h), and the F1 overlay lists every key.

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

using GuiKeys = GuiTest;

nlohmann::json readJson(const std::filesystem::path& file) { return nlohmann::json::parse(readAll(file)); }

TEST_F(GuiKeys, KeysChangeTheAngleMethodWalkerAndPresentation) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"set_angle": 30},
    {"set_method": "map"},
    {"export_state": ")" + d + R"(/before.json"},
    {"key": "]"}, {"key": "]"}, {"key": "]"},
    {"export_state": ")" + d + R"(/fine.json"},
    {"key": "shift+]"},
    {"export_state": ")" + d + R"(/coarse.json"},
    {"key": "shift+["}, {"key": "shift+["}, {"key": "shift+["}, {"key": "shift+["},
    {"key": "m"}, {"key": "u"}, {"key": "n"}, {"key": "page_down"}, {"key": "b"},
    {"key": "f5"},
    {"wait_frames": 1},
    {"export_state": ")" + d + R"(/after.json"},
    {"key": "escape"},
    {"wait_frames": 1},
    {"export_state": ")" + d + R"(/left.json"},
    {"key": "f1"},
    {"play": false},
    {"screenshot": ")" + d + R"(/help.png"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto before = readJson(dir / "before.json"), fine = readJson(dir / "fine.json");
  const auto coarse = readJson(dir / "coarse.json"), after = readJson(dir / "after.json");
  EXPECT_DOUBLE_EQ(fine["angle_deg"].get<double>(), 33.0);    // three presses of ] (+1° each)
  EXPECT_DOUBLE_EQ(coarse["angle_deg"].get<double>(), 48.0);  // Shift+] (+15°)
  EXPECT_DOUBLE_EQ(after["angle_deg"].get<double>(), -12.0);  // four Shift+[
  EXPECT_EQ(before["method"], "map");
  EXPECT_EQ(after["method"], "lsq");
  EXPECT_FALSE(before["unknown_angle"].get<bool>());
  EXPECT_TRUE(after["unknown_angle"].get<bool>());
  // N and Page Down forward, B back: one walker on from SYN005.
  EXPECT_EQ(before["walker"]["subject"], "SYN005");
  EXPECT_EQ(after["walker"]["subject"], "SYN006");
  EXPECT_TRUE(after["view"]["presentation"].get<bool>());
  EXPECT_FALSE(readJson(dir / "left.json")["view"]["presentation"].get<bool>());
  EXPECT_FALSE(load("help.png").empty());
}

// Ctrl+Z takes back a change of α and of the estimator, one step each; Ctrl+Shift+Z and
// Ctrl+Y bring them back; the header's buttons (script "undo") do the same.
TEST_F(GuiKeys, UndoRestoresTheAngleAndMethodAndRedoReappliesThem) {
  const auto d = dir.string();
  const auto state = [&d](const char* name) { return R"({"export_state": ")" + d + "/" + name + R"(.json"})"; };
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"}, {"set_angle": 30}, {"set_method": "map"},
    {"set_angle": 40}, {"set_method": "lsq"}, {"key": "]"},
    )" + state("changed") + R"(,
    {"key": "ctrl+z"}, )" + state("undo1") + R"(,
    {"key": "ctrl+z"}, )" + state("undo2") + R"(,
    {"undo": null}, )" + state("undo3") + R"(,
    {"key": "ctrl+shift+z"}, )" + state("redo1") + R"(,
    {"key": "ctrl+y"}, {"redo": null}, )" + state("redo3") + R"(,
    {"set_angle": 50}, {"undo": null}, )" + state("branch") + R"(,
    {"wait_frames": 2}, {"play": false}, )" + state("settled") + R"(
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto at = [this](const char* name) { return readJson(dir / (std::string(name) + ".json")); };
  const auto alpha = [&at](const char* name) { return at(name)["angle_deg"].get<double>(); };
  const auto method = [&at](const char* name) { return at(name)["method"].get<std::string>(); };
  EXPECT_DOUBLE_EQ(alpha("changed"), 41.0);
  EXPECT_EQ(method("changed"), "lsq");
  EXPECT_DOUBLE_EQ(alpha("undo1"), 40.0);  // the ] press
  EXPECT_EQ(method("undo1"), "lsq");
  EXPECT_DOUBLE_EQ(alpha("undo2"), 40.0);  // the method
  EXPECT_EQ(method("undo2"), "map");
  EXPECT_DOUBLE_EQ(alpha("undo3"), 30.0);  // the angle
  EXPECT_EQ(method("undo3"), "map");
  EXPECT_DOUBLE_EQ(alpha("redo1"), 40.0);
  EXPECT_EQ(method("redo1"), "map");
  EXPECT_DOUBLE_EQ(alpha("redo3"), 41.0);
  EXPECT_EQ(method("redo3"), "lsq");
  EXPECT_EQ(at("redo3")["undo"]["redo_steps"], 0);
  // A change after an undo: the undo takes it back, and nothing older is redone.
  EXPECT_DOUBLE_EQ(alpha("branch"), 41.0);
  EXPECT_EQ(at("branch")["undo"]["redo_steps"], 1);
  // Frames that change nothing add no steps.
  EXPECT_EQ(at("settled")["undo"]["steps"], at("branch")["undo"]["steps"]);
}

TEST_F(GuiKeys, AKeyNobodyBoundIsAScriptError) {
  const auto script = writeScript(dir, R"([{"key": "ctrl+q"}])");
  const RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script.string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("ctrl+q"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ew::test::gui
