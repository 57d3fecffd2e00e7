// C3D reader against the real files in ../shared/data: the six encodings of one trial,
// the C3D.org sample table of PROVENANCE.md §4, header pointers, invalid residuals,
// non-zero first frames and gait events.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/io/c3d_reader.h"
#include "core/io/file_bytes.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

std::filesystem::path samples() { return test::sharedDataDir() / "c3d-samples"; }
std::filesystem::path schreiber() { return test::sharedDataDir() / "schreiber-moissenet-2019"; }

long nanCount(const RawTrial& t) { return t.positionsMm.array().isNaN().count(); }

bool hasWarningContaining(const RawTrial& t, const std::string& text) {
  for (const auto& w : t.warnings) {
    if (w.find(text) != std::string::npos) return true;
  }
  return false;
}

// [SECTION] Number formats ---------------------------------------------------------------

TEST(C3dVaxFloat, DecodesKnownValues) {
  // VAX F = IEEE single with the 16-bit words swapped and the value divided by 4:
  // 1.0 is stored as the IEEE bits of 4.0 (0x40800000) word-swapped.
  const std::uint8_t one[4] = {0x80, 0x40, 0x00, 0x00};
  EXPECT_EQ(decodeVaxFloat(one), 1.0f);
  const std::uint8_t minusTwoAndHalf[4] = {0x20, 0xC1, 0x00, 0x00};  // IEEE -10.0 = 0xC1200000
  EXPECT_EQ(decodeVaxFloat(minusTwoAndHalf), -2.5f);
  const std::uint8_t zero[4] = {0, 0, 0, 0};
  EXPECT_EQ(decodeVaxFloat(zero), 0.0f);
  const std::uint8_t reserved[4] = {0x00, 0x80, 0x12, 0x34};  // sign 1, exponent 0
  EXPECT_TRUE(std::isnan(decodeVaxFloat(reserved)));
}

// [SECTION] Six encodings of one trial ---------------------------------------------------

// The six files hold one trial. The REAL files were written from the INT values (dec_int
// matches pc_real to 1.2e-4 mm, float rounding), but the vendor's conversion rounded 59 of
// the 8928 valid INT values of pc_int/sgi_int one step differently from dec_int. So the
// tolerance is one INT step, |POINT:SCALE| = 0.2812 mm (readme.txt rounds it to 0.28),
// plus 1e-3 mm for float rounding, and at most 1 % of the values may use that step.
TEST(C3dEncodings, SixEncodingsGiveTheSameCoordinates) {
  EW_REQUIRE_SHARED_DATA();
  const auto dir = samples() / "sample02_vicon370_encodings";
  const RawTrial ref = readC3d(dir / "pc_real.c3d");
  ASSERT_EQ(ref.frameCount(), 89);
  ASSERT_EQ(ref.pointCount(), 36);
  constexpr double kScaleMm = 0.2812;
  constexpr double kFloatMm = 1e-3;
  for (const char* name : {"pc_int.c3d", "dec_int.c3d", "dec_real.c3d", "sgi_int.c3d",
                           "sgi_real.c3d"}) {
    SCOPED_TRACE(name);
    const RawTrial t = readC3d(dir / name);
    ASSERT_EQ(t.labels, ref.labels);
    ASSERT_EQ(t.positionsMm.rows(), ref.positionsMm.rows());
    ASSERT_EQ(t.positionsMm.cols(), ref.positionsMm.cols());
    EXPECT_EQ(t.rateHz, ref.rateHz);
    EXPECT_EQ(t.firstFrame, ref.firstFrame);
    EXPECT_EQ(t.upAxis, ref.upAxis);
    double maxDiff = 0.0;
    long valid = 0, stepped = 0;
    for (Eigen::Index i = 0; i < t.positionsMm.size(); ++i) {
      const double a = t.positionsMm.data()[i], b = ref.positionsMm.data()[i];
      ASSERT_EQ(std::isnan(a), std::isnan(b)) << "missing-sample pattern differs at " << i;
      if (std::isnan(a)) continue;
      ++valid;
      stepped += std::abs(a - b) > kFloatMm;
      maxDiff = std::max(maxDiff, std::abs(a - b));
    }
    EXPECT_LE(maxDiff, kScaleMm + kFloatMm);
    EXPECT_LE(stepped, valid / 100);
  }
  // Some samples are really missing in this trial (negative residuals), and most are not.
  EXPECT_GT(nanCount(ref), 0);
  EXPECT_LT(nanCount(ref), ref.positionsMm.size() / 4);
}

