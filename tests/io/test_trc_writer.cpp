// TRC export (core/io/trc_writer.h): the header lines of the published layout, and a
// synthetic walker written, read back by the project's own TRC reader and prepared again.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/common/errors.h"
#include "core/gait/dataset.h"
#include "core/io/load_trial.h"
#include "core/io/trc_reader.h"
#include "core/io/trc_writer.h"
#include "core/synth/population.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> cellsOf(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, '\t')) cells.push_back(cell);
  if (!line.empty() && line.back() == '\t') cells.push_back("");
  return cells;
}

SynthWalker oneWalker() {
  PopulationOptions o;
  o.count = 1;
  o.simulation.rateHz = 100.0;
  o.simulation.cycles = 3.0;
  return generatePopulation(o).front();
}

TEST(TrcWriter, TheHeaderFollowsThePublishedLayout) {
  const auto dir = test::makeTempDir("trc_header");
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(3, kDims3);
  writeTrc(dir / "walk.trc", m, 60.0, "m");
  const auto lines = linesOf(test::readTextFile(dir / "walk.trc"));
  ASSERT_EQ(lines.size(), 6u + 3u);
  EXPECT_EQ(lines[0], "PathFileType\t4\t(X/Y/Z)\twalk.trc");
  EXPECT_EQ(lines[1], "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames");
  const auto values = cellsOf(lines[2]);
  ASSERT_EQ(values.size(), 8u);
  EXPECT_DOUBLE_EQ(std::stod(values[0]), 60.0);
  EXPECT_EQ(values[2], "3");
  EXPECT_EQ(values[3], "15");
  EXPECT_EQ(values[4], "m");
  const auto names = cellsOf(lines[3]);
  ASSERT_EQ(names.size(), 2u + 3u * kJointCount);
  EXPECT_EQ(names[0], "Frame#");
  EXPECT_EQ(names[1], "Time");
  for (int j = 0; j < kJointCount; ++j) {
    EXPECT_EQ(names[2 + 3 * j], kJointNames[static_cast<size_t>(j)]);
    EXPECT_EQ(names[3 + 3 * j], "");
  }
  const auto axes = cellsOf(lines[4]);
  ASSERT_EQ(axes.size(), 2u + 3u * kJointCount);
  EXPECT_EQ(axes[2], "X1");
  EXPECT_EQ(axes.back(), "Z15");
  EXPECT_EQ(lines[5], "");
  const auto first = cellsOf(lines[6]);
  ASSERT_EQ(first.size(), 2u + 3u * kJointCount);
  EXPECT_EQ(first[0], "1");
  EXPECT_DOUBLE_EQ(std::stod(first[1]), 0.0);
  EXPECT_NEAR(std::stod(cellsOf(lines[7])[1]), 1.0 / 60.0, 1e-6);
}

TEST(TrcWriter, AWalkerReadsBackThroughTheProjectsTrcReader) {
  const auto dir = test::makeTempDir("trc_round_trip");
  const SynthWalker w = oneWalker();
  Eigen::MatrixXd m = w.trial.positionsMm;
  m.block<1, 3>(5, 3 * index(Joint::LWrist)).setConstant(NAN);  // a missing sample stays missing
  writeTrc(dir / "walk.trc", m, 100.0);
  const RawTrial raw = readTrc(dir / "walk.trc");
  EXPECT_EQ(raw.kind, PointKind::CanonicalJoints);
  EXPECT_DOUBLE_EQ(raw.rateHz, 100.0);
  EXPECT_EQ(raw.units, "mm");
  ASSERT_EQ(raw.positionsMm.rows(), m.rows());
  double worst = 0.0;
  for (Eigen::Index r = 0; r < m.rows(); ++r) {
    for (int j = 0; j < kJointCount; ++j) {
      const Eigen::Vector3d back = openSimToCanonical(raw.positionsMm.block<1, 3>(r, 3 * j).transpose());
      const Eigen::Vector3d want = m.block<1, 3>(r, 3 * j).transpose();
      if (!want.allFinite()) {
        EXPECT_FALSE(back.allFinite()) << "frame " << r;
        continue;
      }
      worst = std::max(worst, (back - want).cwiseAbs().maxCoeff());
    }
  }
  EXPECT_LT(worst, 1e-5);  // five decimals of a millimetre
  // And the file is a walker again: Y up is found from the body, the same speed comes out.
  const WalkingTrial again = loadWalkingTrial(dir / "walk.trc");
  EXPECT_NEAR(again.speedMps, w.attributes.at("speed_mps"), 0.05 * w.attributes.at("speed_mps"));
}

TEST(TrcWriter, MetresAreWrittenInMetres) {
  const auto dir = test::makeTempDir("trc_metres");
  const SynthWalker w = oneWalker();
  writeTrc(dir / "walk.trc", w.trial.positionsMm, 100.0, "m");
  const RawTrial raw = readTrc(dir / "walk.trc");
  EXPECT_EQ(raw.units, "m");
  const Eigen::Vector3d head = openSimToCanonical(raw.positionsMm.block<1, 3>(0, 0).transpose());
  EXPECT_LT((head - w.trial.positionsMm.block<1, 3>(0, 0).transpose()).norm(), 1e-4);
}

TEST(TrcWriter, BadArgumentsAreRefusedAndNothingIsWritten) {
  const auto dir = test::makeTempDir("trc_bad");
  const Eigen::MatrixXd m = Eigen::MatrixXd::Zero(2, kDims3);
  EXPECT_THROW(writeTrc(dir / "a.trc", Eigen::MatrixXd::Zero(2, 44), 100.0), Error);
  EXPECT_THROW(writeTrc(dir / "b.trc", m, 0.0), Error);
  EXPECT_THROW(writeTrc(dir / "c.trc", m, 100.0, "cm"), Error);
  EXPECT_TRUE(std::filesystem::is_empty(dir));
}

TEST(TrcWriter, TheExtensionChoosesTheFormat) {
  const auto dir = test::makeTempDir("trc_extension");
  const Eigen::MatrixXd m = Eigen::MatrixXd::Zero(2, kDims3);
  writeJointTrajectories(dir / "w.trc", m, 50.0, {"a comment"});
  writeJointTrajectories(dir / "w.csv", m, 50.0, {"a comment"});
  EXPECT_EQ(test::readTextFile(dir / "w.trc").rfind("PathFileType", 0), 0u);
  EXPECT_EQ(test::readTextFile(dir / "w.csv").rfind("# a comment", 0), 0u);
}

}  // namespace
}  // namespace ew
