// The CLI's defaults and small things a first-time user meets (issue 12): --version,
// output folders typed with a trailing slash, `reconstruct` without --model (the default
// model of real walkers), --components N (the viewer's N), and the σ² a model stores.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/eigenwalker/model_file.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

using CliResult = test::ShellRun;

// The CLI run from inside `dir` (relative paths in `arguments` are the user's).
CliResult runCli(const std::string& arguments, const fs::path& dir) {
  return test::runShell("cd \"" + dir.string() + "\" && \"" + EW_CLI_PATH + "\" " + arguments, dir);
}

std::string q(const fs::path& p) { return "\"" + p.string() + "\""; }

// Entries of a folder whose names start with '.': the atomic writers' temporary siblings.
int hiddenEntries(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir))
    n += e.path().filename().string().rfind('.', 0) == 0;
  return n;
}

// One synthetic population of 5 subjects for the suite (run from inside root_, so the
// relative paths with a trailing slash are the user's).
class CliDefaults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = test::makeTempDir("cli_defaults");
    const CliResult r = runCli("synth --count 5 --seed 11 --cycles 2 --out pop/", root_);
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  static fs::path manifest() { return root_ / "pop" / "walkers.csv"; }
  static fs::path trial() {
    for (const auto& e : fs::directory_iterator(root_ / "pop"))
      if (e.path().filename() != "walkers.csv" && e.path().extension() == ".csv") return e.path();
    return {};
  }
  void SetUp() override { dir_ = test::makeTempDir("cli_defaults_case"); }
  void TearDown() override { fs::remove_all(dir_); }
  static fs::path root_;
  fs::path dir_;
};
fs::path CliDefaults::root_;

TEST_F(CliDefaults, VersionNamesTheProjectVersionAndCommit) {
  const CliResult r = runCli("--version", dir_);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.rfind("eigenwalker-cli 0.", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("(commit "), std::string::npos) << r.out;
}

TEST_F(CliDefaults, SynthWithATrailingSlashWritesTheFolder) {
  // The suite's population was written with "--out pop/": the folder, nothing beside it.
  EXPECT_TRUE(fs::exists(manifest()));
  EXPECT_EQ(hiddenEntries(root_), 0);
  EXPECT_EQ(hiddenEntries(root_ / "pop"), 0);
  const CliResult again = runCli("synth --count 3 --seed 2 --out " + q(dir_ / "s//"), dir_);
  EXPECT_EQ(again.exitCode, 0) << again.err;
  EXPECT_TRUE(fs::exists(dir_ / "s" / "walkers.csv"));
}

TEST_F(CliDefaults, EvaluateWithATrailingSlashWritesTheFolder) {
  const CliResult r =
      runCli("evaluate --data " + q(manifest()) + " --out results/ --experiment variance", dir_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir_ / "results" / "summary.json"));
  EXPECT_TRUE(fs::exists(dir_ / "results" / "variance.csv"));
  EXPECT_EQ(hiddenEntries(dir_), 0);
}

TEST_F(CliDefaults, BuildStoresTheSigma2OptimumAndReconstructUsesIt) {
  const CliResult b = runCli("build --data " + q(manifest()) + " --out m.ewm", dir_);
  ASSERT_EQ(b.exitCode, 0) << b.err;
  EXPECT_NE(b.err.find("MAP sigma2 optimum on the model's walkers"), std::string::npos) << b.err;
  const EigenwalkerModel m = loadModel(dir_ / "m.ewm");
  ASSERT_TRUE(m.sigma2Optimum.has_value());
  for (const auto& line : m.provenance)
    EXPECT_EQ(line.find(root_.string()), std::string::npos) << line;
  const std::string input =
      " --input " + q(trial()) + " --project-angle 30 --angle 30 --json --out rec.csv";
  const CliResult r = runCli("reconstruct --model m.ewm" + input, dir_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["sigma2_mm2"].get<double>(), m.sigma2Optimum->sigma2Mm2);
  EXPECT_NE(j["sigma2_source"].get<std::string>().find("optimum measured"), std::string::npos);
  // Without the sweep the model records none: the paper's 70 mm², said so.
  ASSERT_EQ(
      runCli("build --data " + q(manifest()) + " --no-sigma2-sweep --out plain.ewm", dir_).exitCode,
      0);
  EXPECT_FALSE(loadModel(dir_ / "plain.ewm").sigma2Optimum.has_value());
  const auto p = nlohmann::json::parse(runCli("reconstruct --model plain.ewm" + input, dir_).out);
  EXPECT_EQ(p["sigma2_mm2"].get<double>(), 70.0);
  EXPECT_NE(p["sigma2_source"].get<std::string>().find("the paper's 70"), std::string::npos);
  // --sigma2 still wins.
  const auto g =
      nlohmann::json::parse(runCli("reconstruct --model m.ewm --sigma2 123" + input, dir_).out);
  EXPECT_EQ(g["sigma2_mm2"].get<double>(), 123.0);
}

// The first N eigenwalkers of a model are the model built with N: the same k. (The trial is one
// of the models' walkers: --in-sample keeps them whole, the property being of the models as
// built.)
TEST_F(CliDefaults, ComponentsTruncatesTheModelAsBuildingWithNDoes) {
  ASSERT_EQ(
      runCli("build --data " + q(manifest()) + " --components 4 --out four.ewm", dir_).exitCode, 0);
  ASSERT_EQ(
      runCli("build --data " + q(manifest()) + " --components 2 --out two.ewm", dir_).exitCode, 0);
  const std::string input =
      " --input " + q(trial()) + " --project-angle 40 --angle 40 --sigma2 200 --in-sample --json --out rec.csv";
  const CliResult cut = runCli("reconstruct --model four.ewm --components 2" + input, dir_);
  const CliResult two = runCli("reconstruct --model two.ewm" + input, dir_);
  ASSERT_EQ(cut.exitCode, 0) << cut.err;
  ASSERT_EQ(two.exitCode, 0) << two.err;
  const auto a = nlohmann::json::parse(cut.out), b = nlohmann::json::parse(two.out);
  EXPECT_EQ(a["components"], 2);
  ASSERT_EQ(a["k"].size(), 2u);
  for (size_t n = 0; n < 2; ++n)
    EXPECT_NEAR(a["k"][n].get<double>(), b["k"][n].get<double>(), 1e-6);
  EXPECT_NEAR(a["errors"]["mpjpe_mm"].get<double>(), b["errors"]["mpjpe_mm"].get<double>(), 1e-6);
  const CliResult tooMany = runCli("reconstruct --model two.ewm --components 3" + input, dir_);
  EXPECT_EQ(tooMany.exitCode, 2);
  EXPECT_NE(tooMany.err.find("--components"), std::string::npos) << tooMany.err;
}

TEST_F(CliDefaults, ReconstructWithoutAModelUsesTheDefaultRealModel) {
  const CliResult r = runCli("reconstruct --input " + q(trial()) +
                                 " --project-angle 30 --unknown-angle --json --out rec.csv",
                             dir_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("model: 24 real walkers (default)"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"], "24 real walkers (default)");
  EXPECT_TRUE(fs::exists(dir_ / "rec.csv"));
}

}  // namespace
}  // namespace ew
