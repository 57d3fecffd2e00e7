// `eigenwalker-cli gait` end to end: synthetic walkers measured as generated, the CSV and curves
// files, a trial that cannot be measured named with exit code 1, `--events file` on a trial
// without events refused, and a TRC written by `joints` that `gait` reads back.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

using test::runCli;

class GaitCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    root_ = test::makeTempDir("gait_cli");
    const test::ShellRun r = runCli("synth --count 3 --seed 7 --cycles 4 --out pop/", root_);
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(root_); }
  static fs::path root_;
};
fs::path GaitCli::root_;

std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

TEST_F(GaitCli, SyntheticWalkersAreMeasuredAsGenerated) {
  const test::ShellRun r = runCli("gait pop/walkers.csv --json --out gait.csv --curves curves.csv", root_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto all = nlohmann::json::parse(r.out);
  ASSERT_EQ(all.size(), 3u);
  const std::string manifest = test::readTextFile(root_ / "pop" / "walkers.csv");
  for (const auto& t : all) {
    EXPECT_EQ(t["events"], "kinematics");  // a synthetic CSV has no events of its own
    EXPECT_EQ(t["speed_source"], "progression");
    // The manifest holds the generating cadence and stride length of each walker.
    const std::string subject = t["subject"];
    const auto row = manifest.find(subject + "_T1.csv");
    ASSERT_NE(row, std::string::npos) << subject;
    EXPECT_GT(std::stod(t["cadence_spm"].get<std::string>()), 80.0);
    EXPECT_LT(std::stod(t["cadence_spm"].get<std::string>()), 140.0);
    EXPECT_GT(std::stod(t["stride_length_m"].get<std::string>()), 0.9);
    EXPECT_FALSE(t["events_s"]["right_strikes"].empty());
  }
  const auto csv = lines(test::readTextFile(root_ / "gait.csv"));
  ASSERT_EQ(csv.size(), 4u);
  EXPECT_EQ(csv[0].rfind("file,subject,events,strides,stride_time_s,cadence_spm,", 0), 0u);
  const auto curves = lines(test::readTextFile(root_ / "curves.csv"));
  EXPECT_EQ(curves[0], "file,events,curve,cycle_pct,mean_deg,sd_deg,strides");
  EXPECT_EQ(curves.size(), 1u + 3u * 8u * 101u);  // 3 walkers × 8 curves × 101 samples
}

TEST_F(GaitCli, ATrialThatCannotBeMeasuredIsNamedAndTheExitCodeIsOne) {
  // Half a second of a walker: walking, but no complete stride.
  const auto text = lines(test::readTextFile(root_ / "pop" / "SYN001_T1.csv"));
  std::string cut;
  int data = 0;
  for (const auto& l : text) {
    const bool comment = l.rfind('#', 0) == 0 || l.rfind("frame", 0) == 0;
    if (!comment && ++data > 60) break;
    cut += l + "\n";
  }
  test::writeBinaryFile(root_ / "short.csv", cut);
  const test::ShellRun r = runCli("gait short.csv", root_);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("short.csv"), std::string::npos) << r.err;
  const test::ShellRun file = runCli("gait pop/SYN001_T1.csv --events file", root_);
  EXPECT_EQ(file.exitCode, 1);
  EXPECT_NE(file.err.find("has no foot strike events"), std::string::npos) << file.err;
}

// A known stature scales a video's camera fit; a 3D trial's lengths are measured, not scaled.
TEST_F(GaitCli, AStatureIsForAVideosWalkerOnly) {
  const test::ShellRun r = runCli("gait pop/SYN001_T1.csv --stature 1.7", root_);
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("--stature"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("video"), std::string::npos) << r.err;
}

// A frame rate no camera has is refused, not ignored (once --rate 0, -5 or nan measured the
// trial at the file's rate as if nothing had been said).
TEST_F(GaitCli, ARateNoCameraHasIsRefused) {
  for (const std::string rate : {"0", "-5", "nan"}) {
    const test::ShellRun r = runCli("gait pop/SYN001_T1.csv --rate " + rate, root_);
    EXPECT_EQ(r.exitCode, 1) << rate;
    EXPECT_NE(r.err.find("frame rate " + rate + " Hz is outside"), std::string::npos) << r.err;
  }
}

