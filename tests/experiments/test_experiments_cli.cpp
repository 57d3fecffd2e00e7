// `eigenwalker-cli evaluate | build | reconstruct` end to end on a small synthetic
// population (written by `eigenwalker-cli synth`): files with exact headers, clear errors
// with exit codes 1 (data) and 2 (usage), and an output folder never left half-written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/io/joint_csv.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

using CliResult = test::ShellRun;
using test::readTextFile;

CliResult runCli(const std::string& arguments, const fs::path& dir) {
  return test::runShell(std::string("\"") + EW_CLI_PATH + "\" " + arguments, dir);
}

std::string firstLine(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
  }
  return line;
}

std::string q(const fs::path& p) { return "\"" + p.string() + "\""; }

// One population for the whole suite: 5 subjects, and a 2-subject one (too few for LOO).
class ExperimentsCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = test::makeTempDir("experiments_cli");
    for (const auto& [name, count] : {std::pair{"five", 5}, std::pair{"two", 2}}) {
      const CliResult r = runCli("synth --count " + std::to_string(count) + " --seed 7 --cycles 2 --out " +
                                     q(root_ / name),
                                 root_);
      ASSERT_EQ(r.exitCode, 0) << r.err;
    }
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  static fs::path five() { return root_ / "five" / "walkers.csv"; }
  static fs::path two() { return root_ / "two" / "walkers.csv"; }
  void SetUp() override { dir_ = test::makeTempDir("experiments_cli_case"); }
  void TearDown() override { fs::remove_all(dir_); }

  static fs::path root_;
  fs::path dir_;
};
fs::path ExperimentsCli::root_;

