// Settings persist between runs in $XDG_CONFIG_HOME/eigenwalker/settings.json: a first run
// changes the theme, an overlay and the data, the second run starts with them; a broken
// file is a warning, not a crash; --no-settings / EIGENWALKER_NO_SETTINGS leave no file.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

class GuiSettings : public GuiTest {
 protected:
  std::string env() const { return "XDG_CONFIG_HOME=" + quote((dir / "config").string()); }
  std::filesystem::path file() const { return dir / "config" / "eigenwalker" / "settings.json"; }
};

TEST_F(GuiSettings, PersistBetweenRuns) {
  // Run 1: light theme, grid off, a CSV of the displayed walker opened as data.
  const auto csv = (dir / "walker.csv").string();
  auto script = writeScript(dir, R"([
    {"set_theme": "light"},
    {"overlay": ["grid", false]},
    {"export_csv": {"path": ")" + csv + R"(", "cycles": 2}}
  ])");
  RunResult r = runViewer(dir, "--size 1000x700 --script " + quote(script.string()), env());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_TRUE(std::filesystem::exists(file())) << r.err;
  auto j = nlohmann::json::parse(readAll(file()));
  EXPECT_EQ(j.at("theme"), "light");
  EXPECT_EQ(j.at("overlays").at("grid"), false);
  EXPECT_EQ(j.at("window").at("width"), 1000);
  EXPECT_TRUE(j.at("data").empty());  // the synthetic default

  // Run 2 (no --size): starts light, grid off, at the saved size; the script checks nothing
  // but the log and the screenshot size do.
  script = writeScript(dir, R"([{"wait_frames": 2}])");
  r = runViewer(dir, "--script " + quote(script.string()) + " --screenshot " + quote((dir / "run2.png").string()),
                env());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("settings: "), std::string::npos) << r.err;
  const cv::Mat shot = cv::imread((dir / "run2.png").string());
  ASSERT_FALSE(shot.empty());
  EXPECT_EQ(shot.cols, 1000);
  EXPECT_EQ(shot.rows, 700);
  j = nlohmann::json::parse(readAll(file()));
  EXPECT_EQ(j.at("theme"), "light");
  EXPECT_EQ(j.at("overlays").at("grid"), false);
}

// Presentation mode is for the session: left on at exit, the next run starts without it.
TEST_F(GuiSettings, PresentationModeIsNotSaved) {
  auto script = writeScript(dir, R"([{"presentation": true}, {"wait_frames": 1}])");
  RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script.string()), env());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  ASSERT_TRUE(std::filesystem::exists(file())) << r.err;
  EXPECT_EQ(readAll(file()).find("presentation"), std::string::npos) << readAll(file());
  const auto state = (dir / "state.json").string();
  script = writeScript(dir, R"([{"wait_frames": 1}, {"export_state": ")" + state + R"("}])");
  r = runViewer(dir, "--size 800x600 --script " + quote(script.string()), env());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(readAll(state));
  EXPECT_FALSE(j["view"]["presentation"].get<bool>());
  EXPECT_FALSE(j["layout"]["presentation"].get<bool>());
}

TEST_F(GuiSettings, BrokenFileIsAWarningAndNoSettingsWritesNothing) {
  std::filesystem::create_directories(file().parent_path());
  std::ofstream(file()) << "{ not json";
  const auto script = writeScript(dir, R"([{"wait_frames": 1}])");
  RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script.string()), env());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("not valid JSON"), std::string::npos) << r.err;
  // Rewritten, valid, on exit.
  EXPECT_TRUE(nlohmann::json::accept(readAll(file())));

  std::filesystem::remove(file());
  r = runViewer(dir, "--no-settings --size 800x600 --script " + quote(script.string()), env());
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(file()));
  r = runViewer(dir, "--size 800x600 --script " + quote(script.string()), env() + " " + kNoSettings);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(file()));
}

}  // namespace
}  // namespace ew::test::gui
