// Every trial of ../shared/data/walkers.csv must load to plausible human anatomy in the
// canonical frame: this is what the model will be built from.
#include <gtest/gtest.h>

#include <cmath>

#include "core/gait/dataset.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

struct SegmentRange {
  Joint a, b;
  double minMm, maxMm;
  const char* name;
};

// Adult ranges with margin (Winter 2009 segment proportions for 1.5-2.0 m statures;
// joint-centre definitions differ between sources, hence the width of each range).
constexpr SegmentRange kSegments[] = {
    {Joint::RHip, Joint::RKnee, 300, 560, "right thigh"},
    {Joint::LHip, Joint::LKnee, 300, 560, "left thigh"},
    {Joint::RKnee, Joint::RAnkle, 300, 520, "right shank"},
    {Joint::LKnee, Joint::LAnkle, 300, 520, "left shank"},
    {Joint::RShoulder, Joint::RElbow, 200, 400, "right upper arm"},
    {Joint::LShoulder, Joint::LElbow, 200, 400, "left upper arm"},
    // CMU's skeletons end the forearm at the end of the radius bone, short of the wrist
    // markers: 139 mm for CMU subject 05's calibration, 180-203 mm for the others.
    {Joint::RElbow, Joint::RWrist, 120, 330, "right forearm"},
    {Joint::LElbow, Joint::LWrist, 120, 330, "left forearm"},
    {Joint::RHip, Joint::LHip, 120, 300, "hip width"},
    {Joint::RShoulder, Joint::LShoulder, 220, 460, "shoulder width"},
    {Joint::Pelvis, Joint::Sternum, 250, 650, "trunk"},
};

Eigen::VectorXd segmentLengths(const Eigen::MatrixXd& m, Joint a, Joint b) {
  return (m.middleCols<3>(3 * index(a)) - m.middleCols<3>(3 * index(b))).rowwise().norm();
}

double meanOf(const Eigen::MatrixXd& m, Joint j, int axis) { return m.col(3 * index(j) + axis).mean(); }

class WalkersAnatomy : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (test::sharedDataDir().empty()) return;
    dataset_ = new Dataset(loadDataset({test::sharedDataDir() / "walkers.csv"}));
  }
  static void TearDownTestSuite() { delete dataset_; }
  static Dataset* dataset_;
};
Dataset* WalkersAnatomy::dataset_ = nullptr;

TEST_F(WalkersAnatomy, AllThirtyTrialsOfTwentyFourSubjectsLoad) {
  EW_REQUIRE_SHARED_DATA();
  EXPECT_EQ(dataset_->trials.size(), 30u);
  EXPECT_EQ(dataset_->subjects().size(), 24u);
}

TEST_F(WalkersAnatomy, SegmentLengthsAreHumanAndSteady) {
  EW_REQUIRE_SHARED_DATA();
  for (const auto& t : dataset_->trials) {
    const Eigen::MatrixXd& m = t.trial.joints.positionsMm;
    for (const auto& s : kSegments) {
      const Eigen::VectorXd len = segmentLengths(m, s.a, s.b);
      const double mean = len.mean();
      const double sd = std::sqrt((len.array() - mean).square().mean());
      EXPECT_GE(mean, s.minMm) << t.info.file << " " << s.name;
      EXPECT_LE(mean, s.maxMm) << t.info.file << " " << s.name;
      EXPECT_LT(sd / mean, 0.05) << t.info.file << " " << s.name << " varies (CV)";
    }
  }
}

TEST_F(WalkersAnatomy, HeadAboveSternumAbovePelvisAndRightOnPlusX) {
  EW_REQUIRE_SHARED_DATA();
  for (const auto& t : dataset_->trials) {
    const Eigen::MatrixXd& m = t.trial.joints.positionsMm;
    EXPECT_GT(meanOf(m, Joint::Head, 2), meanOf(m, Joint::Sternum, 2)) << t.info.file;
    EXPECT_GT(meanOf(m, Joint::Sternum, 2), meanOf(m, Joint::Pelvis, 2)) << t.info.file;
    for (Joint r : {Joint::RShoulder, Joint::RElbow, Joint::RWrist, Joint::RHip, Joint::RKnee, Joint::RAnkle}) {
      EXPECT_GT(meanOf(m, r, 0), 0.0) << t.info.file << " " << jointName(r);
      EXPECT_LT(meanOf(m, mirrorJoint(r), 0), 0.0) << t.info.file << " " << jointName(mirrorJoint(r));
    }
  }
}

TEST_F(WalkersAnatomy, StrideFrequencySpeedAndCyclesArePlausible) {
  EW_REQUIRE_SHARED_DATA();
  for (const auto& t : dataset_->trials) {
    EXPECT_GE(t.trial.cycles.strideHz, 0.6) << t.info.file;
    EXPECT_LE(t.trial.cycles.strideHz, 1.4) << t.info.file;
    EXPECT_GE(t.trial.cycles.cycleCount, 1.0) << t.info.file;
    EXPECT_GT(t.trial.speedMps, 0.5) << t.info.file;
    EXPECT_LT(t.trial.speedMps, 2.0) << t.info.file;
  }
}

TEST_F(WalkersAnatomy, ManifestColumnsBecomeTrialInfo) {
  EW_REQUIRE_SHARED_DATA();
  const auto& first = dataset_->trials.front().info;
  EXPECT_EQ(first.subject, "SM2014001");
  EXPECT_EQ(first.source, "schreiber-moissenet-2019");
  EXPECT_EQ(first.condition, "spontaneous");
}

}  // namespace
}  // namespace ew
