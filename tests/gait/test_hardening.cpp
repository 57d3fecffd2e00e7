// Inputs that crashed every path after the readers (issue 11): a walk out and back, a
// one-frame 1 km glitch, absurd rates, absurd counts, files that expand a thousandfold in
// memory, a folder named like a trial. Each file is written by the test; each must give a
// typed error or a result, never a crash, and the CLI must say which.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/common/errors.h"
#include "core/gait/canonical_frame.h"
#include "core/gait/dataset.h"
#include "core/gait/gait_cycles.h"
#include "core/gait/prepare.h"
#include "core/io/joint_csv.h"
#include "core/io/load_trial.h"
#include "core/io/trc_reader.h"
#include "core/mapping/joint_mapping.h"
#include "tests/common/synthetic_gait.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

// [SECTION] Files the tests write

// A real overground walk: one straight pass of a Schreiber & Moissenet subject.
fs::path realC3d() {
  return test::sharedDataDir() / "schreiber-moissenet-2019" / "2014001" / "2014001_C4_05.c3d";
}

// 15 joints of a real trial in its lab frame, turned z-up.
JointTrial labJoints(const fs::path& file) {
  JointTrial t = toJointTrial(readRawTrial(file));
  rotateFrames(t.positionsMm, rotationToZUp(t.upAxis.value_or(SignedAxis{2, 1})));
  t.upAxis = SignedAxis{2, 1};
  return t;
}

// The walk, then the same walk reversed in time with every frame turned round (180° about
// the vertical through its pelvis): the walker goes back along the same line, facing home.
Eigen::MatrixXd outAndBack(const Eigen::MatrixXd& out) {
  const Eigen::Index n = out.rows();
  Eigen::MatrixXd both(2 * n, kDims3);
  both.topRows(n) = out;
  const int pelvis = 3 * index(Joint::Pelvis);
  for (Eigen::Index r = 0; r < n; ++r) {
    const auto source = out.row(n - 1 - r);
    for (int j = 0; j < kJointCount; ++j) {
      both(n + r, 3 * j) = 2.0 * source(pelvis) - source(3 * j);
      both(n + r, 3 * j + 1) = 2.0 * source(pelvis + 1) - source(3 * j + 1);
      both(n + r, 3 * j + 2) = source(3 * j + 2);
    }
  }
  return both;
}

