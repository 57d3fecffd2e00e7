#include <gtest/gtest.h>

#include "core/common/errors.h"
#include "core/common/skeleton.h"

namespace ew {
namespace {

TEST(Skeleton, NamesRoundTripInSpecOrder) {
  EXPECT_EQ(jointName(Joint::Head), "head");
  EXPECT_EQ(jointName(Joint::LAnkle), "l_ankle");
  for (int i = 0; i < kJointCount; ++i) {
    auto j = jointFromName(kJointNames[static_cast<size_t>(i)]);
    ASSERT_TRUE(j.has_value());
    EXPECT_EQ(index(*j), i);
  }
  EXPECT_FALSE(jointFromName("nose").has_value());
}

TEST(Skeleton, MirrorIsAnInvolutionThatSwapsSides) {
  for (int i = 0; i < kJointCount; ++i) {
    auto j = static_cast<Joint>(i);
    EXPECT_EQ(mirrorJoint(mirrorJoint(j)), j);
  }
  EXPECT_EQ(mirrorJoint(Joint::RKnee), Joint::LKnee);
  EXPECT_EQ(mirrorJoint(Joint::Pelvis), Joint::Pelvis);
}

TEST(Skeleton, BonesConnectEveryJoint) {
  std::array<int, kJointCount> degree{};
  for (auto [a, b] : kBones) {
    ++degree[static_cast<size_t>(index(a))];
    ++degree[static_cast<size_t>(index(b))];
  }
  for (int d : degree) EXPECT_GE(d, 1);
}

TEST(Errors, MessageNamesFilePositionAndProblem) {
  try {
    throwMalformed("walk.c3d", "byte 512", "parameter block count 300 exceeds file size");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Malformed);
    EXPECT_STREQ(e.what(), "walk.c3d: byte 512: parameter block count 300 exceeds file size");
  }
}

TEST(Errors, ListsForMessagesSayHowManyWereLeftOut) {
  const std::vector<std::string> names{"LASI", "RASI", "LPSI", "RPSI"};
  EXPECT_EQ(listForMessage(names, 10), "LASI, RASI, LPSI, RPSI");
  EXPECT_EQ(listForMessage(names, 2), "LASI, RASI, … (2 more)");
  EXPECT_EQ(listForMessage(names, 3, " "), "LASI RASI LPSI … (1 more)");
  EXPECT_EQ(listForMessage({}, 3), "");
}

}  // namespace
}  // namespace ew