TEST_F(GaitCli, ATrcWrittenByJointsIsMeasuredLikeItsSource) {
  ASSERT_EQ(runCli("joints pop/SYN002_T1.csv --out syn2.trc", root_).exitCode, 0);
  const test::ShellRun a = runCli("gait pop/SYN002_T1.csv --json", root_);
  const test::ShellRun b = runCli("gait syn2.trc --json", root_);
  ASSERT_EQ(a.exitCode, 0) << a.err;
  ASSERT_EQ(b.exitCode, 0) << b.err;
  const auto ja = nlohmann::json::parse(a.out)[0], jb = nlohmann::json::parse(b.out)[0];
  const auto value = [](const nlohmann::json& j, const char* k) { return std::stod(j[k].get<std::string>()); };
  EXPECT_NEAR(value(ja, "cadence_spm"), value(jb, "cadence_spm"), 0.5);
  EXPECT_NEAR(value(ja, "stance_pct"), value(jb, "stance_pct"), 0.5);
  // The TRC holds the walker in place (joints removes the progression): its speed and
  // footprints come from the stance feet, a few % slow on synthetic walkers (docs/GAIT.md).
  EXPECT_EQ(ja["speed_source"], "progression");
  EXPECT_EQ(jb["speed_source"], "stance feet");
  EXPECT_NEAR(value(jb, "stride_length_m"), value(ja, "stride_length_m"), 0.05 * value(ja, "stride_length_m"));
}

// The shared walkers: --events both gives a row per event source and the comparison line.
TEST(GaitCliSharedData, EventsBothComparesTheC3dEventsWithTheKinematics) {
  EW_REQUIRE_SHARED_DATA();
  const auto dir = test::makeTempDir("gait_cli_data");
  const auto trial = test::sharedDataDir() / "schreiber-moissenet-2019" / "2014022" / "2014022_C4_04.c3d";
  const test::ShellRun r = runCli("gait \"" + trial.string() + "\" --events both --whole-trial", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("file events"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("kinematics"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("kinematics vs file events over 1 trials"), std::string::npos) << r.err;
}

// A C3D with heel and toe markers: its kinematic events from the feet, the ankle's curve and
// range and the foot progression in the report, the ankle and foot columns in `angles`; a BVH
// without feet keeps the ankle's events and no such columns.
TEST(GaitCliSharedData, TheFeetGiveTheEventsTheAnkleAndTheFootProgression) {
  EW_REQUIRE_SHARED_DATA();
  const auto dir = test::makeTempDir("gait_cli_feet");
  const auto trial = test::sharedDataDir() / "schreiber-moissenet-2019" / "2014022" / "2014022_C4_04.c3d";
  const test::ShellRun r =
      runCli("gait \"" + trial.string() + "\" --events kinematics --whole-trial --json --curves curves.csv", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto t = nlohmann::json::parse(r.out).at(0);
  EXPECT_EQ(t["events"], "kinematics (heel and toe)");
  const double range = std::stod(t["ankle_flexion_range_deg"].get<std::string>());
  EXPECT_GT(range, 10.0);
  EXPECT_LT(range, 50.0);
  const std::string right = t["foot_progression_r_deg"], left = t["foot_progression_l_deg"];
  EXPECT_TRUE(right != "nan" || left != "nan") << right << " " << left;
  EXPECT_NE(test::readTextFile(dir / "curves.csv").find(",ankle_angle_"), std::string::npos);
  ASSERT_EQ(runCli("angles \"" + trial.string() + "\" --out a.csv", dir).exitCode, 0);
  const std::string angles = test::readTextFile(dir / "a.csv");
  EXPECT_NE(angles.find(",ankle_angle_r,foot_progression_r,ankle_angle_l,foot_progression_l,"), std::string::npos);
  const auto bvh = test::sharedDataDir() / "cmu-mocap-bvh" / "02" / "02_01.bvh";
  ASSERT_EQ(runCli("angles \"" + bvh.string() + "\" --out b.csv", dir).exitCode, 0);
  EXPECT_EQ(test::readTextFile(dir / "b.csv").find("ankle_angle"), std::string::npos);
  const test::ShellRun b = runCli("gait \"" + bvh.string() + "\" --json", dir);
  ASSERT_EQ(b.exitCode, 0) << b.err;
  EXPECT_EQ(nlohmann::json::parse(b.out).at(0)["events"], "kinematics");
  EXPECT_EQ(nlohmann::json::parse(b.out).at(0)["ankle_flexion_range_deg"], "nan");
  EXPECT_EQ(nlohmann::json::parse(b.out).at(0)["stride_length_sd_m"], "nan");  // measured, not fitted
}

// A folder of one subject's trials: each row of the table says which trial it is.
TEST(GaitCliSharedData, TheTableNamesEachTrialByItsFile) {
  EW_REQUIRE_SHARED_DATA();
  const auto dir = test::makeTempDir("gait_cli_folder");
  const test::ShellRun r = runCli("gait \"" + (test::sharedDataDir() / "cmu-mocap-bvh" / "02").string() + "\"", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out.rfind("trial\tevents\t", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("\n02_01.bvh\tkinematics\t"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\n02_02.bvh\tkinematics\t"), std::string::npos) << r.out;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace ew
