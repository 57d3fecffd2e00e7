#include <gtest/gtest.h>

#include <fstream>

#include "core/common/errors.h"
#include "core/gait/dataset.h"
#include "core/io/joint_csv.h"
#include "tests/common/error_matchers.h"
#include "tests/common/synthetic_gait.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

std::filesystem::path writeWalker(const std::filesystem::path& dir, const std::string& name, double strideHz) {
  test::AnalyticGait g;
  g.strideHz = strideHz;
  const auto file = dir / name;
  std::filesystem::create_directories(file.parent_path());
  writeJointCsv(file, test::analyticWalkFrames(g), g.rateHz);
  return file;
}

TEST(Dataset, ManifestKeepsSubjectsConditionsAndExtraColumns) {
  const auto dir = test::makeTempDir("manifest");
  writeWalker(dir, "a/s1_t1.csv", 0.9);
  writeWalker(dir, "a/s1_t2.csv", 0.95);
  writeWalker(dir, "b/s2_t1.csv", 1.0);
  std::ofstream(dir / "m.csv") << "file,subject,source,condition,height_m\n"
                                  "a/s1_t1.csv,S1,lab,slow,1.70\n"
                                  "a/s1_t2.csv,S1,lab,slow,1.70\n"
                                  "b/s2_t1.csv,S2,lab,fast,1.82\n";
  const Dataset d = loadDataset({dir / "m.csv"});
  ASSERT_EQ(d.trials.size(), 3u);
  EXPECT_EQ(d.subjects(), (std::vector<std::string>{"S1", "S2"}));
  EXPECT_EQ(d.trials[2].info.condition, "fast");
  EXPECT_EQ(d.trials[2].info.attributes.at("height_m"), "1.82");
  EXPECT_NEAR(d.trials[1].trial.cycles.strideHz, 0.95, 0.02);
}

TEST(Dataset, PerFileOptionsReachOnlyTheirFile) {
  const auto dir = test::makeTempDir("perfile");
  const auto a = writeWalker(dir, "a.csv", 0.9);
  writeWalker(dir, "b.csv", 0.9);
  // Declaring a's frames at twice their rate doubles its stride frequency; b is untouched.
  const Dataset d = loadDatasetPerFile({dir}, [&a](const std::filesystem::path& f) {
    LoadOptions o;
    if (f.filename() == a.filename()) o.rateHzOverride = 200.0;  // written at 100 Hz
    return o;
  });
  ASSERT_EQ(d.trials.size(), 2u);
  for (const auto& t : d.trials) {
    const bool isA = t.info.file.find("a.csv") != std::string::npos;
    EXPECT_NEAR(t.trial.cycles.strideHz, isA ? 1.8 : 0.9, 0.04) << t.info.file;
  }
}

TEST(Dataset, FolderIsRecursiveAndSkipsUnusableFilesWithWarnings) {
  const auto dir = test::makeTempDir("folder");
  writeWalker(dir, "x/07_01.csv", 0.9);
  writeWalker(dir, "x/y/08_01.csv", 0.9);
  std::ofstream(dir / "x" / "broken.c3d") << "not a c3d";
  std::ofstream(dir / "readme.txt") << "ignored";
  const Dataset d = loadDataset({dir});
  ASSERT_EQ(d.trials.size(), 2u);
  EXPECT_EQ(d.trials[0].info.subject, "07");
  ASSERT_EQ(d.warnings.size(), 1u);
  EXPECT_NE(d.warnings[0].find("broken.c3d"), std::string::npos) << d.warnings[0];
}

// A folder with more under it than any dataset (a home, the whole disk, opened by mistake)
// stops the walk with an error naming it, rather than reading everything there.
TEST(Dataset, AFolderPastTheLimitsIsRefusedNotRead) {
  const auto dir = test::makeTempDir("folder_limits");
  for (int i = 0; i < 6; ++i) std::ofstream(dir / ("t" + std::to_string(i) + ".csv")) << "x\n";
  for (int i = 0; i < 6; ++i) std::ofstream(dir / ("notes" + std::to_string(i) + ".txt")) << "x\n";
  std::vector<std::string> warnings;
  EXPECT_EQ(collectTrialFiles({dir}, warnings, {20, 6}).size(), 6u);
  EXPECT_TRUE(test::throwsError([&] { collectTrialFiles({dir}, warnings, {20, 5}); }, ErrorKind::BadArgument,
                                {dir.string(), "more than 5 trial files", "open the folder that holds the trials"}));
  EXPECT_TRUE(test::throwsError([&] { collectTrialFiles({dir}, warnings, {11, 100}); }, ErrorKind::BadArgument,
                                {"more than 11 files and folders"}));
}

TEST(Dataset, ManifestRowThatFailsIsAnError) {
  const auto dir = test::makeTempDir("badrow");
  std::ofstream(dir / "m.csv") << "file,subject,source,condition\nmissing.c3d,S1,lab,walk\n";
  try {
    loadDataset({dir / "m.csv"});
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.c3d"), std::string::npos);
  }
  std::ofstream(dir / "m2.csv") << "file,source\na.csv,lab\n";
  EXPECT_THROW(loadDataset({dir / "m2.csv"}), Error);
  std::ofstream(dir / "m3.csv") << "file,subject\na.csv\n";
  EXPECT_THROW(loadDataset({dir / "m3.csv"}), Error);
}

}  // namespace
}  // namespace ew
