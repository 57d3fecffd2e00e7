// C3D export (core/io/c3d_writer.h): written files read back by the project's own C3D reader
// (core/io/c3d_reader.h) to the same points, labels, rate and events; the header and parameter
// layout byte by byte; long trials past the header's 16-bit frame words; hostile inputs refused
// with the file and the problem named and nothing written; and `reconstruct` / `joints
// --out x.c3d` on a real trial against the CSV they write.
//
// Tolerances. A coordinate is stored as the 32-bit float nearest to it, so the reader gives back
// exactly double(float(x)) (checked bit for bit): at most |x|·2⁻²⁴ away, 0.12 µm at 2 m. An
// event's seconds within its minute are a float too: below 60 s that is 3.6 µs at worst, far
// inside half a frame (5 ms at 100 Hz); the test asks for the float itself.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "core/common/errors.h"
#include "core/gait/dataset.h"
#include "core/gait/gait_events.h"
#include "core/io/c3d_reader.h"
#include "core/io/c3d_writer.h"
#include "core/io/joint_csv.h"
#include "core/io/trc_writer.h"
#include "core/mapping/joint_mapping.h"
#include "core/synth/population.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

SynthWalker oneWalker() {
  PopulationOptions o;
  o.count = 1;
  o.simulation.rateHz = 100.0;
  o.simulation.cycles = 3.0;
  return generatePopulation(o).front();
}

double asStored(double v) { return static_cast<double>(static_cast<float>(v)); }

std::uint16_t wordAt(const std::string& bytes, std::size_t at) {
  return static_cast<std::uint16_t>(static_cast<unsigned char>(bytes[at]) |
                                    (static_cast<unsigned char>(bytes[at + 1]) << 8));
}

float floatAt(const std::string& bytes, std::size_t at) {
  float v = 0;
  std::memcpy(&v, bytes.data() + at, 4);  // the test machines are little-endian, as the file
  return v;
}

// The value of a one-dimensional text parameter: after its name, the offset word, the type,
// the dimension count and the dimension.
std::string textParameter(const std::string& bytes, const std::string& name, std::size_t length) {
  const std::size_t at = bytes.find(name);
  if (at == std::string::npos) return "";
  return bytes.substr(at + name.size() + 5, length);
}

// Two points over three frames and a couple of events: the smallest file with everything.
C3dContent smallContent() {
  C3dContent c;
  c.rateHz = 50.0;
  Eigen::MatrixX3d a(3, 3), b(3, 3);
  a << 1, 2, 3, 4, 5, 6, 7, 8, 9;
  b << -10.5, 20.25, 1000.125, 0, 0, 1, 3, 2, 1;
  c.points = {{"RHEE", "right heel", a}, {"r_toe", "", b}};
  c.events = {{Side::Right, GaitEventType::FootStrike, 0.02, ""},
              {Side::Left, GaitEventType::FootOff, 0.04, "Foot Off"}};
  return c;
}

// [SECTION] Round trip through our reader

