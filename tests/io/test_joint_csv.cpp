#include <gtest/gtest.h>

#include <fstream>

#include "core/common/errors.h"
#include "core/io/file_bytes.h"
#include "core/io/joint_csv.h"
#include "core/io/load_trial.h"
#include "tests/common/synthetic_gait.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

std::string sampleCsv(int rows) {
  std::string text = jointCsvHeader() + "\n";
  for (int r = 0; r < rows; ++r) {
    text += std::to_string(r) + "," + std::to_string(r / 100.0);
    for (int c = 0; c < kDims3; ++c) text += "," + std::to_string(r * 100 + c);
    text += "\n";
  }
  return text;
}

TEST(JointCsv, RoundTripKeepsValuesRateAndMissingSamples) {
  const auto dir = test::makeTempDir("csv");
  Eigen::MatrixXd frames = test::analyticWalkFrames(test::AnalyticGait{});
  frames(10, 7) = std::nan("");
  writeJointCsv(dir / "walk.csv", frames, 100.0, {"a comment"});
  RawTrial raw = readRawTrial(dir / "walk.csv");
  EXPECT_EQ(raw.format, "CSV");
  EXPECT_EQ(raw.kind, PointKind::CanonicalJoints);
  EXPECT_DOUBLE_EQ(raw.rateHz, 100.0);
  ASSERT_EQ(raw.positionsMm.rows(), frames.rows());
  EXPECT_TRUE(std::isnan(raw.positionsMm(10, 7)));
  frames(10, 7) = raw.positionsMm(10, 7) = 0.0;
  // Written with 10 significant digits: mm values of ~1e3 keep 1e-6 mm.
  EXPECT_LT((raw.positionsMm - frames).cwiseAbs().maxCoeff(), 1e-5);
}

TEST(JointCsv, RateFromTimeColumnAndUnitsDirective) {
  const RawTrial raw = parseJointCsv("# units=m\n" + sampleCsv(5), "t.csv");
  EXPECT_NEAR(raw.rateHz, 100.0, 1e-9);
  EXPECT_DOUBLE_EQ(raw.positionsMm(1, 0), 100.0 * 1000.0);
}

TEST(JointCsv, MalformedInputNamesFileAndLine) {
  auto expectError = [](const std::string& text, const std::string& needle) {
    try {
      parseJointCsv(text, "bad.csv");
      ADD_FAILURE() << "accepted: " << needle;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("bad.csv"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expectError("", "empty file");
  expectError("frame,time_s,head_x\n0,0,1\n", "columns");
  std::string text = sampleCsv(3);
  expectError(text.substr(0, text.size() - 30), "line 4");
  std::string garbage = sampleCsv(3);
  garbage.replace(garbage.find("\n1,") + 5, 3, "abc");
  expectError(garbage, "not a number");
  expectError(jointCsvHeader() + "\n", "no data rows");
}

TEST(JointCsv, TruncatedAtEveryOffsetNeverCrashes) {
  const std::string text = sampleCsv(4);
  for (size_t n = 0; n < text.size(); n += 3) {
    try {
      parseJointCsv(text.substr(0, n), "cut.csv");
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("cut.csv"), std::string::npos);
    }
  }
}

TEST(LoadTrial, WrongExtensionAndMissingFileAreClearErrors) {
  const auto dir = test::makeTempDir("ext");
  std::ofstream(dir / "walk.xyz") << "hello";
  try {
    readRawTrial(dir / "walk.xyz");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Unsupported);
    EXPECT_NE(std::string(e.what()).find("walk.xyz"), std::string::npos);
  }
  try {
    readRawTrial(dir / "absent.c3d");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    EXPECT_NE(std::string(e.what()).find("no such file"), std::string::npos);
  }
  std::ofstream(dir / "text.csv") << "this is not a table\n";
  EXPECT_THROW(readRawTrial(dir / "text.csv"), Error);
}

TEST(LoadTrial, UnitsConvertToMillimetres) {
  EXPECT_DOUBLE_EQ(unitToMm("m", "f"), 1000.0);
  EXPECT_DOUBLE_EQ(unitToMm("CM", "f"), 10.0);
  EXPECT_DOUBLE_EQ(unitToMm(" mm ", "f"), 1.0);
  EXPECT_NEAR(unitToMm("cmu", "f"), 56.444, 1e-3);
  EXPECT_THROW(unitToMm("furlong", "f"), Error);
}

}  // namespace
}  // namespace ew
