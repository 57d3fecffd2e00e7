// Experiment "engines" (core/experiments/engines_experiment.h) through the CLI on four
// synthetic walkers (no shared data): every engine on the same clips — the same views, noise
// levels and random cameras — in one CSV, with a summary, the gait agreement per setting and
// the plots; and its summary arithmetic on hand-made rows.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "core/experiments/engines_experiment.h"
#include "core/experiments/results_folder.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

using test::runCli;

// A CSV line split at commas outside quotes.
std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    else if (c == ',' && !quoted) out.emplace_back();
    else out.back() += c;
  }
  return out;
}

std::vector<std::map<std::string, std::string>> readCsv(const fs::path& file) {
  std::istringstream in(test::readTextFile(file));
  std::string line;
  std::getline(in, line);
  const auto header = cells(line);
  std::vector<std::map<std::string, std::string>> rows;
  while (std::getline(in, line)) {
    const auto c = cells(line);
    std::map<std::string, std::string> row;
    for (size_t i = 0; i < header.size() && i < c.size(); ++i) row[header[i]] = c[i];
    rows.push_back(row);
  }
  return rows;
}

// One run of every engine, and one of the skeleton engine alone; each test is its own
// process under ctest, so the runs are shared by one test rather than repeated by several.
class EnginesExperiment : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = test::makeTempDir("engines_experiment");
    ASSERT_EQ(runCli("synth --count 4 --seed 5 --cycles 2 --out four/", root_).exitCode, 0);
  }
  void TearDown() override { fs::remove_all(root_); }
  test::ShellRun evaluate(const std::string& options, const std::string& out) const {
    return runCli("evaluate --data four/walkers.csv --experiment engines --cameras 1 --angles 0,60 " + options +
                      " --out " + out,
                  root_);
  }
  fs::path root_;
};

// Same clips for every engine; the summary, the gait agreement and the plots.
TEST_F(EnginesExperiment, EveryEngineSeesTheSameClipsInOneTable) {
  const test::ShellRun run = evaluate("--threads 2", "ev");
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.err.find("engines:"), std::string::npos) << run.err;
  const fs::path ev = root_ / "ev";
  EXPECT_EQ(test::readTextFile(ev / "engines.csv").rfind(std::string(kEnginesHeader) + "\n", 0), 0u);
  const auto rows = readCsv(ev / "engines.csv");
  // A clip: setting, subject, view or camera, noise. Every engine answers each with the same frames.
  using Clip = std::tuple<std::string, std::string, std::string, std::string, std::string>;
  std::map<Clip, std::set<std::string>> engines, frames;
  for (const auto& r : rows) {
    const Clip clip{r.at("setting"), r.at("subject"), r.at("angle_deg"), r.at("camera"), r.at("noise")};
    engines[clip].insert(r.at("engine") + "/" + r.at("variant"));
    frames[clip].insert(r.at("frames"));
    EXPECT_EQ(r.at("error"), "") << r.at("engine") << " " << r.at("subject");
    EXPECT_GT(std::stod(r.at("seconds")), 0.0);
  }
  // 4 walkers × 2 views × 3 levels (mm), and 4 walkers × 1 camera × 3 levels (px).
  EXPECT_EQ(engines.size(), 4u * 2 * 3 + 4u * 1 * 3);
  for (const auto& [clip, names] : engines) {
    EXPECT_EQ(names.size(), std::get<0>(clip) == "view" ? 3u : 6u) << std::get<0>(clip) << " " << std::get<1>(clip);
    EXPECT_EQ(frames[clip].size(), 1u) << "engines scored on different clips";
  }

  EXPECT_EQ(test::readTextFile(ev / "engines_summary.csv").rfind(std::string(kEnginesSummaryHeader) + "\n", 0), 0u);
  EXPECT_EQ(test::readTextFile(ev / "engines_gait_bland_altman.csv").rfind(kEnginesBlandAltmanHeader, 0), 0u);
  std::set<std::string> settings;
  for (const auto& b : readCsv(ev / "engines_gait_bland_altman.csv")) {
    settings.insert(b.at("setting") + " " + b.at("noise"));
    // A camera row pools the random cameras of an azimuth band: it has no view angle.
    EXPECT_EQ(b.at("angle_deg").empty(), b.at("setting") == "camera");
    EXPECT_EQ(b.at("band").empty(), b.at("setting") != "camera");
  }
  EXPECT_EQ(settings, (std::set<std::string>{"view 0", "view 10", "view 20", "camera 0", "camera 2", "camera 5"}));
  // A row of measures per engine and clip, and one more per camera clip: the eigenwalker with
  // the stature given.
  const auto cameraClips = std::count_if(engines.begin(), engines.end(),
                                         [](const auto& e) { return std::get<0>(e.first) == "camera"; });
  EXPECT_EQ(readCsv(ev / "engines_gait_agreement.csv").size(),
            (rows.size() + static_cast<size_t>(cameraClips)) * agreementMeasures().size());
  for (const char* png : {"engines_views.png", "engines_cameras.png", "engines_time.png",
                          "engines_gait_stride_length_views.png", "engines_gait_stride_length_cameras.png"})
    EXPECT_GT(fs::file_size(ev / png), 5000u) << png;
  EXPECT_NE(test::readTextFile(ev / "summary.json").find("\"engines\""), std::string::npos);
}

