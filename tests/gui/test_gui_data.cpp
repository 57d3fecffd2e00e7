// Opening data in the viewer, end to end: a folder "dropped" (the script action goes through
// the same code as GLFW's drop callback) loads its trials; the data table (core's
// TrialSummary per file) follows a per-file frame-rate override after a reload; dropping
// something that is not motion capture is an error, not a crash.

#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

using GuiData = GuiTest;

TEST_F(GuiData, DropAFolderSummariseAndOverrideTheRate) {
  const auto syn = dir / "syn";
  const std::string synth = quote(EW_CLI_PATH) + " synth --out " + quote(syn.string()) +
                            " --count 4 --format bvh --force > /dev/null 2>&1";
  ASSERT_EQ(std::system(synth.c_str()), 0);
  const auto first = syn / "SYN001_T1.bvh";
  ASSERT_TRUE(std::filesystem::exists(first));
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"drop": [")" + syn.string() + R"("]},
    {"export_data_summary": ")" + d + R"(/before.json"},
    {"set_file_override": {"file": ")" + first.string() + R"(", "rate": 240}},
    {"reload": null},
    {"export_data_summary": ")" + d + R"(/after.json"},
    {"show_panel": ["data", true]},
    {"screenshot": ")" + d + R"(/data.png"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("Loaded syn: 4 walkers"), std::string::npos) << r.err;

  const auto before = nlohmann::json::parse(readAll(dir / "before.json")).at("trials");
  const auto after = nlohmann::json::parse(readAll(dir / "after.json")).at("trials");
  ASSERT_EQ(before.size(), 4u);
  ASSERT_EQ(after.size(), 4u);
  for (const auto& t : before) {
    EXPECT_TRUE(t.at("ok").get<bool>()) << t.dump();
    EXPECT_NEAR(t.at("rate_hz").get<double>(), 120.0, 1e-3);
  }
  // The overridden file plays twice as fast: twice the stride frequency; the others unchanged.
  for (std::size_t i = 0; i < 4; ++i) {
    const bool overridden = after[i].at("file").get<std::string>().find("SYN001_T1") != std::string::npos;
    const double ratio = after[i].at("stride_hz").get<double>() / before[i].at("stride_hz").get<double>();
    EXPECT_NEAR(after[i].at("rate_hz").get<double>(), overridden ? 240.0 : 120.0, 1e-3);
    EXPECT_NEAR(ratio, overridden ? 2.0 : 1.0, 0.02) << after[i].dump();
  }
  EXPECT_FALSE(cv::imread(d + "/data.png").empty());
}

TEST_F(GuiData, DroppingSomethingElseIsAnError) {
  const auto txt = dir / "notes.txt";
  std::ofstream(txt) << "hello";
  auto script = writeScript(dir, R"([{"drop": [")" + txt.string() + R"("]}])");
  RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script.string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("not a motion-capture file"), std::string::npos) << r.err;
  script = writeScript(dir, R"([{"drop": ["/nonexistent/x.bvh"]}])");
  r = runViewer(dir, "--size 800x600 --script " + quote(script.string()));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("no such file"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ew::test::gui