void writeText(const fs::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// A TRC of raw markers (OpenSim layout), the rate as given.
void writeTrc(const fs::path& file, const RawTrial& raw, const std::string& rate,
              const std::string& numMarkers) {
  std::ostringstream out;
  out << "PathFileType\t4\t(X/Y/Z)\t" << file.filename().string() << "\n";
  out << "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n";
  out << rate << "\t" << rate << "\t" << raw.frameCount() << "\t" << numMarkers << "\tmm\n";
  out << "Frame#\tTime";
  for (const auto& label : raw.labels) out << "\t" << label << "\t\t";
  out << "\n\t";
  for (size_t k = 0; k < raw.labels.size(); ++k)
    out << "\tX" << k + 1 << "\tY" << k + 1 << "\tZ" << k + 1;
  out << "\n";
  out.precision(10);
  for (int r = 0; r < raw.frameCount(); ++r) {
    out << r + 1 << "\t" << r / raw.rateHz;
    for (Eigen::Index c = 0; c < raw.positionsMm.cols(); ++c) {
      out << "\t";
      if (std::isfinite(raw.positionsMm(r, c))) out << raw.positionsMm(r, c);
    }
    out << "\n";
  }
  writeText(file, out.str());
}

// A joint CSV of the analytic walker whose `# rate_hz` directive says `rate`.
fs::path csvWithRate(const fs::path& dir, const std::string& rate) {
  const fs::path file = dir / "rate.csv";
  writeJointCsv(file, test::analyticWalkFrames({}), 100.0);
  std::ifstream in(file);
  std::ostringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  s.replace(s.find("rate_hz=100"), 11, "rate_hz=" + rate);
  writeText(file, s);
  return file;
}

// An ASF of `bones` one-dof bones hanging off the root, and an AMC of `frames` frames that
// name no bone (all dofs 0): tiny text, frames x bones points by forward kinematics.
void writeAmplifyingAsfAmc(const fs::path& dir, int bones, int frames, int padBytes = 0) {
  std::ostringstream asf;
  asf << ":version 1.10\n:name amp\n:units\n  length 1.0\n  angle deg\n:root\n"
      << "  order TX TY TZ RX RY RZ\n  axis XYZ\n  position 0 0 0\n  orientation 0 0 "
         "0\n:bonedata\n";
  for (int b = 1; b <= bones; ++b) {
    asf << "begin\nid " << b << "\nname b" << b << "\ndirection 0 1 0\nlength 1\naxis 0 0 0 XYZ\n"
        << "dof rx\nlimits (-180 180)\nend\n";
  }
  asf << ":hierarchy\nbegin\nroot";
  for (int b = 1; b <= bones; ++b) asf << " b" << b;
  asf << "\nend\n";
  writeText(dir / "amp.asf", asf.str());
  std::ostringstream amc;
  amc << ":FULLY-SPECIFIED\n:DEGREES\n";
  const std::string pad(static_cast<size_t>(padBytes), ' ');
  for (int f = 1; f <= frames; ++f)
    amc << f << "\n" << (padBytes ? "root 0 0 0 0 0 0" + pad + "\n" : "");
  writeText(dir / "amp_01.amc", amc.str());
}

// A BVH with `joints` channel-less joints (each with an End Site) under a 6-channel root,
// and `frames` frames: a few bytes a frame, 2 x joints points each.
void writeAmplifyingBvh(const fs::path& file, int joints, int frames, int padBytes = 0) {
  std::ostringstream bvh;
  bvh << "HIERARCHY\nROOT Hips\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition "
      << "Zrotation Xrotation Yrotation\n";
  for (int j = 0; j < joints; ++j) {
    bvh << "JOINT j" << j << "\n{\nOFFSET 0 1 0\nCHANNELS 0\nEnd Site\n{\nOFFSET 0 1 0\n}\n}\n";
  }
  bvh << "}\nMOTION\nFrames: " << frames << "\nFrame Time: 0.01\n";
  const std::string row = "0 0 0 0 0 0" + std::string(static_cast<size_t>(padBytes), ' ') + "\n";
  for (int f = 0; f < frames; ++f) bvh << row;
  writeText(file, bvh.str());
}

// `action` must throw an Error of `kind` whose message holds every one of `texts`.
template <typename Action>
void expectTypedError(Action&& action, ErrorKind kind, const std::vector<std::string>& texts) {
  try {
    action();
    ADD_FAILURE() << "accepted; expected an error mentioning '" << texts.front() << "'";
  } catch (const Error& e) {
    EXPECT_EQ(errorKindName(e.kind()), errorKindName(kind)) << e.what();
    for (const auto& text : texts)
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

test::ProgramRun cli(const std::vector<std::string>& arguments, const fs::path& dir) {
  return test::runProgram(EW_CLI_PATH, arguments, dir);
}

// The CLI ran to its end: no signal, an exit code, and a message rather than silence.
void expectCleanExit(const test::ProgramRun& run) {
  EXPECT_EQ(run.signal, 0) << "killed by signal " << run.signal << ":\n" << run.output;
  EXPECT_TRUE(run.exitCode == 0 || run.exitCode == 1) << run.exitCode << ":\n" << run.output;
}

// [SECTION] Walks with turns

TEST(Hardening, OutAndBackWalkReconstructsFromItsLongestStraightSegment) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path dir = test::makeTempDir("out_and_back");
  const JointTrial lab = labJoints(realC3d());
  const WalkingTrial single = prepareWalkingTrial(lab);
  const fs::path file = dir / "out_and_back.csv";
  writeJointCsv(file, outAndBack(lab.positionsMm), lab.rateHz);

  const WalkingTrial both = loadWalkingTrial(file);
  ASSERT_GE(both.segments.size(), 2u);
  ASSERT_GE(both.segment, 0);
  const StraightSegment& used = both.segments[static_cast<size_t>(both.segment)];
  EXPECT_GE(both.windowBegin, used.begin);
  EXPECT_LE(both.windowEnd, used.end);
  EXPECT_GE(both.cycles.cycleCount, 1.0);
  // Each leg is the real walk: the same speed and cadence as the trial alone.
  EXPECT_NEAR(both.speedMps, single.speedMps, 0.1 * single.speedMps);
  EXPECT_NEAR(both.cycles.strideHz, single.cycles.strideHz, 0.1 * single.cycles.strideHz);
  // The two legs head opposite ways.
  const double turn =
      std::remainder(both.segments.front().headingDeg - both.segments.back().headingDeg, 360.0);
  EXPECT_GT(std::abs(turn), 150.0);

  const auto run = cli({"info", file.string()}, dir);
  expectCleanExit(run);
  EXPECT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("straight segments"), std::string::npos) << run.output;

  // The user may take the other leg: `joints --segment N` counts as `info` lists them.
  const int other = static_cast<int>(both.segments.size()) - both.segment;  // 1-based
  const auto chosen = cli({"joints", file.string(), "--segment", std::to_string(other), "--out",
                           (dir / "other.csv").string()},
                          dir);
  EXPECT_EQ(chosen.exitCode, 0) << chosen.output;
  std::ifstream written(dir / "other.csv");
  std::stringstream header;
  header << written.rdbuf();
  EXPECT_NE(header.str().find("straight_segment=" + std::to_string(other) + " of"),
            std::string::npos);
  const auto absent =
      cli({"joints", file.string(), "--segment", "9", "--out", (dir / "x.csv").string()}, dir);
  EXPECT_EQ(absent.exitCode, 2) << absent.output;
  EXPECT_NE(absent.output.find("segment 9 does not exist"), std::string::npos) << absent.output;
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
}

TEST(Hardening, ChosenSegmentIsUsedAndABadChoiceIsATypedError) {
  EW_REQUIRE_SHARED_DATA();
  const JointTrial lab = labJoints(realC3d());
  JointTrial both = lab;
  both.positionsMm = outAndBack(lab.positionsMm);
  const WalkingTrial longest = prepareWalkingTrial(both);
  PrepareOptions options;
  options.segment = static_cast<int>(longest.segments.size()) - 1 - longest.segment;
  // The other leg is the same walk turned round: it reconstructs too.
  const WalkingTrial other = prepareWalkingTrial(both, options);
  EXPECT_EQ(other.segment, *options.segment);
  EXPECT_NEAR(other.speedMps, longest.speedMps, 0.1 * longest.speedMps);
  options.segment = 17;
  expectTypedError([&] { prepareWalkingTrial(both, options); }, ErrorKind::BadArgument,
                   {"segment 18 does not exist"});
}

TEST(Hardening, WalkingInACircleNeverCrashes) {
  // Heading turns continuously: every straight segment is short. A result or a typed
  // error naming the walking stage, whichever; never an empty window read past its end.
  test::AnalyticGait g;
  g.durationS = 6.0;
  JointTrial t = test::analyticWalkTrial(g);
  t.upAxis = SignedAxis{2, 1};
  for (Eigen::Index r = 0; r < t.positionsMm.rows(); ++r) {
    const double a =
        2.0 * M_PI * static_cast<double>(r) / static_cast<double>(t.positionsMm.rows());
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    for (int j = 0; j < kJointCount; ++j) {
      t.positionsMm.block<1, 3>(r, 3 * j) =
          (turn * t.positionsMm.block<1, 3>(r, 3 * j).transpose()).transpose();
    }
  }
  try {
    const WalkingTrial w = prepareWalkingTrial(t);
    EXPECT_GE(w.cycles.cycleCount, 1.0);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("walking"), std::string::npos) << e.what();
  }
}

