#include <gtest/gtest.h>

#include "core/common/errors.h"
#include "core/io/trc_reader.h"

namespace ew {
namespace {

const char* kTrc =
    "PathFileType\t4\t(X/Y/Z)\twalk.trc\r\n"
    "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\r\n"
    "60.00\t60.00\t3\t2\tm\t60.00\t1\t3\r\n"
    "Frame#\tTime\tLASI\t\t\tRASI\t\t\r\n"
    "\t\tX1\tY1\tZ1\tX2\tY2\tZ2\r\n"
    "\r\n"
    "1\t0.000\t0.1\t0.9\t0.2\t0.3\t0.9\t0.2\r\n"
    "2\t0.0167\t0.1\t0.9\t0.2\t\t\t\r\n"
    "3\t0.0333\t0.1\t0.9\t0.2\t0.3\t0.9\t0.25\r\n";

TEST(Trc, ReadsHeaderNamesRateUnitsAndGaps) {
  const RawTrial raw = parseTrc(kTrc, "walk.trc");
  EXPECT_EQ(raw.format, "TRC");
  EXPECT_EQ(raw.labels, (std::vector<std::string>{"LASI", "RASI"}));
  EXPECT_DOUBLE_EQ(raw.rateHz, 60.0);
  EXPECT_EQ(raw.units, "m");
  ASSERT_EQ(raw.positionsMm.rows(), 3);
  EXPECT_DOUBLE_EQ(raw.positionsMm(0, 1), 900.0);
  EXPECT_TRUE(std::isnan(raw.positionsMm(1, 3)));
  EXPECT_DOUBLE_EQ(raw.positionsMm(2, 5), 250.0);
  EXPECT_EQ(raw.firstFrame, 1);
}

TEST(Trc, ToleratesMissingHeaderKeys) {
  std::string text = kTrc;
  text.replace(text.find("DataRate"), text.find("Frame#") - text.find("DataRate"), "");
  const RawTrial raw = parseTrc(text, "walk.trc");
  EXPECT_NEAR(raw.rateHz, 1.0 / 0.0167, 1e-6);
  EXPECT_EQ(raw.units, "mm");
  EXPECT_GE(raw.warnings.size(), 2u);
}

TEST(Trc, MalformedRowsNameTheLine) {
  std::string text = kTrc;
  text.replace(text.find("0.0333\t0.1"), 6, "0.0333\tx");
  try {
    parseTrc(text, "walk.trc");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("line 9"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseTrc("", "empty.trc"), Error);
  EXPECT_THROW(parseTrc("hello\nworld\n", "text.trc"), Error);
}

// Issue 53: a header declaring 2e9 frames over one row was read silently; the QTM reader
// refuses the same mismatch. NumFrames is not trusted for an allocation, only compared.
TEST(Trc, NumFramesThatIsNotTheRowsIsRefused) {
  std::string huge = kTrc;
  huge.replace(huge.find("60.00\t60.00\t3\t"), 14, "60.00\t60.00\t2e9\t");
  huge.erase(huge.find("2\t0.0167"));  // one row left
  try {
    parseTrc(huge, "huge.trc");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Malformed);
    EXPECT_EQ(e.file(), "huge.trc");
    EXPECT_EQ(e.position(), "line 3");
    EXPECT_NE(std::string(e.what()).find("NumFrames says 2e9 frames, the file holds 1 (cut short?)"), std::string::npos)
        << e.what();
  }
  std::string more = kTrc;
  more.replace(more.find("60.00\t60.00\t3\t"), 14, "60.00\t60.00\t2\t");
  try {
    parseTrc(more, "more.trc");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("NumFrames says 2 frames, the file holds 3"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("cut short"), std::string::npos) << e.what();
  }
  // Left empty, NumFrames states nothing to compare.
  std::string unsaid = kTrc;
  unsaid.replace(unsaid.find("60.00\t60.00\t3\t"), 14, "60.00\t60.00\t\t");
  EXPECT_EQ(parseTrc(unsaid, "unsaid.trc").positionsMm.rows(), 3);
}

TEST(Trc, TruncationsNeverCrash) {
  const std::string text = kTrc;
  for (size_t n = 0; n < text.size(); ++n) {
    try {
      parseTrc(text.substr(0, n), "cut.trc");
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("cut.trc"), std::string::npos);
    }
  }
}

}  // namespace
}  // namespace ew