// [SECTION] The C3D.org sample table (PROVENANCE.md §4) -------------------------------------

struct SampleRow {
  const char* path;
  int points;
  double rateHz;
  long firstFrame;
  long lastFrame;
};

TEST(C3dSamples, EverySampleLoadsWithTheDocumentedShape) {
  EW_REQUIRE_SHARED_DATA();
  const std::vector<SampleRow> table = {
      {"sample02_vicon370_encodings/pc_int.c3d", 36, 50, 1, 89},
      {"sample02_vicon370_encodings/pc_real.c3d", 36, 50, 1, 89},
      {"sample02_vicon370_encodings/dec_int.c3d", 36, 50, 1, 89},
      {"sample02_vicon370_encodings/dec_real.c3d", 36, 50, 1, 89},
      {"sample02_vicon370_encodings/sgi_int.c3d", 36, 50, 1, 89},
      {"sample02_vicon370_encodings/sgi_real.c3d", 36, 50, 1, 89},
      {"sample03_vicon370_gait/gait-raw.c3d", 27, 50, 1, 142},
      {"sample03_vicon370_gait/gait-pig-nz.c3d", 85, 120, 300, 600},
      {"sample06_motion_analysis/MACsample.c3d", 33, 60, 1, 180},
      {"sample06_motion_analysis/newwalk.c3d", 25, 60, 1, 360},
      {"sample26_qualisys/Walking_Hybrid_1_1.c3d", 25, 240, 290, 961},
      {"sample00_vicon_nexus/pyCGM2 lower limb CGM24 Walking01.c3d", 171, 100, 63, 555},
      {"sample08_header_pointers/TESTBPI.c3d", 26, 50, 1, 450},
      {"sample16_simi_invalid_residuals/basketball.c3d", 22, 25, 1, 34},
      {"sample13_phoenix_not_zup/golfswing1.c3d", 29, 107.53, 2, 514},
  };
  for (const auto& row : table) {
    SCOPED_TRACE(row.path);
    const RawTrial t = readC3d(samples() / row.path);
    EXPECT_EQ(t.format, "C3D");
    EXPECT_EQ(t.kind, PointKind::Markers);
    EXPECT_EQ(t.pointCount(), row.points);
    EXPECT_NEAR(t.rateHz, row.rateHz, 0.01);
    EXPECT_EQ(t.firstFrame, row.firstFrame);
    EXPECT_EQ(t.frameCount(), row.lastFrame - row.firstFrame + 1);
    EXPECT_EQ(t.positionsMm.cols(), 3 * row.points);
    for (const auto& label : t.labels) EXPECT_FALSE(label.empty());
    // Every value is a finite number of millimetres or NaN: nothing absurd leaks through.
    const double maxAbs = t.positionsMm.array().isNaN().select(0.0, t.positionsMm.array()).abs().maxCoeff();
    EXPECT_LT(maxAbs, 1.0e6);
  }
}

TEST(C3dSamples, StatedUpAxisComesFromYScreen) {
  EW_REQUIRE_SHARED_DATA();
  const RawTrial pc = readC3d(samples() / "sample02_vicon370_encodings/pc_int.c3d");
  ASSERT_TRUE(pc.upAxis.has_value());
  EXPECT_EQ(*pc.upAxis, (SignedAxis{2, 1}));
  // The Schreiber files have no POINT:X_SCREEN/Y_SCREEN: the data decides later.
  const RawTrial sm = readC3d(schreiber() / "2014001/2014001_C4_05.c3d");
  EXPECT_FALSE(sm.upAxis.has_value());
}

// [SECTION] Header pointers, residuals, units, frame numbers ----------------------------