// [SECTION] Glitches

TEST(Hardening, OneMarkerJumpingOneKilometreForOneFrameIsRejectedNotFatal) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path dir = test::makeTempDir("glitch");
  RawTrial raw = readRawTrial(realC3d());
  LoadOptions options;
  options.unitsOverride = "mm";
  const std::string rate = std::to_string(raw.rateHz);
  writeTrc(dir / "clean.trc", raw, rate, std::to_string(raw.labels.size()));
  const WalkingTrial clean = loadWalkingTrial(dir / "clean.trc", options);
  const int frame = raw.frameCount() / 2;
  for (Eigen::Index c = 0; c < raw.positionsMm.cols(); c += 3) {
    if (std::isfinite(raw.positionsMm(frame, c))) {
      raw.positionsMm(frame, c) += 1.0e6;  // 1 km along x, one marker, one frame
      break;
    }
  }
  const fs::path file = dir / "glitch.trc";
  writeTrc(file, raw, rate, std::to_string(raw.labels.size()));
  const WalkingTrial glitched = loadWalkingTrial(file, options);
  EXPECT_NEAR(glitched.speedMps, clean.speedMps, 0.01 * clean.speedMps);
  EXPECT_NEAR(glitched.cycles.strideHz, clean.cycles.strideHz, 0.01 * clean.cycles.strideHz);
  bool warned = false;
  for (const auto& w : glitched.joints.warnings)
    warned |= w.find("glitched sample") != std::string::npos;
  EXPECT_TRUE(warned) << "the rejected glitch is not reported";

  const auto run = cli({"info", file.string()}, dir);
  expectCleanExit(run);
  EXPECT_EQ(run.exitCode, 0) << run.output;
}

// [SECTION] Rates and counts

