// The CLI on trials that lack joints: `info` lists the joints a model will estimate,
// `joints` writes them (estimated from the default model) with a comment line naming them,
// `reconstruct` takes a 2D CSV with a joint empty in every frame and a 3D lower-body trial,
// and a trial without an ankle is refused with the joints named.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/common/nan.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/synthetic_walkers.h"
#include "core/experiments/view_csv.h"
#include "core/io/joint_csv.h"
#include "tests/common/synthetic_gait.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Joints (METHOD §1 indices) blanked in every frame; `dims` columns per joint.
Eigen::MatrixXd blank(Eigen::MatrixXd frames, std::initializer_list<Joint> joints) {
  const auto dims = static_cast<int>(frames.cols()) / kJointCount;
  for (Joint j : joints) frames.middleCols(dims * index(j), dims).setConstant(kNaN);
  return frames;
}

const std::initializer_list<Joint> kUpperBody = {Joint::Head,   Joint::Sternum, Joint::RShoulder,
                                                 Joint::RElbow, Joint::RWrist,  Joint::LShoulder,
                                                 Joint::LElbow, Joint::LWrist};

class JointCompletionCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::makeTempDir("joint_completion_cli"); }
  test::ProgramRun cli(const std::vector<std::string>& args) {
    return test::runProgram(EW_CLI_PATH, args, dir_);
  }
  // A lower-body trial: the analytic walk with the trunk, head and arms absent.
  fs::path lowerBodyCsv() {
    test::AnalyticGait g;
    g.durationS = 4.0;
    const fs::path file = dir_ / "lower_body.csv";
    writeJointCsv(file, blank(test::analyticWalkFrames(g), kUpperBody), g.rateHz);
    return file;
  }
  fs::path dir_;
};

TEST_F(JointCompletionCli, InfoListsTheJointsTheModelWillEstimate) {
  const fs::path file = lowerBodyCsv();
  const auto run = cli({"info", "--json", file.string()});
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto json = nlohmann::json::parse(run.output.substr(run.output.find('[')));
  const std::vector<std::string> expected = {"head",    "sternum",    "r_shoulder", "r_elbow",
                                             "r_wrist", "l_shoulder", "l_elbow",    "l_wrist"};
  EXPECT_EQ(json[0]["joints_model_estimated"].get<std::vector<std::string>>(), expected);
  EXPECT_TRUE(json[0]["ok"].get<bool>());
  const auto table = cli({"info", file.string()});
  EXPECT_NE(table.output.find("model: head,sternum"), std::string::npos) << table.output;
}

TEST_F(JointCompletionCli, JointsWritesTheEstimatedJointsAndNamesThem) {
  const fs::path out = dir_ / "completed.csv";
  const auto run = cli({"joints", lowerBodyCsv().string(), "--out", out.string()});
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const std::string text = readText(out);
  EXPECT_NE(text.find("# model_estimated_joints=head, sternum, r_shoulder, r_elbow, r_wrist, "
                      "l_shoulder, l_elbow, l_wrist (not measured: estimated from the model"),
            std::string::npos)
      << text.substr(0, 600);
  const RawTrial back = readJointCsv(out);
  EXPECT_TRUE(back.positionsMm.allFinite());
}

TEST_F(JointCompletionCli, ReconstructsALowerBodyTrialAndScoresTheMeasuredJoints) {
  const fs::path out = dir_ / "rec.csv";
  const auto run = cli({"reconstruct", "--input", lowerBodyCsv().string(), "--project-angle", "30",
                        "--angle", "30", "--out", out.string(), "--json"});
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto json = nlohmann::json::parse(run.output.substr(run.output.find("\n{") + 1));
  EXPECT_EQ(json["joints_model_estimated"].size(), 8u);
  EXPECT_EQ(json["errors"]["joints_scored"], 7);
  EXPECT_TRUE(json["errors"]["mpjpe_model_estimated_mm"].is_null());
  EXPECT_GT(json["errors"]["mpjpe_measured_mm"].get<double>(), 0.0);
  EXPECT_TRUE(readJointCsv(out).positionsMm.allFinite());
}

TEST_F(JointCompletionCli, Reconstructs2DWithAWristEmptyInEveryFrame) {
  // The synthetic base walker seen at 30°, its right wrist never seen.
  const double rate = 100.0;
  const Eigen::MatrixXd frames = synthesizeFrames(
      syntheticBaseWalker(), 2.0 * std::numbers::pi * 0.9, 0.0, frameTimes(300, rate));
  const fs::path in = dir_ / "view.csv", out = dir_ / "rec.csv";
  writeViewCsv(in, {blank(projectFramesToView(frames, 30.0), {Joint::RWrist}), rate});
  const auto run = cli(
      {"reconstruct", "--input", in.string(), "--angle", "30", "--out", out.string(), "--json"});
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("\"joints_model_estimated\": [\n    \"r_wrist\"\n  ]"),
            std::string::npos)
      << run.output;
  const std::string text = readText(out);
  EXPECT_NE(text.find("# model_estimated_joints=r_wrist"), std::string::npos);
  EXPECT_TRUE(readJointCsv(out).positionsMm.allFinite());
}

TEST_F(JointCompletionCli, TooFewJointsIsADataErrorNamingThem) {
  test::AnalyticGait g;
  const fs::path file = dir_ / "no_ankle.csv";
  writeJointCsv(file, blank(test::analyticWalkFrames(g), {Joint::Head, Joint::LAnkle}), g.rateHz);
  const auto run = cli({"joints", file.string(), "--out", (dir_ / "x.csv").string()});
  EXPECT_EQ(run.exitCode, 1) << run.output;
  EXPECT_NE(run.output.find("too few joints measured to estimate the rest: l_ankle missing"),
            std::string::npos)
      << run.output;
}

}  // namespace
}  // namespace ew
