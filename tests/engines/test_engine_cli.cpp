// --engine in the CLI (issue 15): `build --engine snippet` writes a prior the snippet file
// reader loads, `reconstruct --engine snippet` reconstructs a walker the prior never saw, and
// every option that belongs to the other engine is an error naming it, not ignored.
// A synthetic population (no shared data): 10 walkers learnt, an eleventh held out.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/io/joint_csv.h"
#include "core/snippet/snippet_file.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

test::ShellRun runCli(const std::string& arguments, const fs::path& dir) {
  return test::runShell("cd \"" + dir.string() + "\" && \"" + EW_CLI_PATH + "\" " + arguments, dir);
}

class EngineCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = test::makeTempDir("engine_cli");
    for (const char* args : {"synth --count 10 --seed 11 --cycles 2 --out pop/",
                             "synth --count 1 --seed 99 --cycles 2 --out other/",
                             "build --engine snippet --data pop/walkers.csv --out prior.ewsp"}) {
      const test::ShellRun r = runCli(args, root_);
      ASSERT_EQ(r.exitCode, 0) << args << "\n" << r.err;
    }
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  static std::string heldOut() { return "other/SYN001_T1.csv"; }
  static fs::path root_;
};
fs::path EngineCli::root_;

TEST_F(EngineCli, BuildWritesAPriorOfTheWalkersItWasGiven) {
  const SnippetPrior p = loadSnippetPrior(root_ / "prior.ewsp");
  EXPECT_EQ(p.subjects.size(), 10u);
  EXPECT_EQ(p.components.size(), 8u);  // the default m
  EXPECT_EQ(p.frames, 11);
  const test::ShellRun r =
      runCli("build --engine snippet --data pop/walkers.csv --clusters 3 --components 12 --out small.ewsp", root_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const SnippetPrior small = loadSnippetPrior(root_ / "small.ewsp");
  ASSERT_EQ(small.components.size(), 3u);
  for (const auto& c : small.components) EXPECT_LE(c.basis.cols(), 12);
}

// Measured: 22.7 mm at the known view, α̂ 59.5° and 23.3 mm over the circle (a prior of 10
// synthetic walkers). 50 mm is about twice that; a wrong axis or a broken stitch is in the
// hundreds.
TEST_F(EngineCli, ReconstructsAHeldOutWalkerAtAKnownAndAnUnknownView) {
  for (const std::string angle : {"--angle 60", "--unknown-angle"}) {
    const test::ShellRun r = runCli("reconstruct --engine snippet --prior prior.ewsp --input " + heldOut() +
                                        " --project-angle 60 " + angle + " --out rec.csv --json",
                                    root_);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["engine"], "snippet");
    EXPECT_LT(j["errors"]["mpjpe_frames_mm"].get<double>(), 50.0) << angle;
    EXPECT_LT(j["angle_error_deg"].get<double>(), 10.0) << angle;
    EXPECT_EQ(j["angle_source"], angle == "--angle 60" ? "given" : "estimated");
    const RawTrial out = readJointCsv(root_ / "rec.csv");
    EXPECT_EQ(out.positionsMm.rows(), j["frames"].get<int>());
  }
}

TEST_F(EngineCli, TheOtherEnginesOptionsAreErrors) {
  const std::string in = " --input " + heldOut() + " --project-angle 60 --angle 60 --out x.csv";
  const std::pair<std::string, std::string> cases[] = {
      {"reconstruct --engine snippet --method lsq" + in, "--method"},
      {"reconstruct --engine snippet --sigma2 100" + in, "--sigma2"},
      {"reconstruct --engine snippet --components 3" + in, "--components"},
      {"reconstruct --engine snippet --model prior.ewsp" + in, "--model"},
      {"reconstruct --prior prior.ewsp" + in, "--prior"},
      {"reconstruct --engine zou" + in, "--engine"},
      {"build --engine snippet --data pop/walkers.csv --variance 0.9 --out y.ewsp", "--variance"},
      {"build --data pop/walkers.csv --clusters 4 --out y.ewm", "--clusters"},
  };
  for (const auto& [args, option] : cases) {
    const test::ShellRun r = runCli(args, root_);
    EXPECT_NE(r.exitCode, 0) << args;
    EXPECT_NE(r.err.find(option), std::string::npos) << args << "\n" << r.err;
  }
  EXPECT_FALSE(fs::exists(root_ / "x.csv"));
  EXPECT_FALSE(fs::exists(root_ / "y.ewsp"));
  EXPECT_FALSE(fs::exists(root_ / "y.ewm"));
}