TEST(C3dHeaderPointers, ParameterSectionIsFoundThroughTheHeaderPointer) {
  EW_REQUIRE_SHARED_DATA();
  const auto path = samples() / "sample08_header_pointers/TESTBPI.c3d";
  auto bytes = readFileBytes(path);
  ASSERT_EQ(bytes.at(0), 11) << "TESTBPI.c3d keeps its parameters at block 11";
  const RawTrial t = parseC3d(bytes, path.string());
  EXPECT_EQ(t.pointCount(), 26);
  EXPECT_EQ(t.labels.front(), "RFT1");
  EXPECT_EQ(t.frameCount(), 450);
  // Block 2 is filler (0xFF): a reader that assumed block 2 would read garbage. Pointing
  // the header there must give a clear error, not a trial.
  bytes[0] = 2;
  try {
    parseC3d(bytes, path.string());
    ADD_FAILURE() << "parameters read from the filler block";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("TESTBPI.c3d"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("byte"), std::string::npos) << e.what();
  }
}

TEST(C3dResiduals, NegativeResidualsAreMissingAndMissingUnitsWarn) {
  EW_REQUIRE_SHARED_DATA();
  const RawTrial t = readC3d(samples() / "sample16_simi_invalid_residuals/basketball.c3d");
  EXPECT_EQ(t.frameCount(), 34);
  EXPECT_EQ(nanCount(t), t.positionsMm.size());
  EXPECT_EQ(t.units, "mm");
  EXPECT_TRUE(hasWarningContaining(t, "POINT:UNITS missing"));
  EXPECT_TRUE(hasWarningContaining(t, "invalid"));
}

TEST(C3dUnits, OverrideScalesEveryCoordinate) {
  EW_REQUIRE_SHARED_DATA();
  const auto path = samples() / "sample02_vicon370_encodings/pc_real.c3d";
  const RawTrial mm = readC3d(path);
  LoadOptions metres;
  metres.unitsOverride = "m";
  const RawTrial m = readC3d(path, metres);
  EXPECT_EQ(m.units, "m");
  for (Eigen::Index i = 0; i < mm.positionsMm.size(); ++i) {
    const double a = mm.positionsMm.data()[i], b = m.positionsMm.data()[i];
    if (std::isnan(a)) continue;
    ASSERT_NEAR(b, 1000.0 * a, 1e-9 * std::abs(b) + 1e-9);
  }
  LoadOptions bogus;
  bogus.unitsOverride = "furlong";
  EXPECT_THROW(readC3d(path, bogus), Error);
}

TEST(C3dFrames, NonZeroFirstFrameIsKept) {
  EW_REQUIRE_SHARED_DATA();
  const RawTrial t = readC3d(samples() / "sample03_vicon370_gait/gait-pig-nz.c3d");
  EXPECT_EQ(t.firstFrame, 300);
  EXPECT_EQ(t.frameCount(), 301);
  // Its events are stored in capture time; relative to frame 300 they fall in the trial.
  ASSERT_FALSE(t.events.empty());
  for (const auto& e : t.events) {
    EXPECT_GE(e.timeS, 0.0);
    EXPECT_LE(e.timeS, (t.frameCount() - 1) / t.rateHz);
  }
}

// [SECTION] Events and the walking trials --------------------------------------------------

TEST(C3dEvents, SchreiberFootStrikesMatchTheDocumentedTimes) {
  EW_REQUIRE_SHARED_DATA();
  const RawTrial t = readC3d(schreiber() / "2014001/2014001_C4_05.c3d");
  ASSERT_EQ(t.events.size(), 7u);
  std::vector<double> right, left;
  for (const auto& e : t.events) {
    if (e.type != GaitEventType::FootStrike) continue;
    (e.side == Side::Right ? right : left).push_back(e.timeS);
  }
  const double frame = 1.0 / t.rateHz;
  ASSERT_EQ(right.size(), 2u);
  ASSERT_EQ(left.size(), 2u);
  EXPECT_NEAR(right[0], 0.05, frame);
  EXPECT_NEAR(right[1], 1.01, frame);
  EXPECT_NEAR(left[0], 0.53, frame);
  EXPECT_NEAR(left[1], 1.50, frame);
  int footOff = 0;
  for (const auto& e : t.events) footOff += e.type == GaitEventType::FootOff;
  EXPECT_EQ(footOff, 3);
}