TEST(C3dWriter, AWalkerAndItsFeetReadBackToTheSamePointsLabelsRateAndEvents) {
  const auto dir = test::makeTempDir("c3d_round_trip");
  const SynthWalker w = oneWalker();
  Eigen::MatrixXd frames = w.trial.positionsMm;
  frames.block<1, 3>(5, 3 * index(Joint::LWrist)).setConstant(NAN);  // missing stays missing
  frames(7, 3 * index(Joint::Head) + 1) = NAN;  // one coordinate missing: the whole sample is
  C3dContent c;
  c.rateHz = 100.0;
  c.points = jointPointTrajectories(frames, "joint centre");
  Eigen::MatrixX3d heel = frames.middleCols<3>(3 * index(Joint::RAnkle));
  heel.col(2).array() -= 60.0;
  c.points.push_back({"r_heel", "right heel, 60 mm under the ankle", heel});
  c.events = {{Side::Left, GaitEventType::FootOff, 0.5, ""},
              {Side::Right, GaitEventType::FootStrike, 0.1234567, ""},
              {Side::Right, GaitEventType::Other, 75.25, "Toe Touch"}};  // past a minute
  writeC3d(dir / "walk.c3d", c);

  const RawTrial raw = readC3d(dir / "walk.c3d");
  EXPECT_EQ(raw.format, "C3D");
  EXPECT_EQ(raw.kind, PointKind::CanonicalJoints);  // our 15 joints first, then a foot point
  EXPECT_EQ(raw.rateHz, 100.0);
  EXPECT_EQ(raw.units, "mm");
  EXPECT_EQ(raw.firstFrame, 1);
  ASSERT_EQ(raw.labels.size(), 16u);
  for (int j = 0; j < kJointCount; ++j) EXPECT_EQ(raw.labels[static_cast<size_t>(j)], kJointNames[static_cast<size_t>(j)]);
  EXPECT_EQ(raw.labels[15], "r_heel");
  ASSERT_TRUE(raw.upAxis.has_value());
  EXPECT_EQ(*raw.upAxis, (SignedAxis{2, 1}));  // Y_SCREEN +Z
  ASSERT_EQ(raw.positionsMm.rows(), frames.rows());
  for (Eigen::Index r = 0; r < frames.rows(); ++r)
    for (std::size_t p = 0; p < c.points.size(); ++p) {
      const Eigen::RowVector3d want = c.points[p].positionsMm.row(r);
      const Eigen::RowVector3d back = raw.positionsMm.block<1, 3>(r, 3 * static_cast<Eigen::Index>(p));
      if (!want.allFinite()) {
        EXPECT_FALSE(back.array().isFinite().any()) << "frame " << r << " point " << p;
        continue;
      }
      for (int a = 0; a < 3; ++a) ASSERT_EQ(back[a], asStored(want[a])) << "frame " << r << " point " << p;
    }
  bool saidMissing = false;
  for (const auto& warning : raw.warnings)
    saidMissing |= warning.find("2 of " + std::to_string(16 * frames.rows()) + " point samples are missing") != std::string::npos;
  EXPECT_TRUE(saidMissing) << ::testing::PrintToString(raw.warnings);

  ASSERT_EQ(raw.events.size(), 3u);  // sorted by time
  EXPECT_EQ(raw.events[0].side, Side::Right);
  EXPECT_EQ(raw.events[0].type, GaitEventType::FootStrike);
  EXPECT_EQ(raw.events[0].label, "Foot Strike");
  EXPECT_EQ(raw.events[0].timeS, asStored(0.1234567));
  EXPECT_EQ(raw.events[1].side, Side::Left);
  EXPECT_EQ(raw.events[1].type, GaitEventType::FootOff);
  EXPECT_EQ(raw.events[1].timeS, 0.5);
  EXPECT_EQ(raw.events[2].label, "Toe Touch");
  EXPECT_EQ(raw.events[2].type, GaitEventType::Other);
  EXPECT_EQ(raw.events[2].timeS, 75.25);  // 1 minute and 15.25 s
}

