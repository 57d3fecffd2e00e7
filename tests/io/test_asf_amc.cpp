// ASF/AMC reader: a hand-written skeleton with analytic bone ends, then CMU subject 35.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <numbers>

#include "core/common/errors.h"
#include "core/io/asf_amc_reader.h"
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

void expectNear(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double tol = 1e-9) {
  EXPECT_LT((a - b).norm(), tol) << "got " << a.transpose() << ", want " << b.transpose();
}

std::string withCrlf(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n') out += '\r';
    out += c;
  }
  return out;
}

// Root, bone "a" up +y (length 2, dof rx), bone "b" along +x (length 1) whose axis is
// turned 90 deg about z, so its rx dof turns about the global y axis. Lengths in inches.
const std::string kAsf =
    "# tiny skeleton\n"
    ":version 1.10\n"
    ":name tiny\n"
    ":units\n"
    "  mass 1.0\n"
    "  length 1.0\n"
    "  angle deg\n"
    ":documentation\n"
    "  free text: with a colon\n"
    ":root\n"
    "   order TX TY TZ RX RY RZ\n"
    "   axis XYZ\n"
    "   position 0 0 0\n"
    "   orientation 0 0 0\n"
    ":bonedata\n"
    "  begin\n"
    "     id 1\n"
    "     name a\n"
    "     direction 0 1 0\n"
    "     length 2\n"
    "     axis 0 0 0 XYZ\n"
    "    dof rx\n"
    "    limits (-180.0 180.0)\n"
    "  end\n"
    "  begin\n"
    "     id 2\n"
    "     name b\n"
    "     direction 1 0 0\n"
    "     length 1\n"
    "     axis 0 0 90 XYZ\n"
    "    dof rx rz\n"
    "    limits (-inf inf)\n"
    "           (-90 90)\n"
    "  end\n"
    ":hierarchy\n"
    "  begin\n"
    "    root a\n"
    "    a b\n"
    "  end\n";

const std::string kAmc =
    "#!OML:ASF tiny.asf\n"
    ":FULLY-SPECIFIED\n"
    ":DEGREES\n"
    "1\n"
    "root 1 2 3 0 0 0\n"
    "a 0\n"
    "b 0 0\n"
    "2\n"
    "root 1 2 3 0 0 0\n"
    "a 90\n"
    "b 90 0\n"
    "3\n"
    "root 0 0 0 0 0 90\n";  // bones omitted: all their dofs are 0

constexpr double kIn = 25.4;

// [SECTION] Fixture with analytic positions

TEST(AsfAmc, BoneEndsFollowTheAcclaimConvention) {
  RawTrial t = parseAsfAmc(kAsf, kAmc, "tiny.amc");
  ASSERT_EQ(t.frameCount(), 3);
  EXPECT_EQ(t.labels, (std::vector<std::string>{"root", "a", "b"}));
  // Rest pose: a up 2, b along +x 1 (the axis only matters for rotations).
  expectNear(pointAt(t, "root", 0), kIn * Eigen::Vector3d(1, 2, 3));
  expectNear(pointAt(t, "a", 0), kIn * Eigen::Vector3d(1, 4, 3));
  expectNear(pointAt(t, "b", 0), kIn * Eigen::Vector3d(2, 4, 3));
  // a: Rx(90) takes +y to +z. b: C·Rx(90)·C⁻¹ = Ry(90) takes +x to -z, then Rx(90) to +y.
  expectNear(pointAt(t, "a", 1), kIn * Eigen::Vector3d(1, 2, 5));
  expectNear(pointAt(t, "b", 1), kIn * Eigen::Vector3d(1, 3, 5));
  // Root Rz(90): a's +y becomes -x, b's +x becomes +y; missing bones stay at 0.
  expectNear(pointAt(t, "a", 2), kIn * Eigen::Vector3d(-2, 0, 0));
  expectNear(pointAt(t, "b", 2), kIn * Eigen::Vector3d(-2, 1, 0));
}

TEST(AsfAmc, FieldsRateAndUnits) {
  RawTrial t = parseAsfAmc(kAsf, kAmc, "tiny.amc");
  EXPECT_EQ(t.format, "ASF/AMC");
  EXPECT_EQ(t.kind, PointKind::SkeletonJoints);
  ASSERT_TRUE(t.upAxis.has_value());
  EXPECT_EQ(*t.upAxis, (SignedAxis{1, 1}));
  EXPECT_EQ(t.units, "in");
  EXPECT_EQ(t.firstFrame, 1);
  EXPECT_DOUBLE_EQ(t.rateHz, 120.0);
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_NE(t.warnings[0].find("120 Hz"), std::string::npos);

  LoadOptions o;
  o.rateHzOverride = 60.0;
  o.unitsOverride = "mm";
  RawTrial m = parseAsfAmc(kAsf, kAmc, "tiny.amc", o);
  EXPECT_DOUBLE_EQ(m.rateHz, 60.0);
  EXPECT_TRUE(m.warnings.empty());
  EXPECT_EQ(m.units, "mm");
  expectNear(pointAt(m, "a", 0), Eigen::Vector3d(1, 4, 3));
}

