// Skeleton joints (BVH, ASF/AMC) -> 15 joints: synthetic skeletons for the naming rules,
// the CMU files for anatomy (segment lengths, their constancy, trunk order, and the
// pelvis-sternum distance agreeing between the BVH and ASF conventions).

#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "core/common/errors.h"
#include "core/io/asf_amc_reader.h"
#include "core/io/bvh_reader.h"
#include "core/mapping/joint_mapping.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

// [SECTION] Helpers

// One frame of named points (positions made up, distinct per point).
RawTrial syntheticTrial(const std::vector<std::string>& labels) {
  RawTrial raw;
  raw.file = "synthetic.bvh";
  raw.format = "BVH";
  raw.kind = PointKind::SkeletonJoints;
  raw.rateHz = 100.0;
  raw.labels = labels;
  raw.positionsMm.resize(2, 3 * static_cast<Eigen::Index>(labels.size()));
  for (Eigen::Index c = 0; c < raw.positionsMm.cols(); ++c) {
    raw.positionsMm(0, c) = static_cast<double>(c);
    raw.positionsMm(1, c) = static_cast<double>(2 * c);
  }
  return raw;
}

Eigen::Vector3d rawAt(const RawTrial& raw, const std::string& label, int frame) {
  for (size_t k = 0; k < raw.labels.size(); ++k) {
    if (raw.labels[k] == label) return raw.positionsMm.block<1, 3>(frame, 3 * static_cast<int>(k)).transpose();
  }
  ADD_FAILURE() << "no " << label;
  return Eigen::Vector3d::Zero();
}

const std::vector<std::string> kMixamo = {
    "mixamorig:Hips",         "mixamorig:Spine",        "mixamorig:Spine1",
    "mixamorig:Spine2",       "mixamorig:Neck",         "mixamorig:Head",
    "mixamorig:HeadTop_End",  "mixamorig:LeftShoulder", "mixamorig:LeftArm",
    "mixamorig:LeftForeArm",  "mixamorig:LeftHand",     "mixamorig:RightShoulder",
    "mixamorig:RightArm",     "mixamorig:RightForeArm", "mixamorig:RightHand",
    "mixamorig:LeftUpLeg",    "mixamorig:LeftLeg",      "mixamorig:LeftFoot",
    "mixamorig:RightUpLeg",   "mixamorig:RightLeg",     "mixamorig:RightFoot"};

struct Segments {
  double thigh, shank, upperArm, forearm, hipWidth, pelvisSternum, legLength;
  double worstCv;  // largest coefficient of variation over frames of the segments
  double headAboveSternumShare, sternumAbovePelvisShare;  // frames where y order holds
};

Segments measure(const JointTrial& t) {
  const std::vector<std::pair<Joint, Joint>> pairs = {
      {Joint::LHip, Joint::LKnee},     {Joint::RHip, Joint::RKnee},
      {Joint::LKnee, Joint::LAnkle},   {Joint::RKnee, Joint::RAnkle},
      {Joint::LShoulder, Joint::LElbow}, {Joint::RShoulder, Joint::RElbow},
      {Joint::LElbow, Joint::LWrist},  {Joint::RElbow, Joint::RWrist},
      {Joint::LHip, Joint::RHip},      {Joint::Pelvis, Joint::Sternum}};
  std::vector<double> mean(pairs.size());
  double worstCv = 0.0;
  for (size_t p = 0; p < pairs.size(); ++p) {
    Eigen::VectorXd len(t.frameCount());
    for (int f = 0; f < t.frameCount(); ++f) {
      len[f] = (jointAt(t.positionsMm, f, pairs[p].first) - jointAt(t.positionsMm, f, pairs[p].second)).norm();
    }
    mean[p] = len.mean();
    const double sd = std::sqrt((len.array() - mean[p]).square().mean());
    worstCv = std::max(worstCv, sd / mean[p]);
  }
  int headUp = 0, sternumUp = 0;
  for (int f = 0; f < t.frameCount(); ++f) {
    const double yHead = jointAt(t.positionsMm, f, Joint::Head).y();
    const double ySternum = jointAt(t.positionsMm, f, Joint::Sternum).y();
    const double yPelvis = jointAt(t.positionsMm, f, Joint::Pelvis).y();
    headUp += yHead > ySternum ? 1 : 0;
    sternumUp += ySternum > yPelvis ? 1 : 0;
  }
  const double n = t.frameCount();
  return {0.5 * (mean[0] + mean[1]), 0.5 * (mean[2] + mean[3]), 0.5 * (mean[4] + mean[5]),
          0.5 * (mean[6] + mean[7]), mean[8],  mean[9], 0.5 * (mean[0] + mean[1] + mean[2] + mean[3]),
          worstCv, headUp / n, sternumUp / n};
}

