// The skeleton engine's bone-length policy (core/skeleton/bone_choice.h): each source taken
// from what was given, and what a source needs and is not given named in the error.
#include <gtest/gtest.h>

#include <numbers>

#include "core/common/errors.h"
#include "core/common/trial.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/skeleton/bone_choice.h"
#include "core/skeleton/bone_sources.h"
#include "tests/common/error_matchers.h"

namespace ew {
namespace {

// One frame of the mean walker flattened onto a plane 4 m from a 1200 px pinhole: its image
// lengths are its bones' lengths times 0.3.
struct FlatWalker {
  KeypointTrial keypoints;
  JointTrial reference;
};

FlatWalker flatWalker() {
  const Eigen::MatrixXd pose = synthesizeFrames(defaultRealModel().mean, 6.0, 0.0, frameTimes(1, 30.0));
  FlatWalker w;
  w.reference.positionsMm = pose;
  w.keypoints.file = "flat.json";
  w.keypoints.jointsPx.resize(1, 2 * kJointCount);
  for (int j = 0; j < kJointCount; ++j) {
    w.reference.positionsMm(0, 3 * j + 1) = 0.0;
    w.keypoints.jointsPx(0, 2 * j) = 960 + 0.3 * pose(0, 3 * j);
    w.keypoints.jointsPx(0, 2 * j + 1) = 540 - 0.3 * pose(0, 3 * j + 2);
  }
  return w;
}

TEST(BoneChoice, EachSourceFromWhatWasGiven) {
  const FlatWalker w = flatWalker();
  const BoneLengths truth = boneLengthsFromFrames(w.reference.positionsMm, "flat");
  BoneChoice choice;
  // No source named: the reference's.
  const ChosenBones fromReference = chooseBones(choice, w.keypoints, &w.reference, "flat.trc", std::nullopt);
  EXPECT_EQ(fromReference.source, "the reference flat.trc");
  EXPECT_EQ(fromReference.lengths.mm, truth.mm);

  choice.source = BoneSource::Table2;
  choice.statureMm = 1700.0;
  const ChosenBones table2 = chooseBones(choice, w.keypoints, nullptr, "", std::nullopt);
  EXPECT_NEAR(standingChainMm(table2.lengths), kHeadAboveAnklesPerStature * 1700.0, 1e-9);

  choice.source = BoneSource::Eigenwalker;
  const ChosenBones scaled = chooseBones(choice, w.keypoints, nullptr, "", truth);
  EXPECT_NEAR(standingChainMm(scaled.lengths), kHeadAboveAnklesPerStature * 1700.0, 1e-9);
  EXPECT_EQ(scaled.source, "the eigenwalker's fit, scaled to the stature");

  choice.source = BoneSource::Frame;
  choice.frame = 0;
  const int thigh = boneBetween(Joint::RHip, Joint::RKnee);
  choice.referenceBone = "r_hip-r_knee=" + std::to_string(truth.mm[static_cast<std::size_t>(thigh)]);
  const ChosenBones frame = chooseBones(choice, w.keypoints, nullptr, "", std::nullopt);
  for (int b = 0; b < kBoneCount; ++b)
    EXPECT_NEAR(frame.lengths.mm[static_cast<std::size_t>(b)], truth.mm[static_cast<std::size_t>(b)], 1e-3);
}

TEST(BoneChoice, WhatASourceNeedsIsNamed) {
  const FlatWalker w = flatWalker();
  BoneChoice choice;
  EXPECT_TRUE(test::throwsError([&] { chooseBones(choice, w.keypoints, nullptr, "", std::nullopt); },
                                ErrorKind::BadArgument, {"--bones", "--reference FILE"}));
  choice.source = BoneSource::Table2;
  EXPECT_TRUE(test::throwsError([&] { chooseBones(choice, w.keypoints, nullptr, "", std::nullopt); },
                                ErrorKind::BadArgument, {"--stature"}));
  choice.source = BoneSource::Frame;
  choice.names.frame = "the frame field";
  EXPECT_TRUE(test::throwsError([&] { chooseBones(choice, w.keypoints, nullptr, "", std::nullopt); },
                                ErrorKind::BadArgument, {"the frame field"}));
  choice.frame = 5;
  choice.referenceBone = "r_hip-r_knee=400";
  EXPECT_TRUE(test::throwsError([&] { chooseBones(choice, w.keypoints, nullptr, "", std::nullopt); },
                                ErrorKind::BadArgument, {"frame 5"}));
  EXPECT_TRUE(test::throwsError([&] { referenceBoneOf("r_elbow-l_wrist=250", "--reference-bone"); },
                                ErrorKind::BadArgument, {"no bone joins"}));
  EXPECT_TRUE(test::throwsError([&] { parseBoneSource("femur", "--bones"); }, ErrorKind::BadArgument, {"femur"}));
}

}  // namespace
}  // namespace ew