TEST(Hardening, AbsurdRateInCsvIsATypedErrorNamingTheRate) {
  const fs::path dir = test::makeTempDir("csv_rate");
  for (const std::string rate : {"1e300", "0.001", "-5", "0"}) {
    const fs::path file = csvWithRate(dir, rate);
    expectTypedError([&] { loadWalkingTrial(file); }, ErrorKind::Malformed,
                     {"frame rate", "rate.csv"});
    const auto run = cli({"info", file.string()}, dir);
    expectCleanExit(run);
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find("frame rate"), std::string::npos) << run.output;
  }
}

TEST(Hardening, AbsurdRateInTrcIsATypedError) {
  const fs::path dir = test::makeTempDir("trc_rate");
  RawTrial raw;
  raw.labels = {"a", "b"};
  raw.rateHz = 100.0;
  raw.positionsMm = Eigen::MatrixXd::Random(50, 6);
  const fs::path file = dir / "rate.trc";
  writeTrc(file, raw, "1e300", "2");
  expectTypedError([&] { readRawTrial(file); }, ErrorKind::Malformed, {"DataRate", "frame rate"});
  expectCleanExit(cli({"info", file.string()}, dir));
}

TEST(Hardening, RateOverrideIsBoundedToo) {
  LoadOptions options;
  for (double rate : {1e300, 0.5, std::numeric_limits<double>::infinity()}) {
    options.rateHzOverride = rate;
    EXPECT_THROW(parseJointCsv(jointCsvHeader() + "\n", "x.csv", options), Error);
  }
}

TEST(Hardening, NumMarkersOf1e20IsOnlyAWarning) {
  // Was a cast of 1e20 to size_t (undefined behaviour): the name row is what counts.
  const fs::path dir = test::makeTempDir("trc_count");
  RawTrial raw;
  raw.labels = {"a", "b"};
  raw.rateHz = 100.0;
  raw.positionsMm = Eigen::MatrixXd::Random(50, 6);
  writeTrc(dir / "count.trc", raw, "100", "1e20");
  const RawTrial read = readRawTrial(dir / "count.trc");
  EXPECT_EQ(read.labels.size(), 2u);
  ASSERT_FALSE(read.warnings.empty());
  EXPECT_NE(read.warnings.front().find("1e20"), std::string::npos) << read.warnings.front();
}

// [SECTION] Memory