void expectHumanAnatomy(const Segments& s) {
  EXPECT_GT(s.thigh, 330);
  EXPECT_LT(s.thigh, 520);
  EXPECT_GT(s.shank, 330);
  EXPECT_LT(s.shank, 520);
  EXPECT_GT(s.upperArm, 220);
  EXPECT_LT(s.upperArm, 380);
  EXPECT_GT(s.forearm, 120);  // CMU subject 05's forearm is 138 mm
  EXPECT_LT(s.forearm, 320);
  EXPECT_GT(s.hipWidth, 140);
  EXPECT_LT(s.hipWidth, 260);
  EXPECT_GT(s.pelvisSternum, 450);
  EXPECT_LT(s.pelvisSternum, 650);
  EXPECT_LT(s.worstCv, 0.05);
  EXPECT_EQ(s.headAboveSternumShare, 1.0);
  EXPECT_EQ(s.sternumAbovePelvisShare, 1.0);
}

std::vector<std::string> manifestCmuFiles() {
  std::vector<std::string> files;
  std::ifstream in(test::sharedDataDir() / "walkers.csv");
  std::string line;
  while (std::getline(in, line)) {
    const auto rel = line.substr(0, line.find(','));
    if (rel.ends_with(".bvh") || rel.ends_with(".amc")) files.push_back(rel);
  }
  return files;
}

// [SECTION] Naming rules on synthetic skeletons

TEST(SkeletonMap, MixamoNamesWithNamespace) {
  RawTrial raw = syntheticTrial(kMixamo);
  JointTrial t = mapSkeletonJoints(raw);
  EXPECT_EQ(t.source, "Mixamo-style BVH");
  EXPECT_EQ(t.frameCount(), 2);
  EXPECT_TRUE(t.positionsMm.allFinite());
  for (int f = 0; f < 2; ++f) {
    EXPECT_EQ(jointAt(t.positionsMm, f, Joint::LKnee), rawAt(raw, "mixamorig:LeftLeg", f));
    EXPECT_EQ(jointAt(t.positionsMm, f, Joint::RWrist), rawAt(raw, "mixamorig:RightHand", f));
    EXPECT_EQ(jointAt(t.positionsMm, f, Joint::Sternum), rawAt(raw, "mixamorig:Neck", f));
    EXPECT_TRUE(jointAt(t.positionsMm, f, Joint::Pelvis)
                    .isApprox(0.5 * (rawAt(raw, "mixamorig:LeftUpLeg", f) +
                                     rawAt(raw, "mixamorig:RightUpLeg", f))));
    EXPECT_TRUE(jointAt(t.positionsMm, f, Joint::Head)
                    .isApprox(0.5 * (rawAt(raw, "mixamorig:Head", f) +
                                     rawAt(raw, "mixamorig:HeadTop_End", f))));
  }
  for (bool e : t.estimated) EXPECT_FALSE(e);
}

TEST(SkeletonMap, MissingHeadIsEstimatedAndFlagged) {
  auto labels = kMixamo;
  std::erase_if(labels, [](const std::string& l) { return l.find("Head") != std::string::npos; });
  RawTrial raw = syntheticTrial(labels);
  JointTrial t = mapSkeletonJoints(raw);
  EXPECT_TRUE(t.estimated[static_cast<size_t>(index(Joint::Head))]);
  EXPECT_TRUE(jointAt(t.positionsMm, 1, Joint::Head)
                  .isApprox(estimateHead(jointAt(t.positionsMm, 1, Joint::Pelvis),
                                         jointAt(t.positionsMm, 1, Joint::Sternum))));
  EXPECT_FALSE(t.warnings.empty());
}

