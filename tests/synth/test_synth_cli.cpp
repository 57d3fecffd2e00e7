// `eigenwalker-cli synth`: writes walkers and a manifest our loaders read back, never a
// half-written folder, and refuses bad arguments with a clear message and exit code 2.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/gait/dataset.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

struct CliResult {
  int exitCode = -1;
  std::string output;  // stdout and stderr
};

CliResult runCli(const std::string& arguments, const fs::path& dir) {
  const fs::path log = dir / "cli_output.txt";
  const std::string command =
      std::string("\"") + EW_CLI_PATH + "\" " + arguments + " > \"" + log.string() + "\" 2>&1";
  const int status = std::system(command.c_str());
  CliResult r;
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log);
  std::ostringstream s;
  s << in.rdbuf();
  r.output = s.str();
  fs::remove(log);
  return r;
}

std::vector<std::string> lines(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

class SynthCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::makeTempDir("synth_cli"); }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(SynthCli, WritesCsvWalkersAndAManifestTheLoaderReads) {
  const fs::path out = dir_ / "population";
  const CliResult r =
      runCli("synth --count 4 --seed 3 --cycles 2 --out \"" + out.string() + "\"", dir_);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto manifest = lines(out / "walkers.csv");
  ASSERT_EQ(manifest.size(), 5u);
  EXPECT_EQ(manifest[0].rfind("file,subject,source,condition,height_m,", 0), 0u) << manifest[0];
  for (const char* column : {"cadence_spm", "stride_length_m", "speed_mps", "arm_swing_deg"}) {
    EXPECT_NE(manifest[0].find(column), std::string::npos) << column;
  }
  EXPECT_EQ(manifest[1].rfind("SYN001_T1.csv,SYN001,synthetic,", 0), 0u) << manifest[1];
  const Dataset d = loadDataset({out / "walkers.csv"});
  ASSERT_EQ(d.trials.size(), 4u);
  EXPECT_EQ(d.trials[2].info.source, "synthetic");
  EXPECT_FALSE(d.trials[2].info.attributes.at("speed_mps").empty());
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().filename().string().find(".partial"), std::string::npos)
        << "temporary folder left behind: " << entry.path();
  }
}

TEST_F(SynthCli, SameSeedSameBytes) {
  const fs::path a = dir_ / "a", b = dir_ / "b";
  ASSERT_EQ(runCli("synth --count 2 --seed 8 --out \"" + a.string() + "\"", dir_).exitCode, 0);
  ASSERT_EQ(runCli("synth --count 2 --seed 8 --out \"" + b.string() + "\"", dir_).exitCode, 0);
  for (const char* f : {"SYN001_T1.csv", "SYN002_T1.csv", "walkers.csv"}) {
    EXPECT_EQ(lines(a / f), lines(b / f)) << f;
  }
}

TEST_F(SynthCli, WritesBvhTheLoaderMapsBack) {
  const fs::path out = dir_ / "bvh";
  const CliResult r = runCli(
      "synth --count 2 --format bvh --trials 2 --treadmill --out \"" + out.string() + "\"", dir_);
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(out / "SYN002_T2.bvh"));
  const Dataset d = loadDataset({out / "walkers.csv"});
  ASSERT_EQ(d.trials.size(), 4u);
  EXPECT_EQ(d.subjects().size(), 2u);
  for (const auto& t : d.trials) {
    EXPECT_EQ(t.trial.joints.source, "Mixamo-style BVH");
    EXPECT_LT(t.trial.speedMps, 0.15) << "treadmill";
  }
}

TEST_F(SynthCli, RefusesToOverwriteANonEmptyFolderUnlessForced) {
  const fs::path out = dir_ / "existing";
  fs::create_directories(out);
  std::ofstream(out / "precious.txt") << "keep me";
  CliResult r = runCli("synth --count 1 --out \"" + out.string() + "\"", dir_);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.output.find("not empty"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(out / "precious.txt"));
  r = runCli("synth --count 1 --force --out \"" + out.string() + "\"", dir_);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(fs::exists(out / "precious.txt"));
  EXPECT_TRUE(fs::exists(out / "walkers.csv"));
}

TEST_F(SynthCli, BadArgumentsFailWithAMessage) {
  const std::string out = " --out \"" + (dir_ / "x").string() + "\"";
  struct Case {
    std::string args, expected;
  };
  for (const Case& c :
       {Case{"synth --count 0" + out, "--count"}, Case{"synth --count many" + out, "--count"},
        Case{"synth --format xyz" + out, "--format"}, Case{"synth --cycles 0.5" + out, "--cycles"},
        Case{"synth --rate -5" + out, "--rate"}, Case{"synth --count 2", "--out"}}) {
    const CliResult r = runCli(c.args, dir_);
    EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.expected), std::string::npos) << c.args << "\n" << r.output;
  }
  EXPECT_FALSE(fs::exists(dir_ / "x"));
}

}  // namespace
}  // namespace ew
