// BVH reader: hand-written fixtures with analytic answers, then every CMU BVH trial of
// the manifest.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "core/common/errors.h"
#include "core/io/bvh_reader.h"
#include "core/io/load_trial.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

// [SECTION] Helpers

Eigen::Vector3d pointAt(const RawTrial& t, const std::string& label, int frame) {
  for (size_t k = 0; k < t.labels.size(); ++k) {
    if (t.labels[k] == label) return t.positionsMm.block<1, 3>(frame, 3 * static_cast<int>(k)).transpose();
  }
  ADD_FAILURE() << "no point " << label;
  return Eigen::Vector3d::Constant(std::nan(""));
}

std::string withCrlf(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

LoadOptions inMm() {
  LoadOptions o;
  o.unitsOverride = "mm";
  return o;
}

void expectNear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol = 1e-9) {
  EXPECT_LT((a - b).norm(), tol) << "got " << a.transpose() << ", want " << b.transpose();
}

// A root with 6 channels, a 3-channel arm whose rotation order is a parameter, and an
// End Site one unit along +x from the arm. Tabs, trailing spaces, a blank line.
std::string armFixture(const std::string& order, const std::string& values) {
  return "HIERARCHY\n"
         "ROOT Hips\n"
         "{\n"
         "\tOFFSET 0 0 0\n"
         "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation \n"
         "\tJOINT Arm\n"
         "\t{\n"
         "\t\tOFFSET 0 10 0\n"
         "\t\tCHANNELS 3 " + order + "\n"
         "\t\tEnd Site\n"
         "\t\t{\n"
         "\t\t\tOFFSET 1 0 0\n"
         "\t\t}\n"
         "\t}\n"
         "}\n"
         "MOTION\n"
         "Frames: 1\n"
         "Frame Time: 0.01\n"
         "\n"
         "1 2 3 0 0 0 " + values + "  \n";
}

// [SECTION] Fixtures with analytic positions

TEST(Bvh, RotationChannelsComposeInListedOrderXyz) {
  // R = Rx(90)·Ry(90): Ry takes +x to -z, Rx takes -z to +y.
  RawTrial t = parseBvh(armFixture("Xrotation Yrotation Zrotation", "90 90 0"), "xyz.bvh", inMm());
  ASSERT_EQ(t.frameCount(), 1);
  EXPECT_EQ(t.labels, (std::vector<std::string>{"Hips", "Arm", "Arm_End"}));
  expectNear(pointAt(t, "Hips", 0), {1, 2, 3});
  expectNear(pointAt(t, "Arm", 0), {1, 12, 3});
  expectNear(pointAt(t, "Arm_End", 0), {1, 13, 3});
}

TEST(Bvh, RotationChannelsComposeInListedOrderZyx) {
  // Same angles, listed Z Y X: R = Rz(0)·Ry(90)·Rx(90); Rx keeps +x, Ry takes it to -z.
  RawTrial t = parseBvh(armFixture("Zrotation Yrotation Xrotation", "0 90 90"), "zyx.bvh", inMm());
  expectNear(pointAt(t, "Arm_End", 0), {1, 12, 2});
}

TEST(Bvh, ParentRotationCarriesChildren) {
  // Root Zrotation 90 turns the arm's +y offset to -x and the End Site's +x to +y.
  std::string text = armFixture("Zrotation Yrotation Xrotation", "0 0 0");
  text.replace(text.find("1 2 3 0 0 0"), 11, "0 0 0 90 0 0");
  RawTrial t = parseBvh(text, "root.bvh", inMm());
  expectNear(pointAt(t, "Arm", 0), {-10, 0, 0});
  expectNear(pointAt(t, "Arm_End", 0), {-10, 1, 0});
}

TEST(Bvh, CrlfAndLfGiveTheSameTrial) {
  const std::string lf = armFixture("Xrotation Yrotation Zrotation", "30 -20 10");
  RawTrial a = parseBvh(lf, "lf.bvh", inMm());
  RawTrial b = parseBvh(withCrlf(lf), "crlf.bvh", inMm());
  EXPECT_EQ(a.labels, b.labels);
  EXPECT_TRUE(a.positionsMm.isApprox(b.positionsMm));
}

TEST(Bvh, PositionChannelsOnANonRootJointReplaceItsOffset) {
  const std::string text =
      "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition "
      "Xrotation Yrotation Zrotation\n JOINT Spine\n {\n  OFFSET 0 5 0\n"
      "  CHANNELS 6 Zrotation Xposition Yposition Zposition Yrotation Xrotation\n"
      "  End Site\n  {\n   OFFSET 0 2 0\n  }\n }\n}\n"
      "MOTION\nFrames: 2\nFrame Time: 0.5\n"
      "0 0 0 0 0 0  0 0 5 0 0 0\n"
      "0 0 0 0 0 0  90 1 7 0 0 0\n";
  RawTrial t = parseBvh(text, "six.bvh", inMm());
  EXPECT_DOUBLE_EQ(t.rateHz, 2.0);
  expectNear(pointAt(t, "Spine", 0), {0, 5, 0});
  expectNear(pointAt(t, "Spine_End", 0), {0, 7, 0});
  expectNear(pointAt(t, "Spine", 1), {1, 7, 0});
  expectNear(pointAt(t, "Spine_End", 1), {-1, 7, 0});  // Zrotation 90: +y -> -x
}