TEST(AsfAmc, CmuLengthUnit) {
  std::string asf = kAsf;
  asf.replace(asf.find("length 1.0"), 10, "length 0.45");
  RawTrial t = parseAsfAmc(asf, kAmc, "cmu.amc");
  EXPECT_EQ(t.units, "cmu");
  expectNear(pointAt(t, "root", 0), 25.4 / 0.45 * Eigen::Vector3d(1, 2, 3), 1e-9);
}

TEST(AsfAmc, RadiansAndCrlf) {
  std::string amc = kAmc;
  amc.replace(amc.find(":DEGREES"), 8, ":RADIANS");
  amc.replace(amc.find("a 90"), 4, "a " + std::to_string(std::numbers::pi / 2));
  amc.replace(amc.find("b 90 0"), 6, "b " + std::to_string(std::numbers::pi / 2) + " 0");
  RawTrial t = parseAsfAmc(withCrlf(kAsf), withCrlf(amc), "rad.amc");
  expectNear(pointAt(t, "b", 1), kIn * Eigen::Vector3d(1, 3, 5), 1e-4);
}

TEST(AsfAmc, UnknownBoneNamesTheAmcLine) {
  std::string amc = kAmc + "c 1 2 3\n";
  try {
    parseAsfAmc(kAsf, amc, "tiny.asf", "tiny.amc");
    FAIL() << "unknown bone accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Malformed);
    EXPECT_EQ(e.file(), "tiny.amc");
    EXPECT_EQ(e.position(), "line 14");
  }
}

TEST(AsfAmc, WrongDofCountAndGapsAreErrors) {
  std::string extra = kAmc;
  extra.replace(extra.find("a 90"), 4, "a 90 1");
  EXPECT_THROW(parseAsfAmc(kAsf, extra, "x.amc"), Error);
  std::string gap = kAmc;
  gap.replace(gap.find("\n3\n"), 3, "\n5\n");
  EXPECT_THROW(parseAsfAmc(kAsf, gap, "x.amc"), Error);
}

TEST(AsfAmc, SkeletonErrorsNameTheAsf) {
  std::string asf = kAsf;
  asf.replace(asf.find("a b\n"), 4, "a b\n    b a\n");  // a cycle: a has two parents
  try {
    parseAsfAmc(asf, kAmc, "tiny.asf", "tiny.amc");
    FAIL() << "cycle accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Malformed);
    EXPECT_EQ(e.file(), "tiny.asf");
    EXPECT_EQ(e.position(), "line 39");
  }
}

// [SECTION] CMU subject 35

TEST(AsfAmcCmu, Subject35Loads) {
  EW_REQUIRE_SHARED_DATA();
  const auto start = std::chrono::steady_clock::now();
  RawTrial t = readRawTrial(test::sharedDataDir() / "cmu-mocap-asfamc/35/35_01.amc");
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(t.frameCount(), 358);
  EXPECT_EQ(t.firstFrame, 1);
  EXPECT_DOUBLE_EQ(t.rateHz, 120.0);
  EXPECT_EQ(t.units, "cmu");
  EXPECT_EQ(t.pointCount(), 31);  // root + 30 bones
  EXPECT_EQ(t.labels.front(), "root");
  EXPECT_TRUE(t.positionsMm.allFinite());
  // Root about 1 m up, travelling ~3.8 m along +z (PROVENANCE §3).
  EXPECT_NEAR(pointAt(t, "root", 0).y(), 1000.0, 100.0);
  const double travel = pointAt(t, "root", 357).z() - pointAt(t, "root", 0).z();
  EXPECT_NEAR(travel, 3800.0, 300.0);
  // The femur keeps its ASF length (7.41015 units) through the motion.
  for (int f : {0, 100, 357}) {
    EXPECT_NEAR((pointAt(t, "lfemur", f) - pointAt(t, "lhipjoint", f)).norm(),
                7.41015 * 25.4 / 0.45, 1e-6);
  }
  std::cout << "[ measure  ] 35_01: " << t.frameCount() << " frames in " << ms << " ms\n";
}

TEST(AsfAmcCmu, MissingSkeletonIsAnIoError) {
  const auto dir = test::makeTempDir("asf_missing");
  const auto amc = dir / "x_01.amc";
  std::ofstream(amc) << kAmc;
  EXPECT_THROW(readAsfAmc(amc), Error);
  std::ofstream(dir / "x.asf") << kAsf;
  EXPECT_EQ(readAsfAmc(amc).frameCount(), 3);
}

}  // namespace
}  // namespace ew
