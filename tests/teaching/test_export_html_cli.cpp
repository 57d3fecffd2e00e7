// `eigenwalker-cli export-html`: the walker it picks, the settings it passes, what it refuses.
#include <gtest/gtest.h>

#include "tests/common/test_support.h"

namespace ew {
namespace {

using test::runCli;

class ExportHtmlCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::makeTempDir("export_html_cli"); }
  std::filesystem::path dir_;
};

TEST_F(ExportHtmlCli, WritesTheMeanWalkerByDefault) {
  const test::ShellRun r = runCli("export-html --out walker.html", dir_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("wrote walker.html: the mean walker of 24 real walkers (default), "
                       "view angle 90"),
            std::string::npos)
      << r.err;
  const std::string page = test::readTextFile(dir_ / "walker.html");
  EXPECT_NE(page.find("const W = ["), std::string::npos);
  EXPECT_NE(page.find("lines: false, translate: false"), std::string::npos);
}

TEST_F(ExportHtmlCli, PassesTheSettings) {
  const test::ShellRun r = runCli(
      "export-html --out w.html --walker 2 --angle 45 --elevation 10 --speed -1 --phase 0.25 "
      "--lines --translate "
      "--size 640x480 --dot-radius 3 --theme light --dot-colour '#aa0000' --framing viewer --title "
      "'Walker two' "
      "--caption 'From the default model'",
      dir_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("walking overground at"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(the walker's own)"), std::string::npos) << r.err;
  const std::string page = test::readTextFile(dir_ / "w.html");
  for (const char* part :
       {"const S = {width: 640, height: 480, viewAngleDeg: 45, elevationDeg: 10, playbackSpeed: "
        "-1, "
        "startPhase01: 0.25, lines: true, translate: true",
        "dotRadiusPx: 3}", "dot: \"#aa0000\"", "background: \"#ffffff\"", "<h1>Walker two</h1>",
        "From the default model", "pxPerMm: 0.20425531914893616"})
    EXPECT_NE(page.find(part), std::string::npos) << part;
}

TEST_F(ExportHtmlCli, FitsATrial) {
  ASSERT_EQ(runCli("synth --count 1 --seed 7 --cycles 4 --out pop/", dir_).exitCode, 0);
  const test::ShellRun r =
      runCli("export-html --input pop/SYN001_T1.csv --out trial.html --translate", dir_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("wrote trial.html: pop/SYN001_T1.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(the trial's own)"), std::string::npos) << r.err;
}

TEST_F(ExportHtmlCli, RefusesBadOptions) {
  const auto refused = [&](const std::string& args, const std::string& part) {
    const test::ShellRun r = runCli("export-html --out bad.html " + args, dir_);
    EXPECT_EQ(r.exitCode, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find(part), std::string::npos) << args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "bad.html")) << args;
  };
  refused("--theme neon", "--theme: \"neon\" is not one of dark, light, projector");
  refused("--framing wide", "--framing: \"wide\" is not one of fit, viewer");
  refused("--walker 99", "--walker: \"99\" is no walker's id, nor a number from 1 to 24");
  refused("--walker SM2014", "(its walkers: SM2014001/spontaneous, ");
  refused("--size 800", "--size: \"800\": expected WIDTHxHEIGHT");
  refused("--elevation 91",
          "bad.html: HTML walker: the elevation (degrees) must be in [-90, 90], got 91");
  refused("--dot-colour red", "bad.html: HTML walker: the dot colour must be #rrggbb");
  test::writeBinaryFile(dir_ / "x.csv", "");
  refused("--walker 1 --input x.csv", "excludes");
  refused("--rate 100", "requires --input");
}

}  // namespace
}  // namespace ew
