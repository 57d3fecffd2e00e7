// Synthetic walkers written as our 15-joint CSV and as BVH come back through our own
// loaders (readRawTrial + toJointTrial) as the same 15 joints.
#include <gtest/gtest.h>

#include <fstream>

#include "core/common/errors.h"
#include "core/io/bvh_writer.h"
#include "core/io/joint_csv.h"
#include "core/io/load_trial.h"
#include "core/mapping/joint_mapping.h"
#include "core/synth/population.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

std::vector<SynthWalker> walkers(int count) {
  PopulationOptions o;
  o.count = count;
  o.seed = 99;
  return generatePopulation(o);
}

// BVH axes (X right, Y up, Z backward) back to ours (x right, y forward, z up).
Eigen::MatrixXd fromBvhAxes(const Eigen::MatrixXd& m) {
  Eigen::MatrixXd out(m.rows(), m.cols());
  for (Eigen::Index j = 0; j < m.cols() / 3; ++j) {
    out.col(3 * j) = m.col(3 * j);
    out.col(3 * j + 1) = -m.col(3 * j + 2);
    out.col(3 * j + 2) = m.col(3 * j + 1);
  }
  return out;
}

TEST(SynthRoundTrip, CsvReadsBackToTheSameJoints) {
  const auto dir = test::makeTempDir("synth_csv");
  for (const SynthWalker& w : walkers(3)) {
    const auto file = dir / (w.trialId + ".csv");
    writeJointCsv(file, w.trial.positionsMm, w.trial.rateHz, {"synthetic"});
    const JointTrial back = toJointTrial(readRawTrial(file));
    ASSERT_EQ(back.positionsMm.rows(), w.trial.positionsMm.rows());
    EXPECT_NEAR(back.rateHz, w.trial.rateHz, 1e-9);
    // 10 significant digits: 1e-6 mm for coordinates under 10 m.
    EXPECT_LT((back.positionsMm - w.trial.positionsMm).cwiseAbs().maxCoeff(), 1e-5) << w.id;
  }
  std::filesystem::remove_all(dir);
}

TEST(SynthRoundTrip, BvhReadsBackToTheSameJoints) {
  const auto dir = test::makeTempDir("synth_bvh");
  for (const SynthWalker& w : walkers(3)) {
    const auto file = dir / (w.trialId + ".bvh");
    BvhWriteOptions options;
    options.toesMm = w.toesMm;
    writeBvh(file, w.trial.positionsMm, w.trial.rateHz, options);
    const RawTrial raw = readRawTrial(file);
    EXPECT_EQ(raw.units, "mm") << "unit guessed from the rest-pose hip height";
    const JointTrial back = toJointTrial(raw);
    EXPECT_EQ(back.source, "Mixamo-style BVH");
    for (bool e : back.estimated) EXPECT_FALSE(e);
    ASSERT_EQ(back.positionsMm.rows(), w.trial.positionsMm.rows())
        << "no frame dropped as a T-pose";
    EXPECT_NEAR(back.rateHz, w.trial.rateHz, 1e-6);
    // Exact up to the 6 decimals written (1e-6° over ~1 m chains: ~1e-5 mm per joint).
    const Eigen::MatrixXd error = fromBvhAxes(back.positionsMm) - w.trial.positionsMm;
    EXPECT_LT(error.cwiseAbs().maxCoeff(), 1e-3) << w.id;
  }
  std::filesystem::remove_all(dir);
}

TEST(SynthRoundTrip, BvhWithoutToesStillCarriesTheFifteenJoints) {
  const auto dir = test::makeTempDir("synth_bvh_notoes");
  const SynthWalker w = walkers(1).front();
  writeBvh(dir / "w.bvh", w.trial.positionsMm, w.trial.rateHz);
  LoadOptions mm;
  mm.unitsOverride = "mm";
  const JointTrial back = toJointTrial(readRawTrial(dir / "w.bvh", mm));
  EXPECT_LT((fromBvhAxes(back.positionsMm) - w.trial.positionsMm).cwiseAbs().maxCoeff(), 1e-3);
  std::filesystem::remove_all(dir);
}

TEST(SynthRoundTrip, BvhHierarchyUsesMixamoNamesAndZxyChannels) {
  const SynthWalker w = walkers(1).front();
  const std::string text = formatBvh(w.trial.positionsMm.topRows(3), w.trial.rateHz);
  for (const char* name :
       {"ROOT Hips", "JOINT LeftUpLeg", "JOINT LeftLeg", "JOINT LeftFoot", "JOINT Neck",
        "JOINT Head", "JOINT RightArm", "JOINT RightForeArm", "JOINT RightHand"}) {
    EXPECT_NE(text.find(name), std::string::npos) << name;
  }
  EXPECT_NE(text.find("CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation"),
            std::string::npos);
  EXPECT_NE(text.find("Frames: 3\n"), std::string::npos);
}

TEST(SynthRoundTrip, BvhWriterRejectsBadInput) {
  EXPECT_THROW(formatBvh(Eigen::MatrixXd::Zero(3, 44), 120.0), Error);
  EXPECT_THROW(formatBvh(Eigen::MatrixXd::Zero(0, 45), 120.0), Error);
  const SynthWalker w = walkers(1).front();
  EXPECT_THROW(formatBvh(w.trial.positionsMm, 0.0), Error);
  Eigen::MatrixXd gap = w.trial.positionsMm;
  gap(2, 5) = std::nan("");
  EXPECT_THROW(formatBvh(gap, 120.0), Error);
  BvhWriteOptions wrongToes;
  wrongToes.toesMm = Eigen::MatrixXd::Zero(2, 6);
  EXPECT_THROW(formatBvh(w.trial.positionsMm, 120.0, wrongToes), Error);
}

}  // namespace
}  // namespace ew
