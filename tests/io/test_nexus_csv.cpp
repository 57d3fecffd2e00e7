// Vicon Nexus's CSV export (core/io/nexus_csv.h): a C3D's markers written the way Nexus
// exports them read back as the C3D reads, through to the same 15 joints; tabs, velocity
// columns beside the positions, gaps; and every malformed case named with the file and line.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "core/common/errors.h"
#include "core/io/load_trial.h"
#include "core/io/nexus_csv.h"
#include "tests/common/error_matchers.h"
#include "tests/common/marker_trials.h"
#include "tests/common/nexus_text.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using test::NexusLayout;
using test::nexusText;

RawTrial threeMarkers() { return test::threeMarkerTrial(100.0, 7); }

// The markers written, each label after the subject's name as Nexus writes it.
void expectSameMarkers(const RawTrial& read, const RawTrial& written, const std::string& subject, double tolerance) {
  test::expectSameMarkers(read, written, tolerance, subject + ":");
  EXPECT_EQ(read.firstFrame, written.firstFrame);
}

TEST(NexusCsv, CommasTabsAndVelocityColumnsReadAlike) {
  const RawTrial t = threeMarkers();
  for (const NexusLayout& layout : {NexusLayout{}, NexusLayout{'\t', false, true, "Subject01"},
                                    NexusLayout{',', true, false, "Jane Doe"}}) {
    const std::string text = nexusText(t, layout);
    ASSERT_TRUE(looksLikeNexusCsv(text));
    const RawTrial read = parseNexusCsv(text, "walk.csv");
    EXPECT_EQ(read.format, "Nexus CSV");
    EXPECT_EQ(read.units, "mm");
    expectSameMarkers(read, t, layout.subject, 1e-9);
  }
  // A section straight after the markers, without the blank line, ends them too.
  std::string followed = nexusText(t, {});
  followed.pop_back();
  followed += "Model Outputs\n100\n,,Subject01:LAnkleAngles\nFrame,Sub Frame,X,Y,Z\n,,deg,deg,deg\n7,0,1,2,3\n";
  expectSameMarkers(parseNexusCsv(followed, "walk.csv"), t, "Subject01", 1e-9);
  // An export that opens with its events: the markers read, the events said to be left out.
  const std::string withEvents = "Events\nSubject,Context,Name,Time (s),Description\n"
                                 "Subject01,Left,Foot Strike,0.07,\n\n" + nexusText(t, {});
  ASSERT_TRUE(looksLikeNexusCsv(withEvents));
  const RawTrial eventsFirst = parseNexusCsv(withEvents, "walk.csv");
  expectSameMarkers(eventsFirst, t, "Subject01", 1e-9);
  ASSERT_EQ(eventsFirst.warnings.size(), 1u);
  EXPECT_NE(eventsFirst.warnings[0].find("Events section is not read"), std::string::npos);
  EXPECT_FALSE(looksLikeNexusCsv("frame,time_s,head_x\n"));
  EXPECT_FALSE(looksLikeNexusCsv("file,subject\n"));
}

TEST(NexusCsv, TheUserUnitAndRateWin) {
  const RawTrial t = threeMarkers();
  LoadOptions o;
  o.unitsOverride = "m";
  o.rateHzOverride = 50.0;
  const RawTrial read = parseNexusCsv(nexusText(t, {}), "walk.csv", o);
  EXPECT_DOUBLE_EQ(read.rateHz, 50.0);
  EXPECT_DOUBLE_EQ(read.positionsMm(1, 4), 1000.0 * t.positionsMm(1, 4));
}