TEST(Hardening, AmplifyingAsfAmcIsRefusedBeforeItExpands) {
  const fs::path dir = test::makeTempDir("amp_amc");
  writeAmplifyingAsfAmc(dir, 1024, 19512);
  EXPECT_LT(fs::file_size(dir / "amp.asf") + fs::file_size(dir / "amp_01.amc"), 300'000u);
  // 19512 frames x 1025 points from 0.2 MB.
  expectTypedError([&] { readRawTrial(dir / "amp_01.amc"); }, ErrorKind::Unsupported,
                   {"point-frames"});
}

TEST(Hardening, AmplifyingBvhIsRefusedBeforeItExpands) {
  const fs::path dir = test::makeTempDir("amp_bvh");
  writeAmplifyingBvh(dir / "amp.bvh", 2000, 5000);
  // 5000 frames x 4001 points from 0.19 MB.
  expectTypedError([&] { readRawTrial(dir / "amp.bvh"); }, ErrorKind::Unsupported,
                   {"point-frames"});
}

TEST(Hardening, RealSizedSkeletonFilesStillLoad) {
  // The allowance is per byte: a dense file of many frames is not refused.
  const fs::path dir = test::makeTempDir("dense_bvh");
  writeAmplifyingBvh(dir / "dense.bvh", 30, 3000);
  EXPECT_EQ(readRawTrial(dir / "dense.bvh").frameCount(), 3000);
}

// Peak memory is ASan's, not ours, under AddressSanitizer (GCC defines __SANITIZE_ADDRESS__,
// clang reports it through __has_feature).
#if defined(__SANITIZE_ADDRESS__)
#define EW_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define EW_UNDER_ASAN 1
#endif
#endif
#if !defined(EW_UNDER_ASAN)
// A joint CSV of `frames` frames of zeros: as many positions as a CSV may hold.
void writeLongCsv(const fs::path& file, int frames) {
  std::ofstream out(file);
  out << "# rate_hz=100\n" << jointCsvHeader() << "\n";
  std::string zeros;
  for (int c = 0; c < kDims3; ++c) zeros += ",0";
  for (int r = 0; r < frames; ++r) out << r << "," << r / 100.0 << zeros << "\n";
}

// Peak memory of the CLI on each amplifying file, and on files just inside each reader's
// cap (sanitizer builds shadow every byte, so only the plain build measures it). The bound
// is the issue's: 600 MB.
TEST(Hardening, AmplifyingAndAtTheCapFilesStayUnder600MegabytesInTheCli) {
  const fs::path dir = test::makeTempDir("amp_rss");
  writeAmplifyingAsfAmc(dir, 1024, 19512);
  writeAmplifyingBvh(dir / "amp.bvh", 2000, 5000);
  fs::create_directories(dir / "cap");
  writeAmplifyingAsfAmc(dir / "cap", 1024, 4800, 260);            // 1.3 MB: 4.9e6 point-frames
  writeAmplifyingBvh(dir / "cap" / "cap.bvh", 2000, 1240, 1000);  // 1.3 MB: 5.0e6
  writeLongCsv(dir / "cap" / "cap.csv", 330'000);                 // 5.0e6 point-frames
  for (const fs::path& file : {dir / "amp_01.amc", dir / "amp.bvh", dir / "cap" / "amp_01.amc",
                               dir / "cap" / "cap.bvh", dir / "cap" / "cap.csv"}) {
    const auto run = cli({"info", file.string()}, dir);
    expectCleanExit(run);
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_LT(run.peakRssKb, 600 * 1024) << file << ": peak " << run.peakRssKb / 1024 << " MB";
    const bool atCap = file.parent_path().filename() == "cap";
    EXPECT_EQ(run.output.find("point-frames") == std::string::npos, atCap) << run.output;
    RecordProperty((atCap ? "cap_" : "") + file.filename().string() + "_peak_rss_kb",
                   std::to_string(run.peakRssKb));
  }
  if (!HasFailure()) fs::remove_all(dir);  // 40 MB of files
}
#endif

// [SECTION] Paths

TEST(Hardening, AFolderNamedLikeATrialIsReportedAsAFolder) {
  const fs::path dir = test::makeTempDir("folder_c3d");
  fs::create_directories(dir / "walk.c3d");
  const auto run = cli({"info", (dir / "walk.c3d").string()}, dir);
  expectCleanExit(run);
  EXPECT_EQ(run.exitCode, 1);
  EXPECT_NE(run.output.find("is a folder"), std::string::npos) << run.output;
}

// [SECTION] Stages after the readers

TEST(Hardening, EmptyAndSingleFrameInputsAreTypedErrorsAtEveryStage) {
  JointTrial t;
  t.file = "empty.csv";
  t.rateHz = 100.0;
  t.positionsMm.resize(0, kDims3);
  EXPECT_THROW(prepareWalkingTrial(t), Error);
  t.positionsMm = Eigen::MatrixXd::Zero(1, kDims3);
  EXPECT_THROW(prepareWalkingTrial(t), Error);
  Eigen::MatrixXd none(0, kDims3);
  EXPECT_THROW(placeOnFloor(none), Error);
  EXPECT_THROW(detectUpAxis(none), Error);
  EXPECT_THROW(removeProgression(none, 100.0), Error);
  EXPECT_THROW(detectGaitCycles(none, 100.0, {}, "empty"), Error);
  EXPECT_TRUE(footStrikesFromKinematics(none, 100.0, Side::Left).empty());
  const SteadyWindow w = detectSteadyWindow(none, 100.0);
  EXPECT_EQ(w.end - w.begin, 0);
}

TEST(Hardening, NanAndInfinityEverywhereAreTypedErrors) {
  JointTrial t = test::analyticWalkTrial({});
  t.positionsMm.setConstant(std::numeric_limits<double>::quiet_NaN());
  EXPECT_THROW(prepareWalkingTrial(t), Error);
  t.positionsMm.setConstant(std::numeric_limits<double>::infinity());
  EXPECT_THROW(prepareWalkingTrial(t), Error);
  t = test::analyticWalkTrial({});
  t.rateHz = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(prepareWalkingTrial(t), Error);
  t.rateHz = 1e300;
  EXPECT_THROW(prepareWalkingTrial(t), Error);
}

TEST(Hardening, ACoordinateOfAHundredKilometresIsAGlitchNotANumber) {
  test::AnalyticGait g;
  JointTrial t = test::analyticWalkTrial(g);
  const WalkingTrial clean = prepareWalkingTrial(t);
  t.positionsMm(40, 3 * index(Joint::RAnkle) + 2) = 1e200;  // squares to infinity
  const WalkingTrial w = prepareWalkingTrial(t);
  EXPECT_TRUE(w.joints.positionsMm.allFinite());
  EXPECT_NEAR(w.cycles.strideHz, clean.cycles.strideHz, 1e-6);
}

}  // namespace
}  // namespace ew
