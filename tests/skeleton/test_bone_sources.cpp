// Bone lengths without a 3D reference (core/skeleton/bone_sources.h): Zou et al.'s Table 2
// scaled to a stature, any lengths scaled to a stature, a Fourier walker's bones, and §4.1's
// reference frame.

#include <gtest/gtest.h>

#include <numbers>

#include "core/common/errors.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/skeleton/bone_sources.h"
#include "tests/common/error_matchers.h"

namespace ew {
namespace {

double length(const BoneLengths& bones, Joint a, Joint b) { return bones.mm[static_cast<std::size_t>(boneBetween(a, b))]; }

TEST(BoneSources, Table2KeepsThePapersProportionsAndTheStature) {
  const BoneLengths b = boneLengthsFromZouTable2(1750, "me");
  EXPECT_NEAR(standingChainMm(b), 0.87 * 1750, 1e-9);
  const double unit = 0.87 * 1750 / 140;  // the chain is 36 + 30 + 54 + 20 units
  EXPECT_NEAR(length(b, Joint::RHip, Joint::RKnee), 30 * unit, 1e-9);
  EXPECT_NEAR(length(b, Joint::LKnee, Joint::LAnkle), 36 * unit, 1e-9);
  EXPECT_NEAR(length(b, Joint::Pelvis, Joint::Sternum), 54 * unit, 1e-9);
  EXPECT_NEAR(length(b, Joint::LElbow, Joint::LWrist), 24 * unit, 1e-9);
  EXPECT_NEAR(length(b, Joint::Head, Joint::Sternum), 20 * unit, 1e-9);
  EXPECT_TRUE(test::throwsError([] { boneLengthsFromZouTable2(17500, "me"); }, ErrorKind::BadArgument,
                                {"me", "stature", "17.5"}));
  EXPECT_TRUE(test::throwsError([] { boneLengthsFromZouTable2(std::nan(""), "me"); }, ErrorKind::BadArgument,
                                {"stature"}));
}

TEST(BoneSources, AWalkersBonesAreItsFramesBonesAndScaleToAStature) {
  const EigenwalkerModel& model = defaultRealModel();
  const double omega = 2 * std::numbers::pi * 0.95;
  const BoneLengths fromWalker = boneLengthsFromWalker(model.mean, omega, "mean");
  // The same walker sampled 4 times as densely: the median moves by far less than a mm.
  const Eigen::VectorXd t = frameTimes(256, 256 * 0.95);
  const BoneLengths dense = boneLengthsFromFrames(synthesizeFrames(model.mean, omega, 0.0, t), "mean");
  for (int i = 0; i < kBoneCount; ++i) {
    EXPECT_GT(fromWalker.mm[static_cast<std::size_t>(i)], 30.0);
    EXPECT_NEAR(fromWalker.mm[static_cast<std::size_t>(i)], dense.mm[static_cast<std::size_t>(i)], 1.0);
  }
  // A population's proportions at a stature: the chain is 0.87 S, the ratios are the walker's.
  const BoneLengths scaled = scaledToStature(fromWalker, 1600, "mean");
  EXPECT_NEAR(standingChainMm(scaled), 0.87 * 1600, 1e-9);
  const double k = 0.87 * 1600 / standingChainMm(fromWalker);
  for (int i = 0; i < kBoneCount; ++i)
    EXPECT_NEAR(scaled.mm[static_cast<std::size_t>(i)], k * fromWalker.mm[static_cast<std::size_t>(i)], 1e-9);
  EXPECT_TRUE(test::throwsError([&] { boneLengthsFromWalker(Eigen::VectorXd::Zero(10), omega, "w"); },
                                ErrorKind::BadArgument, {"w", "225"}));
  EXPECT_TRUE(test::throwsError([&] { boneLengthsFromWalker(model.mean, 0.0, "w"); }, ErrorKind::BadArgument,
                                {"frequency"}));
}

TEST(BoneSources, AReferenceFrameParallelToTheImageGivesEveryBone) {
  // A pose flattened onto a plane at 4 m, through a pinhole of 1200 px: image lengths are
  // the bones' lengths times f / Z, the same factor for every bone.
  const Eigen::VectorXd t = frameTimes(1, 30.0);
  const Eigen::MatrixXd pose = synthesizeFrames(defaultRealModel().mean, 6.0, 0.0, t);
  Eigen::MatrixXd flat = pose;
  Eigen::RowVectorXd px(2 * kJointCount);
  for (int j = 0; j < kJointCount; ++j) {
    flat(0, 3 * j + 1) = 0.0;  // depth along y removed
    px[2 * j] = 960 + 1200 * flat(0, 3 * j) / 4000;
    px[2 * j + 1] = 540 - 1200 * flat(0, 3 * j + 2) / 4000;
  }
  const BoneLengths truth = boneLengthsFromFrames(flat, "flat");
  const int thigh = boneBetween(Joint::RHip, Joint::RKnee);
  const BoneLengths b = boneLengthsFromReferenceFrame(px, thigh, truth.mm[static_cast<std::size_t>(thigh)], "frame 12");
  for (int i = 0; i < kBoneCount; ++i) EXPECT_NEAR(b.mm[static_cast<std::size_t>(i)], truth.mm[static_cast<std::size_t>(i)], 1e-9);

  Eigen::RowVectorXd unseen = px;
  unseen[2 * index(Joint::LWrist)] = std::nan("");
  EXPECT_TRUE(test::throwsError([&] { boneLengthsFromReferenceFrame(unseen, thigh, 400, "frame 12"); },
                                ErrorKind::BadData, {"frame 12", "l_wrist"}));
  Eigen::RowVectorXd collapsed = px;
  collapsed.segment<2>(2 * index(Joint::RKnee)) = collapsed.segment<2>(2 * index(Joint::RHip));
  EXPECT_TRUE(test::throwsError([&] { boneLengthsFromReferenceFrame(collapsed, thigh, 400, "frame 12"); },
                                ErrorKind::BadData, {"no length"}));
  EXPECT_TRUE(test::throwsError([&] { boneLengthsFromReferenceFrame(px, thigh, -1, "frame 12"); },
                                ErrorKind::BadArgument, {"positive"}));
}

}  // namespace
}  // namespace ew
