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

TEST_F(GuiKeys, AKeyNobodyBoundIsAScriptError) {
  const auto script = writeScript(dir, R"([{"key": "ctrl+q"}])");
  const RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script.string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("ctrl+q"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ew::test::gui