// The header, the parameter section's header and the data as the C3D guide lays them out,
// checked on the bytes, not only through our reader.
TEST(C3dWriter, TheBytesFollowTheGuidesLayout) {
  const auto dir = test::makeTempDir("c3d_layout");
  C3dContent c = smallContent();
  c.points[1].positionsMm(1, 0) = NAN;
  writeC3d(dir / "small.c3d", c);
  const std::string b = test::readTextFile(dir / "small.c3d");
  ASSERT_EQ(b.size() % kC3dBlockBytes, 0u);
  EXPECT_EQ(b[0], 2);                         // parameters in block 2
  EXPECT_EQ(static_cast<unsigned char>(b[1]), 0x50u);
  EXPECT_EQ(wordAt(b, 2), 2u);                // points
  EXPECT_EQ(wordAt(b, 4), 0u);                // analog values a frame
  EXPECT_EQ(wordAt(b, 6), 1u);                // first frame
  EXPECT_EQ(wordAt(b, 8), 3u);                // last frame
  EXPECT_EQ(floatAt(b, 12), -1.0f);           // scale < 0: REAL
  const unsigned dataBlock = wordAt(b, 16);
  EXPECT_EQ(floatAt(b, 20), 50.0f);
  EXPECT_EQ(wordAt(b, 298), 12345u);          // word 150: 4-character event labels
  EXPECT_EQ(wordAt(b, 300), 0u);              // word 151: no header events (the EVENT group has them)
  EXPECT_EQ(b[512 + 2], static_cast<char>(dataBlock - 2));  // parameter blocks
  EXPECT_EQ(b[512 + 3], 84);                  // Intel
  const std::size_t data = (dataBlock - 1) * kC3dBlockBytes;
  ASSERT_EQ(b.size(), data + kC3dBlockBytes);  // 3 frames x 2 points x 16 bytes, padded
  EXPECT_EQ(floatAt(b, data), 1.0f);          // frame 1, RHEE x
  EXPECT_EQ(floatAt(b, data + 12), 0.0f);     // residual 0: valid, computed
  const std::size_t missing = data + 32 + 16;  // frame 2, r_toe
  for (int k = 0; k < 3; ++k) EXPECT_EQ(floatAt(b, missing + 4 * k), 0.0f);
  EXPECT_EQ(floatAt(b, missing + 12), -1.0f);  // the C3D mark of an invalid sample
  for (const char* text : {"POINT", "LABELS", "RHEE", "right heel", "TRIAL", "ACTUAL_END_FIELD",
                           "EVENT", "CONTEXTS", "Right", "Foot Strike", "GENERIC_FLAGS"})
    EXPECT_NE(b.find(text), std::string::npos) << text;
}

// The Vicon Nexus gait file among the C3D.org samples (whose layout this writer follows: the
// TRIAL fields, the EVENT group's types) and our file read back by the same code give the same
// kind of events; a check that our reading of both is one reading.
TEST(C3dWriter, EventsReadLikeAViconFilesEvents) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path vicon = test::sharedDataDir() / "c3d-samples/sample03_vicon370_gait/gait-pig-nz.c3d";
  if (!fs::exists(vicon)) GTEST_SKIP() << vicon << " not found";
  const RawTrial theirs = readC3d(vicon);
  ASSERT_FALSE(theirs.events.empty());
  const auto dir = test::makeTempDir("c3d_like_vicon");
  C3dContent c = smallContent();
  c.rateHz = theirs.rateHz;
  c.events = theirs.events;
  for (auto& e : c.events) e.label.clear();  // written from their types
  writeC3d(dir / "ours.c3d", c);
  const RawTrial ours = readC3d(dir / "ours.c3d");
  ASSERT_EQ(ours.events.size(), theirs.events.size());
  for (std::size_t i = 0; i < ours.events.size(); ++i) {
    EXPECT_EQ(ours.events[i].side, theirs.events[i].side);
    EXPECT_EQ(ours.events[i].type, theirs.events[i].type);
    EXPECT_EQ(ours.events[i].label, theirs.events[i].label);
    EXPECT_NEAR(ours.events[i].timeS, theirs.events[i].timeS, 1e-5);
  }
}

// [SECTION] Long trials

TEST(C3dWriter, ATrialPastTheHeadersSixteenBitFramesReadsBackWhole) {
  const auto dir = test::makeTempDir("c3d_long");
  const Eigen::Index frames = 70000;
  C3dContent c;
  c.rateHz = 1000.0;
  Eigen::MatrixX3d p(frames, 3);
  for (Eigen::Index r = 0; r < frames; ++r) p.row(r) << static_cast<double>(r), 1.0, 2.0;
  c.points = {{"marker", "", p}};
  c.events = {{Side::Left, GaitEventType::FootStrike, 69.5, ""}};
  writeC3d(dir / "long.c3d", c);
  const std::string b = test::readTextFile(dir / "long.c3d");
  EXPECT_EQ(wordAt(b, 8), 65535u);  // the header's last frame: as far as 16 bits go
  const RawTrial raw = readC3d(dir / "long.c3d");
  ASSERT_EQ(raw.positionsMm.rows(), frames);
  EXPECT_EQ(raw.positionsMm(frames - 1, 0), static_cast<double>(frames - 1));
  EXPECT_EQ(raw.positionsMm(65535, 0), 65535.0);
  ASSERT_EQ(raw.events.size(), 1u);
  EXPECT_EQ(raw.events[0].timeS, 69.5);
}