TEST_F(ExperimentsCli, EvaluateWritesTheChosenExperiments) {
  const fs::path out = dir_ / "eval";
  const CliResult r = runCli("evaluate --data " + q(five()) + " --out " + q(out) +
                                 " --experiment variance,known-view --experiment unknown-view --angles 0,60"
                                 " --sigma2 200 --threads 2",
                             dir_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(firstLine(out / "harmonics.csv"), "walker,subject,source,stride_hz,h1_share,h2_share,residual_share");
  EXPECT_EQ(firstLine(out / "variance.csv"), "component,eigenvalue_mm2,variance_share,cumulative_share");
  EXPECT_EQ(firstLine(out / "known_view.csv"),
            "subject,angle_deg,method,abs_error_mm2,rel_error,var_missing_mm2,mpjpe_mm");
  EXPECT_EQ(firstLine(out / "unknown_view.csv"),
            "subject,true_angle_deg,method,est_angle_deg,angle_error_deg,abs_error_mm2,mpjpe_mm");
  EXPECT_FALSE(fs::exists(out / "sigma_sweep.csv"));  // σ² given, sweep not chosen
  EXPECT_FALSE(fs::exists(out / "noise.csv"));
  const auto s = nlohmann::json::parse(readTextFile(out / "summary.json"));
  EXPECT_EQ(s["walkers"], 5);
  EXPECT_EQ(s["subjects"], 5);
  EXPECT_EQ(s["sigma2_used_mm2"], 200.0);
  EXPECT_TRUE(s["sigma2_opt_mm2"].is_null());
  EXPECT_EQ(s["data_files"].size(), 5u);
  EXPECT_NE(s["command_line"].get<std::string>().find("evaluate"), std::string::npos);
  EXPECT_GT(s["known_view"]["lsq"]["mean_abs_error_mm2"].get<double>(), 0.0);
  EXPECT_LE(s["unknown_view"]["map"]["mae_deg"].get<double>(), 180.0);
  EXPECT_NE(r.err.find("known-view"), std::string::npos) << r.err;  // progress lines
  // The figures, drawn by the plots library the CLI links (core only describes them).
  for (const char* png : {"fig2_cumulative_variance.png", "fig5a_abs_error.png", "fig6_view_angle.png"})
    EXPECT_TRUE(fs::exists(out / png)) << png;
  // Nothing left beside the folder.
  for (const auto& e : fs::directory_iterator(dir_)) EXPECT_EQ(e.path().filename(), "eval");

  // --no-plots: the CSVs only.
  const fs::path bare = dir_ / "bare";
  ASSERT_EQ(runCli("evaluate --data " + q(five()) + " --out " + q(bare) + " --experiment variance --no-plots", dir_).exitCode, 0);
  EXPECT_TRUE(fs::exists(bare / "variance.csv"));
  EXPECT_FALSE(fs::exists(bare / "fig2_cumulative_variance.png"));
}

TEST_F(ExperimentsCli, UsageErrorsExitWith2) {
  const fs::path out = dir_ / "eval";
  const std::string data = " --data " + q(five());
  struct Case {
    std::string args, mention;
  };
  std::ofstream(dir_ / "a_file") << "x";
  const std::vector<Case> cases = {
      {"evaluate --out " + q(out), "--data"},
      {"evaluate" + data + " --out " + q(out) + " --method median", "--method"},
      {"evaluate" + data + " --out " + q(out) + " --experiment everything", "--experiment"},
      {"evaluate" + data + " --out " + q(out) + " --angles 90:0:1", "--angles"},
      {"evaluate" + data + " --out " + q(out) + " --threads 0", "--threads"},
      {"evaluate" + data + " --out " + q(dir_ / "a_file"), "not a folder"},
      {"build" + data + " --out " + q(dir_ / "m.ewm") + " --components 3 --variance 0.9", "excludes"},
      {"reconstruct --model " + q(dir_ / "a_file") + " --input " + q(dir_ / "a_file") + " --out " +
           q(dir_ / "o.csv"),
       "--angle"},
  };
  for (const auto& c : cases) {
    const CliResult r = runCli(c.args, dir_);
    EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.mention), std::string::npos) << c.args << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(ExperimentsCli, UnusableDataExitsWith1AndLeavesTheFolderAsItWas) {
  const fs::path out = dir_ / "eval";
  fs::create_directory(out);
  std::ofstream(out / "marker.txt") << "previous";
  const CliResult few = runCli("evaluate --data " + q(two()) + " --out " + q(out) + " --angles 0", dir_);
  EXPECT_EQ(few.exitCode, 1) << few.err;
  EXPECT_NE(few.err.find("at least 3 subjects"), std::string::npos) << few.err;
  const CliResult missing = runCli("evaluate --data " + q(dir_ / "nope.csv") + " --out " + q(out), dir_);
  EXPECT_EQ(missing.exitCode, 1) << missing.err;
  EXPECT_NE(missing.err.find("nope.csv"), std::string::npos) << missing.err;
  EXPECT_EQ(readTextFile(out / "marker.txt"), "previous");
  size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++entries;
  EXPECT_EQ(entries, 1u);
  std::ofstream(dir_ / "bad.ewm") << "not a model\n";
  const CliResult badModel = runCli("reconstruct --model " + q(dir_ / "bad.ewm") + " --input " +
                                        q(root_ / "five" / "walkers.csv") + " --angle 0 --out " + q(dir_ / "o.csv"),
                                    dir_);
  EXPECT_EQ(badModel.exitCode, 1) << badModel.err;
  EXPECT_NE(badModel.err.find("bad.ewm"), std::string::npos) << badModel.err;
}

TEST_F(ExperimentsCli, BuildThenReconstructA3DTrialAndIts2DView) {
  const fs::path model = dir_ / "model.ewm";
  const CliResult b = runCli("build --data " + q(five()) + " --out " + q(model), dir_);
  ASSERT_EQ(b.exitCode, 0) << b.err;
  EXPECT_NE(b.err.find("model of 5 walkers"), std::string::npos) << b.err;
  fs::path trial;
  for (const auto& e : fs::directory_iterator(root_ / "five")) {
    if (e.path().filename() != "walkers.csv" && e.path().extension() == ".csv") trial = e.path();
  }
  ASSERT_FALSE(trial.empty());
  // A 3D trial seen at 30°: the walker is in the model; used whole (--in-sample), the
  // reconstruction is close.
  const CliResult known = runCli("reconstruct --model " + q(model) + " --input " + q(trial) +
                                     " --project-angle 30 --angle 30 --method lsq --in-sample --json --out " +
                                     q(dir_ / "rec.csv") + " --save-2d " + q(dir_ / "view.csv"),
                                 dir_);
  ASSERT_EQ(known.exitCode, 0) << known.err;
  const auto j = nlohmann::json::parse(known.out);
  EXPECT_EQ(j["angle_deg"], 30.0);
  EXPECT_TRUE(j["held_out"].is_null());
  EXPECT_LT(j["errors"]["mpjpe_mm"].get<double>(), 10.0) << known.out;
  // By default its subject is left out (METHOD §4), as the viewer does: the model of the other
  // four reconstructs it, less closely.
  const CliResult heldOut = runCli("reconstruct --model " + q(model) + " --input " + q(trial) +
                                       " --project-angle 30 --angle 30 --method lsq --json --out " + q(dir_ / "rec_loo.csv"),
                                   dir_);
  ASSERT_EQ(heldOut.exitCode, 0) << heldOut.err;
  const auto loo = nlohmann::json::parse(heldOut.out);
  EXPECT_FALSE(loo["held_out"].is_null());
  EXPECT_NE(heldOut.err.find("left out (leave-one-subject-out, 4 walkers"), std::string::npos) << heldOut.err;
  EXPECT_GT(loo["errors"]["mpjpe_mm"].get<double>(), j["errors"]["mpjpe_mm"].get<double>());
  EXPECT_EQ(firstLine(dir_ / "rec.csv"), jointCsvHeader());
  EXPECT_EQ(firstLine(dir_ / "view.csv").substr(0, 26), "frame,time_s,head_u,head_v");
  // The saved 2D view, angle unknown: found again.
  const CliResult unknown = runCli("reconstruct --model " + q(model) + " --input " + q(dir_ / "view.csv") +
                                       " --unknown-angle --json --out " + q(dir_ / "rec2.csv"),
                                   dir_);
  ASSERT_EQ(unknown.exitCode, 0) << unknown.err;
  const auto u = nlohmann::json::parse(unknown.out);
  EXPECT_NEAR(u["angle_deg"].get<double>(), 30.0, 2.0) << unknown.out;
  EXPECT_FALSE(u.contains("errors"));  // no ground truth for a 2D file
  EXPECT_GE(u["minima"].size(), 1u);
  // A 3D trial needs --project-angle; a 2D one must not have it.
  EXPECT_EQ(runCli("reconstruct --model " + q(model) + " --input " + q(trial) + " --angle 0 --out " +
                       q(dir_ / "x.csv"), dir_).exitCode, 2);
  EXPECT_EQ(runCli("reconstruct --model " + q(model) + " --input " + q(dir_ / "view.csv") +
                       " --angle 0 --project-angle 10 --out " + q(dir_ / "x.csv"), dir_).exitCode, 2);
}

}  // namespace
}  // namespace ew
