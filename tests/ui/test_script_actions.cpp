// The script actions' table (ui/app/script_actions.h): one row per name, every name parses,
// the actions only a ScriptRunner can wait for are refused by applyAction (the tour's way),
// and the others apply through it as through the runner.

#include <gtest/gtest.h>

#include <set>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "ui/app/app_state.h"
#include "ui/app/script.h"
#include "ui/app/script_actions.h"

namespace ew::ui {
namespace {

TEST(ScriptActions, EachNameOnceAndEachParses) {
  std::set<std::string> names;
  nlohmann::json script = nlohmann::json::array();
  for (const auto& kind : scriptActions()) {
    EXPECT_TRUE(names.insert(std::string(kind.name)).second) << kind.name;
    EXPECT_NE(kind.apply, nullptr) << kind.name;
    EXPECT_EQ(scriptAction(kind.name), &kind);
    if (kind.name != "expect_failure") script.push_back({{std::string(kind.name), nullptr}});
  }
  EXPECT_EQ(parseScript(script, "all").size(), names.size() - 1);
  EXPECT_EQ(scriptAction("no_such_action"), nullptr);
  EXPECT_THROW(parseScript(nlohmann::json::parse(R"([{"no_such_action": 1}])"), "bad"), std::runtime_error);
  EXPECT_THROW(parseScript(nlohmann::json::parse(R"([{"expect_failure": {"wait_frames": 1, "open": null}}])"), "bad"),
               std::runtime_error);
  EXPECT_THROW(parseScript(nlohmann::json::parse(R"([{"expect_failure": {"expect_failure": {}}}])"), "bad"),
               std::runtime_error);
}

TEST(ScriptActions, ApplyActionRefusesWhatOnlyTheRunnerWaitsFor) {
  AppState s;
  for (const char* name : {"open", "drop", "reload", "wait_frames", "screenshot", "export_png", "export_video",
                           "expect_failure", "mouse", "track_video", "detect_video", "drag_joint",
                           "write_joint_mapping"}) {
    ASSERT_NE(scriptAction(name), nullptr) << name;
    EXPECT_TRUE(scriptAction(name)->runnerOnly) << name;
    try {
      applyAction(s, {name, nullptr, 1});
      ADD_FAILURE() << name << " applied";
    } catch (const std::invalid_argument& e) {
      EXPECT_STREQ(e.what(), "cannot be used here") << name;
    }
  }
  EXPECT_THROW(applyAction(s, {"no_such_action", nullptr, 1}), std::invalid_argument);
}

TEST(ScriptActions, AppliesAndSaysWhatToWaitFor) {
  AppState s;
  applyAction(s, {"set_theme", "light", 1});
  EXPECT_EQ(s.view.theme, Theme::Light);
  applyAction(s, {"overlay", nlohmann::json::parse(R"(["trails", false])"), 1});
  EXPECT_FALSE(s.view.overlays.trails);
  EXPECT_THROW(applyAction(s, {"overlay", "trails", 1}), std::invalid_argument);

  ScriptWaits w;
  applyScriptAction(s, {"wait_frames", 3, 1}, w);
  EXPECT_EQ(w.frames, 3);
  applyScriptAction(s, {"screenshot", "shot.png", 1}, w);
  ASSERT_TRUE(w.capture.has_value());
  EXPECT_EQ(w.capture->string(), "shot.png");
  EXPECT_TRUE(scriptAction("screenshot")->yields);
  EXPECT_FALSE(scriptAction("set_theme")->yields);
}

}  // namespace
}  // namespace ew::ui
