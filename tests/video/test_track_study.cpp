// `eigenwalker-cli track-study` (video/track_study.h): a held-out shared walker filmed from the
// front and tracked by the flow tracker alone, one row in the CSV with the numbers the summary
// prints; the errors for an unknown subject, an azimuth out of range and data with too few
// walkers to hold one out.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using test::runCli;

std::vector<std::string> csvLines(const fs::path& file) {
  std::istringstream in(test::readTextFile(file));
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string f; std::getline(in, f, ',');) fields.push_back(f);
  return fields;
}

// CMU06 from the front, the tracker alone (measured 2.0 px median, 11.2 px p95, 1.04× the true
// 2D's MPJPE: docs/TRACKING_DESIGN.md "By view"): within a pixel of that and the same ratio to
// 0.05.
TEST(TrackStudyCli, FilmsTracksAndFitsAHeldOutWalker) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path dir = test::makeTempDir("track_study");
  const fs::path data = test::sharedDataDir() / "walkers.csv";
  const test::ShellRun run = runCli("track-study --data \"" + data.string() +
                                        "\" --subjects CMU06 --azimuths -90 --model-loop 0 "
                                        "--out study.csv --per-joint",
                                    dir);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  EXPECT_NE(run.err.find("CMU06 from -90.0 deg, 0 round(s)"), std::string::npos) << run.err;
  EXPECT_NE(run.out.find("whole_bar"), std::string::npos) << run.out;
  for (const char* joint : {" head ", " l_knee ", " r_ankle "})  // --per-joint's line
    EXPECT_NE(run.err.find(joint), std::string::npos) << joint << " in " << run.err;
  const std::vector<std::string> lines = csvLines(dir / "study.csv");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("subject,azimuth_deg,rounds,frames,stride_hz,track_median_px,", 0), 0u);
  const std::vector<std::string> row = csvFields(lines[1]);
  ASSERT_GE(row.size(), 14u) << lines[1];
  EXPECT_EQ(row[0], "CMU06");
  EXPECT_EQ(std::stod(row[1]), -90.0);
  EXPECT_EQ(row[2], "0");
  EXPECT_NEAR(std::stod(row[5]), 2.0, 1.0);   // median px
  EXPECT_NEAR(std::stod(row[6]), 11.2, 1.0);  // p95 px
  EXPECT_NEAR(std::stod(row[9]), 1.04, 0.05);  // MPJPE ratio
  EXPECT_EQ(std::stod(row[10]), 180.0);         // filmed from the front (METHOD §5)
  EXPECT_LT(std::abs(std::remainder(std::stod(row[12]) - 180.0, 360.0)), 10.0);  // the track's fit
  EXPECT_EQ(row[13], "0");                      // the p95 misses the bar without the loop
  fs::remove_all(dir);
}

TEST(TrackStudyCli, RefusesWhatItCannotStudy) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path dir = test::makeTempDir("track_study_bad");
  const fs::path data = test::sharedDataDir() / "walkers.csv";
  const test::ShellRun nobody =
      runCli("track-study --data \"" + data.string() + "\" --subjects NOBODY --out s.csv", dir);
  EXPECT_EQ(nobody.exitCode, 2);
  EXPECT_NE(nobody.err.find("no walker of subject 'NOBODY'"), std::string::npos) << nobody.err;
  const test::ShellRun far =
      runCli("track-study --data \"" + data.string() + "\" --azimuths 200 --out s.csv", dir);
  EXPECT_EQ(far.exitCode, 2) << far.err;
  const test::ShellRun seed =
      runCli("track-study --data \"" + data.string() + "\" --footage-seed -1 --out s.csv", dir);
  EXPECT_EQ(seed.exitCode, 2) << seed.err;
  EXPECT_NE(seed.err.find("--footage-seed"), std::string::npos) << seed.err;
  const fs::path oneTrial =
      test::sharedDataDir() / "schreiber-moissenet-2019/2014001/2014001_C4_05.c3d";
  const test::ShellRun alone =
      runCli("track-study --data \"" + oneTrial.string() + "\" --out s.csv", dir);
  EXPECT_EQ(alone.exitCode, 1);
  EXPECT_NE(alone.err.find("at least three walkers"), std::string::npos) << alone.err;
  EXPECT_FALSE(fs::exists(dir / "s.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ew