TEST_F(EngineCli, WithoutAPriorTheSyntheticPopulationIsLearntAndSaidSo) {
  const test::ShellRun r = runCli("reconstruct --engine snippet --input " + heldOut() +
                                      " --project-angle 90 --angle 90 --out rec.csv --json",
                                  root_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("embedded synthetic population"), std::string::npos) << r.err;
  EXPECT_LT(nlohmann::json::parse(r.out)["errors"]["mpjpe_frames_mm"].get<double>(), 50.0);
}

// evaluate --engine: experiment "snippet" scores only the engines asked for; the paper's
// experiments are the eigenwalker's and say so. 4 walkers keep it short.
TEST_F(EngineCli, EvaluateScoresTheEnginesAskedFor) {
  ASSERT_EQ(runCli("synth --count 4 --seed 5 --cycles 2 --out four/", root_).exitCode, 0);
  const std::pair<std::string, std::string> runs[] = {{"--engine snippet", "snippet MAP"},
                                                      {"--engine eigenwalker --experiment snippet", "eigenwalker MAP"}};
  for (const auto& [args, engine] : runs) {
    const test::ShellRun r = runCli("evaluate --data four/walkers.csv --no-plots --out ev " + args, root_);
    ASSERT_EQ(r.exitCode, 0) << args << "\n" << r.err;
    const std::string csv = test::readTextFile(root_ / "ev" / "snippet_engines.csv");
    EXPECT_NE(csv.find(engine), std::string::npos) << args;
    EXPECT_EQ(csv.find(engine == "snippet MAP" ? "eigenwalker MAP" : "snippet MAP"), std::string::npos) << args;
    // The gait measures of each reconstruction beside the walker's own (issue 17).
    const std::string gait = test::readTextFile(root_ / "ev" / "gait_agreement.csv");
    EXPECT_NE(gait.find("," + engine + ",0,stride_length,"), std::string::npos) << gait;
    const std::string ba = test::readTextFile(root_ / "ev" / "gait_bland_altman.csv");
    EXPECT_EQ(ba.rfind("engine,angle_deg,measure,unit,pairs", 0), 0u) << ba;
    EXPECT_NE(ba.find(engine + ",90,knee_flexion_range,deg,4,0,"), std::string::npos) << ba;
  }
  const test::ShellRun paper =
      runCli("evaluate --data four/walkers.csv --engine snippet --experiment known-view --out ev2", root_);
  EXPECT_EQ(paper.exitCode, 2);
  EXPECT_NE(paper.err.find("is the eigenwalker's"), std::string::npos) << paper.err;
  EXPECT_FALSE(fs::exists(root_ / "ev2"));
}