// [SECTION] Hostile input

void expectRefused(const fs::path& file, const C3dContent& c, const std::string& problem) {
  try {
    writeC3d(file, c);
    ADD_FAILURE() << "no error for: " << problem;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadArgument) << e.what();
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(problem), std::string::npos) << e.what() << "\nwanted: " << problem;
  }
}

TEST(C3dWriter, HostileInputsAreRefusedByNameAndNothingIsWritten) {
  const auto dir = test::makeTempDir("c3d_hostile");
  const fs::path f = dir / "bad.c3d";
  auto with = [](auto change) {
    C3dContent c = smallContent();
    change(c);
    return c;
  };
  expectRefused(f, with([](C3dContent& c) { c.rateHz = NAN; }), "Hz is not one a capture has (1–10000 Hz)");
  expectRefused(f, with([](C3dContent& c) { c.rateHz = 0.0; }), "frame rate 0.000000 Hz");
  expectRefused(f, with([](C3dContent& c) { c.points.clear(); }), "no points to write");
  expectRefused(f, with([](C3dContent& c) { for (auto& p : c.points) p.positionsMm.resize(0, 3); }),
                "no frames to write");
  expectRefused(f, with([](C3dContent& c) { c.points[1].positionsMm.conservativeResize(2, 3); }),
                "point 2 (r_toe): 2 frames where point 1 has 3");
  expectRefused(f, with([](C3dContent& c) { c.points[0].label = std::string(256, 'A'); }),
                "the label has 256 characters; C3D holds at most 255");
  expectRefused(f, with([](C3dContent& c) { c.points[0].label = ""; }), "point 1: the label is empty");
  expectRefused(f, with([](C3dContent& c) { c.points[1].label = "RHEE"; }), "the label 'RHEE' is used twice");
  expectRefused(f, with([](C3dContent& c) { c.points[0].label = "R\tHEE"; }), "not printable ASCII");
  expectRefused(f, with([](C3dContent& c) { c.points[0].label = "RHEE "; }), "begins or ends with a space");
  expectRefused(f, with([](C3dContent& c) { c.points[0].description = std::string(300, 'd'); }),
                "the description has 300 characters");
  expectRefused(f, with([](C3dContent& c) { c.points[0].description = "two\nlines"; }),
                "the description has a control character");
  expectRefused(f, with([](C3dContent& c) { c.points[0].positionsMm(0, 0) = 1e39; }),
                "point 1 (RHEE), frame 1: coordinate");
  expectRefused(f, with([](C3dContent& c) { c.points.resize(256, c.points[0]); }),
                "256 points; C3D's POINT:LABELS names at most 255");
  expectRefused(f, with([](C3dContent& c) { c.events.resize(256, c.events[0]); }),
                "256 events; C3D's EVENT:TIMES holds at most 255");
  expectRefused(f, with([](C3dContent& c) { c.events[1].timeS = -0.5; }), "event 2: time -0.500000 s");
  expectRefused(f, with([](C3dContent& c) { c.events[0].timeS = INFINITY; }), "event 1: time inf s");
  expectRefused(f, with([](C3dContent& c) { c.yScreen = "+Y"; }), "name the same axis");
  EXPECT_TRUE(fs::is_empty(dir));
  // A refusal leaves an existing file as it was; a folder that is not there is an Io error.
  writeC3d(f, smallContent());
  const std::string before = test::readTextFile(f);
  expectRefused(f, with([](C3dContent& c) { c.rateHz = -1; }), "frame rate");
  EXPECT_EQ(test::readTextFile(f), before);
  try {
    writeC3d(dir / "no_such_folder/x.c3d", smallContent());
    ADD_FAILURE() << "wrote into a missing folder";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io) << e.what();
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
}

// [SECTION] A walker: the 15 joints and the events of its kinematics