TEST(Bvh, NamesWithSpacesAndBracesOnTheNameLine) {
  const std::string text =
      "HIERARCHY\nROOT Root Node {\n OFFSET 0 0 0\n CHANNELS 3 Xposition Yposition Zposition\n"
      " End Site {\n  OFFSET 0 1 0\n }\n}\nMOTION\nFrames: 1\nFrame Time: 0.1\n0 0 0\n";
  RawTrial t = parseBvh(text, "names.bvh", inMm());
  EXPECT_EQ(t.labels, (std::vector<std::string>{"Root Node", "Root Node_End"}));
}

TEST(Bvh, FormatFieldsAndUnitOverride) {
  RawTrial t = parseBvh(armFixture("Xrotation Yrotation Zrotation", "0 0 0"), "f.bvh", [] {
    LoadOptions o;
    o.unitsOverride = "cm";
    return o;
  }());
  EXPECT_EQ(t.format, "BVH");
  EXPECT_EQ(t.kind, PointKind::SkeletonJoints);
  ASSERT_TRUE(t.upAxis.has_value());
  EXPECT_EQ(*t.upAxis, (SignedAxis{1, 1}));
  EXPECT_DOUBLE_EQ(t.rateHz, 100.0);
  EXPECT_EQ(t.units, "cm");
  expectNear(pointAt(t, "Arm", 0), {10, 120, 30});
}

TEST(Bvh, RateOverrideWins) {
  LoadOptions o = inMm();
  o.rateHzOverride = 60.0;
  EXPECT_DOUBLE_EQ(parseBvh(armFixture("Xrotation Yrotation Zrotation", "0 0 0"), "r.bvh", o).rateHz,
                   60.0);
}

TEST(Bvh, SeveralRootsAreUnsupportedNamingFileAndLine) {
  const std::string one =
      "ROOT A\n{\n OFFSET 0 0 0\n CHANNELS 3 Xposition Yposition Zposition\n"
      " End Site\n {\n  OFFSET 0 1 0\n }\n}\n";
  const std::string text = "HIERARCHY\n" + one + one + "MOTION\nFrames: 1\nFrame Time: 0.1\n0 0 0 0 0 0\n";
  try {
    parseBvh(text, "two_roots.bvh");
    FAIL() << "two roots accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Unsupported);
    EXPECT_EQ(e.file(), "two_roots.bvh");
    EXPECT_EQ(e.position(), "line 11");
  }
}

TEST(Bvh, ShortAndLongRowsNameTheirLine) {
  std::string text = armFixture("Xrotation Yrotation Zrotation", "0 0 0");
  for (const char* row : {"1 2 3 0 0 0 0 0", "1 2 3 0 0 0 0 0 0 0"}) {
    std::string bad = text;
    bad.replace(bad.find("1 2 3 0 0 0 0 0 0"), 17, row);
    try {
      parseBvh(bad, "row.bvh");
      FAIL() << "row accepted: " << row;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::Malformed);
      EXPECT_EQ(e.position(), "line 20");
    }
  }
}

// [SECTION] Units and the T-pose frame

TEST(Bvh, UnitGuessFromHipHeight) {
  EXPECT_EQ(guessBvhLengthUnit(0.92).unit, "m");
  EXPECT_EQ(guessBvhLengthUnit(16.0).unit, "cmu");
  EXPECT_EQ(guessBvhLengthUnit(95.0).unit, "cm");
  EXPECT_EQ(guessBvhLengthUnit(930.0).unit, "mm");
  EXPECT_TRUE(guessBvhLengthUnit(16.0).plausible);
  EXPECT_FALSE(guessBvhLengthUnit(5.0).plausible);
}

// Legs hanging `hip` units below the root: the rest-pose hip height.
std::string legFixture(double hip, const std::string& rows, int frames) {
  std::ostringstream s;
  s << "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition Yposition Zposition "
       "Zrotation Yrotation Xrotation\n JOINT Leg\n {\n  OFFSET 0 "
    << -hip << " 0\n  CHANNELS 3 Zrotation Yrotation Xrotation\n  End Site\n  {\n   OFFSET 0 "
               "0 1\n  }\n }\n}\nMOTION\nFrames: "
    << frames << "\nFrame Time: 0.0083333\n"
    << rows;
  return s.str();
}

TEST(Bvh, AssumedUnitIsReportedAndApplied) {
  RawTrial cm = parseBvh(legFixture(92, "0 92 0 0 0 0 0 0 0\n", 1), "cm.bvh");
  EXPECT_EQ(cm.units, "cm");
  EXPECT_NEAR(pointAt(cm, "Hips", 0).y(), 920.0, 1e-9);
  ASSERT_FALSE(cm.warnings.empty());
  EXPECT_NE(cm.warnings.back().find("'cm'"), std::string::npos);

  RawTrial cmu = parseBvh(legFixture(16, "0 16 0 0 0 0 0 0 0\n", 1), "cmu.bvh");
  EXPECT_EQ(cmu.units, "cmu");
  EXPECT_NEAR(pointAt(cmu, "Hips", 0).y(), 16 * 25.4 / 0.45, 1e-9);
}

