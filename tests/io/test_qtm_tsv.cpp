// Qualisys Track Manager's TSV export (core/io/qtm_tsv.h): every layout QTM writes (with or
// without the frame and time columns and their header row, gaps as empty cells or zeros) reads
// back the markers written; Qualisys' own sample C3D exported as TSV gives its 15 joints; and
// every malformed case is named with the file and line.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/common/errors.h"
#include "core/io/load_trial.h"
#include "core/io/qtm_tsv.h"
#include "tests/common/error_matchers.h"
#include "tests/common/marker_trials.h"
#include "tests/common/qtm_text.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using test::QtmLayout;
using test::qtmText;

RawTrial threeMarkers() { return test::threeMarkerTrial(120.0, 1); }
using test::expectSameMarkers;

TEST(QtmTsv, EveryLayoutReadsTheMarkersWritten) {
  const RawTrial t = threeMarkers();
  for (const QtmLayout& layout : {QtmLayout{}, QtmLayout{true, false, false, false}, QtmLayout{false, false, false, false},
                                  QtmLayout{true, true, true, false}, QtmLayout{false, false, true, true}}) {
    const RawTrial read = parseQtmTsv(qtmText(t, layout), "walk.tsv");
    EXPECT_EQ(read.format, "QTM TSV");
    EXPECT_EQ(read.units, "mm");
    EXPECT_EQ(read.firstFrame, 1);
    expectSameMarkers(read, t, 1e-9);
    EXPECT_EQ(read.warnings.size(), layout.events ? 1u : 0u);
  }
  // Without a header row, the last marker gone on the first frame: the width is read off a row
  // that ends in a value, so the frame and time are not taken for coordinates.
  RawTrial lastGone = t;
  lastGone.firstFrame = 31;
  lastGone.positionsMm.block<1, 3>(0, 6).setConstant(std::nan(""));
  std::string text = qtmText(lastGone, QtmLayout{true, false, false, false});
  for (size_t at = text.find("\t\n"); at != std::string::npos; at = text.find("\t\n", at)) text.erase(at, 1);
  const RawTrial read = parseQtmTsv(text, "walk.tsv");
  EXPECT_EQ(read.firstFrame, 31);
  expectSameMarkers(read, lastGone, 1e-9);
}

TEST(QtmTsv, TheUserUnitAndRateWin) {
  LoadOptions o;
  o.unitsOverride = "m";
  o.rateHzOverride = 60.0;
  const RawTrial t = threeMarkers();
  const RawTrial read = parseQtmTsv(qtmText(t), "walk.tsv", o);
  EXPECT_DOUBLE_EQ(read.rateHz, 60.0);
  EXPECT_DOUBLE_EQ(read.positionsMm(1, 4), 1000.0 * t.positionsMm(1, 4));
}