// The feet where known: written after the joints, their events from the heel and the toe, and
// read back by our own reader to the same joints and feet (a point never seen is left out).
TEST(C3dWriter, AWalkersFeetAreWrittenAndReadBack) {
  const auto dir = test::makeTempDir("c3d_feet");
  const SynthWalker w = oneWalker();
  const Eigen::MatrixXd& frames = w.trial.positionsMm;
  Eigen::MatrixXd feet(frames.rows(), kFootDims3);
  for (Side side : {Side::Right, Side::Left}) {
    const int ankle = 3 * index(side == Side::Left ? Joint::LAnkle : Joint::RAnkle);
    const Eigen::RowVector3d heelOffset(0, -60, -50), toeOffset(0, 140, -50);
    for (Eigen::Index r = 0; r < frames.rows(); ++r) {
      feet.block<1, 3>(r, 3 * index(heelOf(side))) = frames.block<1, 3>(r, ankle) + heelOffset;
      feet.block<1, 3>(r, 3 * index(toeOf(side))) = frames.block<1, 3>(r, ankle) + toeOffset;
    }
  }
  feet.middleCols<3>(3 * index(FootPoint::LToe)).setConstant(NAN);
  writeWalkerWithFeetC3d(dir / "feet.c3d", frames, feet, 100.0);
  const RawTrial raw = readC3d(dir / "feet.c3d");
  EXPECT_EQ(raw.kind, PointKind::CanonicalJoints);
  ASSERT_EQ(raw.pointCount(), kJointCount + 3);
  EXPECT_EQ(raw.labels[kJointCount], "r_heel");
  const JointTrial back = toJointTrial(raw);
  ASSERT_TRUE(back.hasFeet());
  EXPECT_LT((back.positionsMm - frames).cwiseAbs().maxCoeff(), 1e-3);  // 32-bit floats
  EXPECT_TRUE(back.feetMm.middleCols<3>(3 * index(FootPoint::LToe)).array().isNaN().all());
  for (FootPoint p : {FootPoint::RHeel, FootPoint::RToe, FootPoint::LHeel})
    EXPECT_LT((back.feetMm.middleCols<3>(3 * index(p)) - feet.middleCols<3>(3 * index(p))).cwiseAbs().maxCoeff(), 1e-3);
  // The events: the right foot's from its heel and toe, the left's from its ankle (no left
  // toe); the frames already face +y with z up.
  const GaitEventSet want = gaitEventsFromFeet(frames, feet, 100.0);
  EXPECT_EQ(want.method, "kinematics (heel and toe of one foot, the other's ankle)");
  const GaitEventSet got = gaitEventsFromFile(raw.events, 1e9);
  for (Side side : {Side::Right, Side::Left}) {
    ASSERT_EQ(got.of(side).strikesS.size(), want.of(side).strikesS.size());
    ASSERT_EQ(got.of(side).offsS.size(), want.of(side).offsS.size());
    for (std::size_t i = 0; i < want.of(side).strikesS.size(); ++i)
      EXPECT_NEAR(got.of(side).strikesS[i], want.of(side).strikesS[i], 0.005);
    for (std::size_t i = 0; i < want.of(side).offsS.size(); ++i)
      EXPECT_NEAR(got.of(side).offsS[i], want.of(side).offsS[i], 0.005);
  }
  EXPECT_FALSE(back.feetInSagittalPlanes);
  // Feet lifted from one view say so in their descriptions, and read back so.
  writeWalkerWithFeetC3d(dir / "lifted.c3d", frames, feet, 100.0, {}, {}, true);
  const RawTrial lifted = readC3d(dir / "lifted.c3d");
  ASSERT_EQ(lifted.descriptions.size(), static_cast<std::size_t>(kJointCount + 3));
  EXPECT_EQ(lifted.descriptions[kJointCount], kSagittalFootDescription);
  EXPECT_TRUE(toJointTrial(lifted).feetInSagittalPlanes);
  // Without feet the file is writeWalkerC3d's, byte for byte.
  writeWalkerWithFeetC3d(dir / "none.c3d", frames, Eigen::MatrixXd(), 100.0);
  writeWalkerC3d(dir / "plain.c3d", frames, 100.0);
  EXPECT_EQ(test::readTextFile(dir / "none.c3d"), test::readTextFile(dir / "plain.c3d"));
}