// The skeleton engine (core/skeleton): scored by experiment "snippet"; nothing to build;
// reconstruct needs a calibrated camera and a reference's bone lengths, and each says so
// instead of running another engine.
TEST_F(EngineCli, TheSkeletonEngineIsScoredAndOtherwiseSaysWhereItIs) {
  ASSERT_EQ(runCli("synth --count 3 --seed 5 --cycles 2 --out three/", root_).exitCode, 0);
  const test::ShellRun r =
      runCli("evaluate --data three/walkers.csv --no-plots --engine skeleton --experiment snippet --out sk", root_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string csv = test::readTextFile(root_ / "sk" / "snippet_engines.csv");
  EXPECT_NE(csv.find(",skeleton,"), std::string::npos) << csv;
  EXPECT_EQ(csv.find("MAP"), std::string::npos) << csv;
  const std::pair<std::string, std::string> refusals[] = {
      {"build --engine skeleton --data three/walkers.csv --out s.ewm", "nothing to build"},
      {"reconstruct --engine skeleton --input three/SYN001_T1.csv --out r.csv", "give --camera FILE"},
      {"reconstruct --engine skeleton --input three/SYN001_T1.csv --angle 30 --out r.csv", "--angle"},
      {"evaluate --data three/walkers.csv --engine skeleton --experiment snippet-clusters --out sk2",
       "snippet prior's"}};
  for (const auto& [args, message] : refusals) {
    const test::ShellRun no = runCli(args, root_);
    EXPECT_NE(no.exitCode, 0) << args;
    EXPECT_NE(no.err.find(message), std::string::npos) << args << "\n" << no.err;
  }
  EXPECT_FALSE(fs::exists(root_ / "s.ewm"));
  EXPECT_FALSE(fs::exists(root_ / "sk2"));
  EXPECT_FALSE(fs::exists(root_ / "r.csv"));
}

// The balancing trial through camera 4: the 3D CSV written in the world frame, the JSON
// report scored against the triangulated 3D (docs/RESULTS.md: 163 / 120 mm).
TEST_F(EngineCli, TheSkeletonEngineReconstructsKeypointsThroughACalibratedCamera) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path d = fs::absolute(test::sharedDataDir() / "pose2sim-balancing");
  const test::ShellRun r = runCli("reconstruct --engine skeleton --input " + (d / "pose/cam04_json").string() +
                                      " --camera " + (d / "Calib_qualisys.toml").string() + " --camera-name cam_04 --fps 60"
                                      " --reference " + (d / "pose-3d/S00_P00_T01_BalancingTrial_0-100.trc").string() +
                                      " --out bal.csv --angles bal.mot --json", root_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const nlohmann::json report = nlohmann::json::parse(r.out);
  EXPECT_EQ(report["frame"], "world");
  EXPECT_EQ(report["reference"]["frames"], 100);
  EXPECT_LT(report["reference"]["mpjpe_procrustes_mm"].get<double>(), 200.0);
  EXPECT_LT(report["reference"]["mpjpe_procrustes_mm"].get<double>(),
            report["reference"]["mpjpe_mean_translation_mm"].get<double>());
  EXPECT_EQ(readJointCsv(root_ / "bal.csv").positionsMm.rows(), 100);
  const std::string mot = test::readTextFile(root_ / "bal.mot");
  EXPECT_NE(mot.find("nRows=100\nnColumns=27\ninDegrees=yes\n"), std::string::npos) << mot.substr(0, 200);
  EXPECT_NE(mot.find("endheader\ntime\tpelvis_tilt\t"), std::string::npos);
}

TEST_F(EngineCli, AnglesOfAnyTrialAndWhereTheyDoNotApply) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path trc = fs::absolute(test::sharedDataDir() / "pose2sim-balancing/pose-3d/S00_P00_T01_BalancingTrial_0-100.trc");
  const test::ShellRun r = runCli("angles " + trc.string() + " --out ref.csv", root_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("100 frames at 60 Hz, 23 angles"), std::string::npos) << r.err;
  const std::string csv = test::readTextFile(root_ / "ref.csv");
  EXPECT_NE(csv.find("# up=0 1 0 (file axes)\ntime_s,pelvis_tilt,"), std::string::npos) << csv.substr(0, 400);
  const test::ShellRun txt = runCli("angles " + trc.string() + " --out ref.txt", root_);
  EXPECT_EQ(txt.exitCode, 2) << txt.err;
  EXPECT_NE(txt.err.find(".csv or .mot"), std::string::npos) << txt.err;
  EXPECT_FALSE(fs::exists(root_ / "ref.txt"));
  const test::ShellRun other = runCli("reconstruct --input " + trc.string() + " --project-angle 30 --out x.csv --angles x.mot", root_);
  EXPECT_EQ(other.exitCode, 2) << other.err;
  EXPECT_NE(other.err.find("run `angles` on the 3D CSV"), std::string::npos) << other.err;
}

}  // namespace
}  // namespace ew