TEST(Bvh, SyntheticTPoseFirstFrameIsDropped) {
  const std::string rows =
      "1 16 2 0 0 0 0 0 0\n"       // T-pose: root copied from the next frame, rotations 0
      "1 16 2 3 -4 5 10 20 -15\n"
      "1 16 2.1 3.2 -4.1 5.2 10.5 20.3 -15.2\n"
      "1 16 2.2 3.4 -4.2 5.4 11 20.6 -15.4\n";
  RawTrial t = parseBvh(legFixture(16, rows, 4), "tpose.bvh");
  EXPECT_EQ(t.frameCount(), 3);
  EXPECT_EQ(t.firstFrame, 2);
  EXPECT_NE(t.warnings.front().find("T-pose"), std::string::npos);
}

TEST(Bvh, OrdinaryFirstFramesAreKept) {
  // Root moves between frames 1 and 2: not the conversion's T-pose.
  const std::string moving =
      "1 16 1.9 0 0 0 0 0 0\n1 16 2 3 -4 5 10 20 -15\n1 16 2.1 3.2 -4.1 5.2 10.5 20.3 -15.2\n";
  EXPECT_EQ(parseBvh(legFixture(16, moving, 3), "a.bvh").frameCount(), 3);
  // A still subject standing in a neutral pose: no jump to frame 2.
  const std::string still = "1 16 2 0 0 0 0 0 0\n1 16 2 0 0 0 0 0 0.1\n1 16 2 0 0 0 0 0 0.2\n";
  EXPECT_EQ(parseBvh(legFixture(16, still, 3), "b.bvh").frameCount(), 3);
}

// [SECTION] The CMU trials of the manifest

// PROVENANCE §2: frames including the T-pose frame.
const std::map<std::string, int> kCmuFrames = {
    {"02_01", 344}, {"02_02", 299}, {"05_01", 599}, {"06_01", 495},
    {"07_01", 317}, {"07_02", 330}, {"07_03", 416}, {"07_06", 418},
    {"08_01", 278}, {"08_02", 310}, {"08_03", 354}};

std::vector<std::string> manifestBvhFiles() {
  std::vector<std::string> files;
  std::ifstream in(test::sharedDataDir() / "walkers.csv");
  std::string line;
  while (std::getline(in, line)) {
    const auto comma = line.find(',');
    if (comma != std::string::npos && line.substr(0, comma).ends_with(".bvh")) {
      files.push_back(line.substr(0, comma));
    }
  }
  return files;
}

TEST(BvhCmu, EveryManifestTrialLoads) {
  EW_REQUIRE_SHARED_DATA();
  const auto files = manifestBvhFiles();
  ASSERT_EQ(files.size(), kCmuFrames.size());
  for (const auto& rel : files) {
    SCOPED_TRACE(rel);
    const auto start = std::chrono::steady_clock::now();
    RawTrial t = readRawTrial(test::sharedDataDir() / rel);
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    const std::string stem = std::filesystem::path(rel).stem().string();
    EXPECT_EQ(t.frameCount(), kCmuFrames.at(stem) - 1);
    EXPECT_EQ(t.firstFrame, 2);
    EXPECT_NEAR(t.rateHz, 120.0, 0.01);
    EXPECT_EQ(t.units, "cmu");
    EXPECT_EQ(t.format, "BVH");
    int joints = 0;
    for (const auto& label : t.labels) joints += label.ends_with("_End") ? 0 : 1;
    EXPECT_EQ(joints, 31);
    EXPECT_EQ(t.pointCount(), 31 + 7);
    EXPECT_TRUE(t.positionsMm.allFinite());
    // Standing hip height 0.85-1.0 m once converted from CMU units.
    EXPECT_GT(pointAt(t, "Hips", 0).y(), 800.0);
    EXPECT_LT(pointAt(t, "Hips", 0).y(), 1050.0);
    ASSERT_EQ(t.warnings.size(), 2u);
    EXPECT_NE(t.warnings[0].find("T-pose"), std::string::npos);
    EXPECT_NE(t.warnings[1].find("'cmu'"), std::string::npos);
    std::cout << "[ measure  ] " << stem << ": " << t.frameCount() << " frames in " << ms
              << " ms\n";
  }
}

TEST(BvhCmu, CrlfCopyOfARealFileLoadsTheSame) {
  EW_REQUIRE_SHARED_DATA();
  const auto path = test::sharedDataDir() / "cmu-mocap-bvh/07/07_01.bvh";
  std::ifstream in(path, std::ios::binary);
  const std::string lf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  RawTrial a = parseBvh(lf, "lf");
  RawTrial b = parseBvh(withCrlf(lf), "crlf");
  EXPECT_EQ(a.frameCount(), b.frameCount());
  EXPECT_TRUE(a.positionsMm.isApprox(b.positionsMm));
}

}  // namespace
}  // namespace ew