TEST(C3dWriter, AWalkerCarriesTheEventsOfItsOwnKinematicsAndOpensAsAWalker) {
  const auto dir = test::makeTempDir("c3d_walker");
  const SynthWalker w = oneWalker();
  const Eigen::MatrixXd& frames = w.trial.positionsMm;
  // Notes may be UTF-8 (METHOD's "§"); one longer than a parameter's 255 bytes becomes lines.
  const std::string longNote = "frame: METHOD §2, " + std::string(300, 'n') + " end";
  writeWalkerC3d(dir / "walk.c3d", frames, 100.0, {"a note", longNote});
  const std::string walkBytes = test::readTextFile(dir / "walk.c3d");
  EXPECT_NE(walkBytes.find("frame: METHOD §2, nnn"), std::string::npos);
  EXPECT_NE(walkBytes.find("nnn end"), std::string::npos);
  const RawTrial raw = readC3d(dir / "walk.c3d");
  EXPECT_EQ(raw.kind, PointKind::CanonicalJoints);
  const GaitEventSet want = gaitEventsFromKinematics(frames, 100.0);
  const GaitEventSet back = gaitEventsFromFile(raw.events, 1e9);
  ASSERT_GT(want.right.strikesS.size() + want.left.strikesS.size(), 3u);
  for (Side side : {Side::Right, Side::Left}) {
    ASSERT_EQ(back.of(side).strikesS.size(), want.of(side).strikesS.size());
    ASSERT_EQ(back.of(side).offsS.size(), want.of(side).offsS.size());
    // The copy turned to face +y exactly moves the ankle's lead a little: half a frame.
    for (std::size_t i = 0; i < want.of(side).strikesS.size(); ++i)
      EXPECT_NEAR(back.of(side).strikesS[i], want.of(side).strikesS[i], 0.005);
    for (std::size_t i = 0; i < want.of(side).offsS.size(); ++i)
      EXPECT_NEAR(back.of(side).offsS[i], want.of(side).offsS[i], 0.005);
  }
  // Opened as any trial: the same speed comes out.
  const WalkingTrial again = loadWalkingTrial(dir / "walk.c3d");
  EXPECT_NEAR(again.speedMps, w.attributes.at("speed_mps"), 0.05 * w.attributes.at("speed_mps"));

  // The same walker turned (a proper rotation) to walk along −x with y down, as a camera's
  // axes may hold it: the screen axes follow the body and the events are the same.
  Eigen::MatrixXd turned = frames;
  for (int j = 0; j < kJointCount; ++j) {
    const Eigen::MatrixXd p = frames.middleCols<3>(3 * j);
    turned.col(3 * j) = -p.col(1);
    turned.col(3 * j + 1) = -p.col(2);
    turned.col(3 * j + 2) = p.col(0);
  }
  writeWalkerC3d(dir / "turned.c3d", turned, 100.0);
  const RawTrial rawTurned = readC3d(dir / "turned.c3d");
  EXPECT_EQ(*rawTurned.upAxis, (SignedAxis{1, -1}));
  const std::string bytes = test::readTextFile(dir / "turned.c3d");
  EXPECT_EQ(textParameter(bytes, "X_SCREEN", 2), "-X");  // forward
  EXPECT_EQ(textParameter(bytes, "Y_SCREEN", 2), "-Y");  // up
  const GaitEventSet turnedBack = gaitEventsFromFile(rawTurned.events, 1e9);
  for (Side side : {Side::Right, Side::Left}) {
    ASSERT_EQ(turnedBack.of(side).strikesS.size(), back.of(side).strikesS.size());
    for (std::size_t i = 0; i < back.of(side).strikesS.size(); ++i)
      EXPECT_NEAR(turnedBack.of(side).strikesS[i], back.of(side).strikesS[i], 1e-4);
  }

  // The extension chooses the format in any case, as the CLI's --out does.
  writeJointTrajectories(dir / "UPPER.C3D", frames, 100.0, {"a comment"});
  EXPECT_EQ(readC3d(dir / "UPPER.C3D").positionsMm.rows(), frames.rows());

  // A walker with a gap has no kinematic events, and says so in the file.
  Eigen::MatrixXd gap = frames;
  gap(3, 0) = NAN;
  writeWalkerC3d(dir / "gap.c3d", gap, 100.0);
  EXPECT_TRUE(readC3d(dir / "gap.c3d").events.empty());
  EXPECT_NE(test::readTextFile(dir / "gap.c3d").find("no gait events: a joint sample is missing"),
            std::string::npos);
}