TEST(SkeletonMap, CmuBvhWithoutTheThoraxDefectIsNotShifted) {
  // Neck1 present (CMU naming) but Neck is not on Spine1: joints map as they are.
  RawTrial raw = syntheticTrial({"Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "RightUpLeg",
                                 "RightLeg", "RightFoot", "Spine", "Spine1", "Neck", "Neck1",
                                 "Head", "Head_End", "LeftArm", "LeftForeArm", "LeftHand",
                                 "RightArm", "RightForeArm", "RightHand"});
  JointTrial t = mapSkeletonJoints(raw);
  EXPECT_EQ(t.source, "CMU BVH (Hahne conversion)");
  EXPECT_EQ(jointAt(t.positionsMm, 1, Joint::Sternum), rawAt(raw, "Neck1", 1));
  EXPECT_EQ(jointAt(t.positionsMm, 1, Joint::LShoulder), rawAt(raw, "LeftArm", 1));
}

TEST(SkeletonMap, UnknownSkeletonListsFoundAndNeededNames) {
  RawTrial raw = syntheticTrial({"pelvis", "femur_l", "tibia_l"});
  try {
    mapSkeletonJoints(raw);
    FAIL() << "unknown skeleton accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::UnknownMarkerSet);
    const std::string m = e.what();
    EXPECT_NE(m.find("femur_l"), std::string::npos) << m;
    EXPECT_NE(m.find("leftupleg"), std::string::npos) << m;
    EXPECT_NE(m.find("lfemur"), std::string::npos) << m;
  }
}

// [SECTION] CMU anatomy

TEST(SkeletonMapCmu, EveryManifestTrialHasHumanAnatomy) {
  EW_REQUIRE_SHARED_DATA();
  const auto files = manifestCmuFiles();
  ASSERT_EQ(files.size(), 12u);
  for (const auto& rel : files) {
    SCOPED_TRACE(rel);
    const auto path = test::sharedDataDir() / rel;
    RawTrial raw = rel.ends_with(".bvh") ? readBvh(path) : readAsfAmc(path);
    JointTrial t = toJointTrial(raw);
    EXPECT_TRUE(t.positionsMm.allFinite());
    for (bool e : t.estimated) EXPECT_FALSE(e);
    const Segments s = measure(t);
    expectHumanAnatomy(s);
    std::cout << "[ measure  ] " << path.stem().string() << " (" << t.source
              << "): thigh " << s.thigh << ", shank " << s.shank << ", upper arm " << s.upperArm
              << ", forearm " << s.forearm << ", hip width " << s.hipWidth
              << ", pelvis-sternum " << s.pelvisSternum << " (" << s.pelvisSternum / s.legLength
              << " of leg), worst CV " << s.worstCv << "\n";
  }
}

TEST(SkeletonMapCmu, BvhAndAsfConventionsGiveComparableTrunks) {
  // No CMU subject is here in both formats, so compare pelvis-sternum relative to the
  // subject's leg (thigh + shank): subject 35 (ASF) against each BVH subject.
  EW_REQUIRE_SHARED_DATA();
  const auto dir = test::sharedDataDir();
  const Segments asf = measure(toJointTrial(readAsfAmc(dir / "cmu-mocap-asfamc/35/35_01.amc")));
  const double asfRatio = asf.pelvisSternum / asf.legLength;
  for (const char* rel : {"cmu-mocap-bvh/02/02_01.bvh", "cmu-mocap-bvh/05/05_01.bvh",
                          "cmu-mocap-bvh/06/06_01.bvh", "cmu-mocap-bvh/07/07_01.bvh",
                          "cmu-mocap-bvh/08/08_01.bvh"}) {
    SCOPED_TRACE(rel);
    const Segments bvh = measure(toJointTrial(readBvh(dir / rel)));
    const double bvhRatio = bvh.pelvisSternum / bvh.legLength;
    EXPECT_NEAR(bvhRatio / asfRatio, 1.0, 0.12);
    EXPECT_NEAR(bvh.pelvisSternum, asf.pelvisSternum, 40.0);
  }
}

}  // namespace
}  // namespace ew