// A frame rate given over the file's re-times its events with its frames: each stays on its frame.
TEST(C3dEvents, ARateOverrideKeepsEachEventOnItsFrame) {
  EW_REQUIRE_SHARED_DATA();
  const std::filesystem::path file = schreiber() / "2014001/2014001_C4_05.c3d";
  const RawTrial asFiled = readC3d(file);
  LoadOptions half;
  half.rateHzOverride = asFiled.rateHz / 2.0;
  const RawTrial slowed = readC3d(file, half);
  ASSERT_EQ(slowed.events.size(), asFiled.events.size());
  for (std::size_t i = 0; i < asFiled.events.size(); ++i)
    EXPECT_NEAR(slowed.events[i].timeS * slowed.rateHz, asFiled.events[i].timeS * asFiled.rateHz, 1e-6);
}

// The Schreiber-Moissenet files keep the subject's measures in a SUBJECT group (LABELS, UNITS,
// VALUES): the stature is read (metres there), and a value that is no person's stature in its
// unit is left out with a warning.
TEST(C3dSubject, TheRecordedStatureIsReadAndAnAbsurdOneWarns) {
  EW_REQUIRE_SHARED_DATA();
  const auto file = schreiber() / "2014001/2014001_C4_05.c3d";
  const RawTrial t = readC3d(file);
  ASSERT_TRUE(t.subjectStatureMm.has_value());
  EXPECT_NEAR(*t.subjectStatureMm, 1655.0, 0.01);
  EXPECT_FALSE(readC3d(schreiber() / "2014001/2014001_ST.c3d").subjectStatureMm.has_value());

  // The same file with its height (1.655 m, the fourth of six floats) made 1655 "m".
  std::vector<std::uint8_t> bytes = readFileBytes(file);
  const float height = 1.655f, absurd = 1655.0f;
  std::uint8_t from[4], to[4];
  std::memcpy(from, &height, 4);
  std::memcpy(to, &absurd, 4);
  const auto at = std::search(bytes.begin(), bytes.end(), std::begin(from), std::end(from));
  ASSERT_NE(at, bytes.end());
  std::copy(std::begin(to), std::end(to), at);
  const RawTrial patched = parseC3d(bytes, "patched.c3d");
  EXPECT_FALSE(patched.subjectStatureMm.has_value());
  EXPECT_TRUE(hasWarningContaining(patched, "not a person's stature")) << patched.warnings.size();
}

TEST(C3dSchreiber, EveryTrialLoadsComplete) {
  EW_REQUIRE_SHARED_DATA();
  int trials = 0;
  for (const auto& dir : std::filesystem::directory_iterator(schreiber())) {
    for (const auto& f : std::filesystem::directory_iterator(dir.path())) {
      if (f.path().extension() != ".c3d") continue;
      SCOPED_TRACE(f.path().string());
      const RawTrial t = readC3d(f.path());
      ++trials;
      EXPECT_EQ(t.rateHz, 100.0);
      EXPECT_EQ(t.units, "mm");
      EXPECT_TRUE(t.pointCount() == 52 || t.pointCount() == 48);
      EXPECT_EQ(nanCount(t), 0) << "PROVENANCE: no gaps in these trials";
      EXPECT_TRUE(t.warnings.empty()) << t.warnings.front();
      const bool isStatic = f.path().stem().string().ends_with("_ST");
      if (isStatic) {
        EXPECT_EQ(t.frameCount(), 1);
      } else {
        EXPECT_GE(t.frameCount(), 125);
        EXPECT_LE(t.frameCount(), 232);
        EXPECT_EQ(t.events.size(), 7u);
      }
    }
  }
  EXPECT_EQ(trials, 36);
}

TEST(C3dErrors, MissingFileAndTextFileAreClearErrors) {
  EW_REQUIRE_SHARED_DATA();
  try {
    readC3d(samples() / "no_such_file.c3d");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
  }
  // A text file with a .c3d name: the header key check names the file and the byte.
  const auto text = readFileBytes(samples() / "sample08_header_pointers/readme.txt");
  try {
    parseC3d(text, "readme_as.c3d");
    ADD_FAILURE() << "text parsed as C3D";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Malformed);
    EXPECT_NE(std::string(e.what()).find("readme_as.c3d: byte 1: not a C3D file"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace ew