// [SECTION] The command line on a real trial

// `reconstruct` and `joints` with --out x.c3d write what --out x.csv writes: the same joints
// (the CSV's 10 significant digits and the float's rounding apart) and, in the C3D, the events
// of those joints' kinematics.
TEST(C3dWriterCli, ReconstructAndJointsWriteTheJointsTheirCsvHolds) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path trial =
      fs::absolute(test::sharedDataDir() / "schreiber-moissenet-2019/2014001/2014001_C4_05.c3d");
  if (!fs::exists(trial)) GTEST_SKIP() << trial << " not found";
  const auto dir = test::makeTempDir("c3d_cli");
  const std::string reconstruct = "reconstruct --input " + trial.string() + " --project-angle 30 --angle 30 --out ";
  const std::string joints = "joints " + trial.string() + " --out ";
  for (const std::string& command : {reconstruct, joints}) {
    for (const char* out : {"x.c3d", "x.csv"}) {
      const test::ShellRun r = test::runCli(command + out, dir);
      ASSERT_EQ(r.exitCode, 0) << command << out << "\n" << r.err;
    }
    const RawTrial csv = readJointCsv(dir / "x.csv");
    const RawTrial c3d = readC3d(dir / "x.c3d");
    EXPECT_EQ(c3d.kind, PointKind::CanonicalJoints);
    // The joints as the CSV has them; `joints` on motion capture writes the feet after them.
    const JointTrial fromC3d = toJointTrial(c3d);
    EXPECT_EQ(fromC3d.hasFeet(), command == joints) << command;
    EXPECT_EQ(std::vector<std::string>(c3d.labels.begin(), c3d.labels.begin() + kJointCount), csv.labels);
    EXPECT_EQ(c3d.labels.size(), command == joints ? 19u : 15u);
    EXPECT_NEAR(c3d.rateHz, csv.rateHz, 1e-9);
    ASSERT_EQ(c3d.positionsMm.rows(), csv.positionsMm.rows()) << command;
    ASSERT_EQ(fromC3d.positionsMm.cols(), csv.positionsMm.cols());
    double worst = 0.0;
    for (Eigen::Index r = 0; r < csv.positionsMm.rows(); ++r)
      for (Eigen::Index k = 0; k < csv.positionsMm.cols(); ++k) {
        const double v = csv.positionsMm(r, k);
        const double d = std::abs(fromC3d.positionsMm(r, k) - v);
        EXPECT_LE(d, std::abs(v) * (0x1p-24 + 1e-9) + 1e-9) << command << " frame " << r << " column " << k;
        worst = std::max(worst, d);
      }
    std::cout << command << "x.c3d: " << c3d.positionsMm.rows() << " frames, " << c3d.events.size()
              << " events, worst difference from the CSV " << worst << " mm\n";
    const GaitEventSet want = gaitEventsFromFeet(csv.positionsMm, fromC3d.feetMm, csv.rateHz);
    const GaitEventSet back = gaitEventsFromFile(c3d.events, 1e9);
    for (Side side : {Side::Right, Side::Left}) {
      ASSERT_EQ(back.of(side).strikesS.size(), want.of(side).strikesS.size()) << command;
      ASSERT_EQ(back.of(side).offsS.size(), want.of(side).offsS.size()) << command;
      for (std::size_t i = 0; i < want.of(side).strikesS.size(); ++i)
        EXPECT_NEAR(back.of(side).strikesS[i], want.of(side).strikesS[i], 0.5 / csv.rateHz);
      for (std::size_t i = 0; i < want.of(side).offsS.size(); ++i)
        EXPECT_NEAR(back.of(side).offsS[i], want.of(side).offsS[i], 0.5 / csv.rateHz);
    }
    EXPECT_FALSE(c3d.events.empty()) << command;
  }
}

}  // namespace
}  // namespace ew