// Each way a file can be wrong: the error names the file and, where there is one, the line.
TEST(NexusCsv, MalformedExportsNameTheFileAndTheLine) {
  const std::string good = nexusText(threeMarkers(), NexusLayout{',', false, false, "S"});
  const auto replaced = [&](const std::string& from, const std::string& to) {
    return test::replacedOnce(good, from, to);
  };
  const auto fails = [](const std::string& text, ErrorKind kind, std::initializer_list<std::string_view> parts) {
    return test::throwsError([&] { parseNexusCsv(text, "lab.csv"); }, kind, parts);
  };
  EXPECT_TRUE(fails("Devices\n1000\n,,Force\nFrame,Sub Frame,Fx\n,,N\n1,0,1\n", ErrorKind::BadData,
                    {"lab.csv", "without a Trajectories section"}));
  EXPECT_TRUE(fails("Trajectories\n100\n,,S:LASI\n", ErrorKind::Malformed, {"lab.csv", "ends inside"}));
  EXPECT_TRUE(fails(replaced("Trajectories\n100", "Trajectories\nfast"), ErrorKind::Malformed,
                    {"lab.csv", "line 2", "rate"}));
  EXPECT_TRUE(fails(replaced("Trajectories\n100", "Trajectories\n1e300"), ErrorKind::Malformed, {"lab.csv"}));
  EXPECT_TRUE(fails(replaced("Frame,Sub Frame", "Time,Sub Frame"), ErrorKind::Malformed,
                    {"lab.csv", "line 4", "Frame,Sub Frame"}));
  EXPECT_TRUE(fails(replaced(",Y,Z,X,Y,Z,X", ",Y,Q,X,Y,Z,X"), ErrorKind::Malformed, {"lab.csv", "S:LASI", "no Z"}));
  EXPECT_TRUE(fails(replaced("S:RASI", "S:LASI"), ErrorKind::Malformed, {"lab.csv", "named twice"}));
  EXPECT_TRUE(fails(replaced(",mm,mm,mm,mm", ",m,m,m,mm"), ErrorKind::Malformed, {"lab.csv", "--units"}));
  EXPECT_TRUE(fails(replaced("\n8,0,", "\n9,0,"), ErrorKind::Malformed,
                    {"lab.csv", "line 7", "frame 9 after frame 7"}));
  EXPECT_TRUE(fails(replaced("\n8,0,", "\n8.5,0,"), ErrorKind::Malformed, {"lab.csv", "line 7", "whole number"}));
  EXPECT_TRUE(fails(replaced("\n8,0,", "\n8,0,abc"), ErrorKind::Malformed, {"lab.csv", "line 7", "not a number"}));
  EXPECT_TRUE(fails(replaced("\n8,0,", "\n8,0,1,2,3,4,5,6,7,8,9,10,"), ErrorKind::Malformed,
                    {"lab.csv", "line 7", "fields"}));
  EXPECT_TRUE(fails("Trajectories\n100\n,,\nFrame,Sub Frame\n,,\n1,0\n", ErrorKind::BadData, {"lab.csv", "no marker"}));
  EXPECT_TRUE(fails("Trajectories\n100\n,,S:A\nFrame,Sub Frame,X,Y,Z\n,,mm,mm,mm\n\n", ErrorKind::BadData,
                    {"lab.csv", "no frames"}));
}

// A Schreiber-Moissenet trial's 52 markers exported from its C3D the way Nexus writes them:
// the same markers, and through the marker-set tables the same 15 joints as the C3D gives.
TEST(NexusCsv, ASharedC3dExportedAsNexusCsvGivesTheSameJoints) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path c3d = test::sharedDataDir() / "schreiber-moissenet-2019/2014001/2014001_C4_05.c3d";
  const RawTrial fromC3d = readRawTrial(c3d);
  const fs::path csv = test::makeTempDir("nexus_csv") / "2014001_C4_05.csv";
  std::ofstream(csv) << nexusText(fromC3d, {});
  const RawTrial fromCsv = readRawTrial(csv);
  EXPECT_EQ(fromCsv.format, "Nexus CSV");
  expectSameMarkers(fromCsv, fromC3d, "Subject01", 1e-6 * 2000.0);  // ten digits of mm
  test::expectSameJoints(mapRawTrial(fromC3d, {}), mapRawTrial(fromCsv, {}));
}

}  // namespace
}  // namespace ew