// The noise is there (the per-frame geometry feels it), and each walker, view and level gets
// one draw whatever else runs: the skeleton engine alone, on one thread, gives the numbers it
// gave beside the others. --engine narrows the table; bad options leave no folder.
TEST_F(EnginesExperiment, NoiseIsOneDrawPerClipWhateverRunsBesideIt) {
  ASSERT_EQ(evaluate("--threads 2 --no-plots", "all").exitCode, 0);
  const test::ShellRun alone = evaluate("--engine skeleton --threads 1 --no-plots", "alone");
  ASSERT_EQ(alone.exitCode, 0) << alone.err;
  std::map<std::string, double> skeleton;  // mean MPJPE per noise level, views
  for (const auto& s : readCsv(root_ / "alone" / "engines_summary.csv"))
    if (s.at("setting") == "view" && s.at("engine") == "skeleton") skeleton[s.at("noise")] = std::stod(s.at("mean_mpjpe_mm"));
  ASSERT_EQ(skeleton.size(), 3u);
  // Measured 26 / 93 / 119 mm at 0 / 10 / 20 mm of noise (all four views): eq. 5 turns 2D noise
  // on a bone seen end-on into depth. Without noise applied the three would be equal.
  EXPECT_LT(skeleton["0"] * 2.0, skeleton["20"]);
  std::map<std::string, std::string> together;
  const auto key = [](const std::map<std::string, std::string>& r) {
    return r.at("setting") + "|" + r.at("subject") + "|" + r.at("variant") + "|" + r.at("angle_deg") + "|" + r.at("noise");
  };
  for (const auto& r : readCsv(root_ / "all" / "engines.csv"))
    if (r.at("engine") == "skeleton") together[key(r)] = r.at("mpjpe_mm");
  const auto rows = readCsv(root_ / "alone" / "engines.csv");
  ASSERT_EQ(rows.size(), together.size());
  for (const auto& r : rows) {
    EXPECT_EQ(r.at("engine"), "skeleton");
    EXPECT_EQ(together[key(r)], r.at("mpjpe_mm")) << key(r);
  }
  for (const char* args : {"--angles 0,nan", "--cameras 0"}) {
    const test::ShellRun bad =
        runCli(std::string("evaluate --data four/walkers.csv --experiment engines --out bad ") + args, root_);
    EXPECT_NE(bad.exitCode, 0) << args;
    EXPECT_FALSE(fs::exists(root_ / "bad")) << args;
  }
}

TEST(EnginesSummary, MeansMediansFailuresAndTimePerFrame) {
  const auto row = [](const std::string& engine, double noise, double mpjpe, double seconds, const std::string& error) {
    return EnginesRow{"view", "S", engine, "v", 0.0, -1, noise, "mm", 100, mpjpe, 0.0, seconds, error};
  };
  const std::vector<EnginesRow> rows = {row("a", 0, 10, 0.1, ""), row("a", 0, 30, 0.3, ""), row("a", 0, NAN, 0.2, "no"),
                                        row("a", 5, 50, 0.5, ""), row("b", 0, 7, 0.05, "")};
  const auto s = summarizeEngines(rows);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].engine, "a");
  EXPECT_EQ(s[0].clips, 3);
  EXPECT_EQ(s[0].failures, 1);
  EXPECT_DOUBLE_EQ(s[0].meanMpjpeMm, 20.0);
  EXPECT_DOUBLE_EQ(s[0].medianMpjpeMm, 30.0);  // the upper median of two
  EXPECT_NEAR(s[0].meanSeconds, 0.2, 1e-12);
  EXPECT_NEAR(s[0].msPerFrame, 2.0, 1e-12);   // 0.6 s over 300 frames
  EXPECT_EQ(s[1].noise, 5.0);
  EXPECT_EQ(s[2].engine, "b");
}

}  // namespace
}  // namespace ew