TEST(QtmTsv, MalformedExportsNameTheFileAndTheLine) {
  const std::string good = qtmText(threeMarkers());
  const auto replaced = [&](const std::string& from, const std::string& to) {
    return test::replacedOnce(good, from, to);
  };
  const auto fails = [](const std::string& text, ErrorKind kind, std::initializer_list<std::string_view> parts) {
    return test::throwsError([&] { parseQtmTsv(text, "lab.tsv"); }, kind, parts);
  };
  EXPECT_TRUE(fails(replaced("DATA_INCLUDED\t3D", "DATA_INCLUDED\t6D"), ErrorKind::BadData, {"lab.tsv", "'6D'", "C3D"}));
  EXPECT_TRUE(fails(replaced("MARKER_NAMES", "MARKERS"), ErrorKind::BadData, {"lab.tsv", "no MARKER_NAMES"}));
  EXPECT_TRUE(fails("a,b,c\n1,2,3\n", ErrorKind::BadData, {"lab.tsv", "no MARKER_NAMES"}));
  EXPECT_TRUE(fails(replaced("\tRASI\tLHEE", "\tLASI\tLHEE"), ErrorKind::Malformed, {"lab.tsv", "line 10", "named twice"}));
  EXPECT_TRUE(fails(replaced("\tRASI\tLHEE", "\t\tLHEE"), ErrorKind::Malformed, {"lab.tsv", "line 10", "without a name"}));
  EXPECT_TRUE(fails(replaced("NO_OF_MARKERS\t3", "NO_OF_MARKERS\t4"), ErrorKind::Malformed,
                    {"lab.tsv", "line 10", "NO_OF_MARKERS says 4"}));
  EXPECT_TRUE(fails(replaced("NO_OF_FRAMES\t4", "NO_OF_FRAMES\t5"), ErrorKind::Malformed,
                    {"lab.tsv", "NO_OF_FRAMES says 5", "holds 4", "cut short"}));
  // Counts no integer holds are said as they read (libFuzzer found the cast to long).
  EXPECT_TRUE(fails(replaced("NO_OF_MARKERS\t3", "NO_OF_MARKERS\t281e300"), ErrorKind::Malformed,
                    {"lab.tsv", "NO_OF_MARKERS says 2.81e+302"}));
  EXPECT_TRUE(fails(replaced("NO_OF_FRAMES\t4", "NO_OF_FRAMES\t-1e19"), ErrorKind::Malformed,
                    {"lab.tsv", "NO_OF_FRAMES says -1e+19"}));
  EXPECT_TRUE(fails(replaced("NO_OF_FRAMES\t4", "NO_OF_FRAMES\tmany"), ErrorKind::Malformed,
                    {"lab.tsv", "line 1", "NO_OF_FRAMES"}));
  EXPECT_TRUE(fails(replaced("FREQUENCY\t120\n", ""), ErrorKind::BadData, {"lab.tsv", "--rate"}));
  EXPECT_TRUE(fails(replaced("FREQUENCY\t120", "FREQUENCY\t0"), ErrorKind::Malformed, {"lab.tsv", "FREQUENCY"}));
  EXPECT_TRUE(fails(replaced("\n2\t", "\n3\t"), ErrorKind::Malformed, {"lab.tsv", "line 14", "frame 3 after frame 1"}));
  EXPECT_TRUE(fails(replaced("\n2\t", "\n2.5\t"), ErrorKind::Malformed, {"lab.tsv", "line 14", "whole number"}));
  EXPECT_TRUE(fails(replaced("\n2\t0.008333333333\t", "\n2\t0.008333333333\tx"), ErrorKind::Malformed,
                    {"lab.tsv", "line 14", "not a number"}));
  EXPECT_TRUE(fails(replaced("\n2\t0.008333333333\t", "\n2\t0.008333333333\t1\t2\t3\t4\t5\t6\t7\t8\t9\t10\t"),
                    ErrorKind::Malformed, {"lab.tsv", "line 14", "fields, expected 11"}));
  const std::string bare = qtmText(threeMarkers(), QtmLayout{false, false, false, false});
  std::string narrow = bare;
  narrow.replace(narrow.find("\n100\t"), 5, "\n");
  narrow.replace(narrow.find("\n100.25\t"), 8, "\n");
  narrow.replace(narrow.find("\n100.5\t"), 7, "\n");
  narrow.replace(narrow.find("\n100.75\t"), 8, "\n");
  EXPECT_TRUE(fails(narrow, ErrorKind::Malformed, {"lab.tsv", "fields for 3 markers"}));
  EXPECT_TRUE(fails(good.substr(0, good.find("Frame\t")), ErrorKind::BadData, {"lab.tsv", "no frames"}));
}

// Qualisys' own sample (c3d-samples/sample26_qualisys, the Qualisys hybrid marker set) written
// as QTM exports it reads back to the same 15 joints as its C3D.
TEST(QtmTsv, QualisysSampleExportedAsTsvGivesTheSameJoints) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path c3d = test::sharedDataDir() / "c3d-samples/sample26_qualisys/Walking_Hybrid_1_1.c3d";
  const RawTrial fromC3d = readRawTrial(c3d);
  const fs::path tsv = test::makeTempDir("qtm_tsv") / "Walking_Hybrid_1_1.tsv";
  std::ofstream(tsv) << qtmText(fromC3d);
  const RawTrial fromTsv = readRawTrial(tsv);
  EXPECT_EQ(fromTsv.format, "QTM TSV");
  expectSameMarkers(fromTsv, fromC3d, 1e-6 * 5000.0);  // ten digits of mm
  test::expectSameJoints(mapRawTrial(fromC3d, {}), mapRawTrial(fromTsv, {}));
}

}  // namespace
}  // namespace ew
