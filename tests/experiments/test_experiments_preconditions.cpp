// Issue 11: the experiments check their own preconditions — too few walkers, non-finite
// angles and σ², noise levels and joint sets, folds that do not belong to the walkers —
// and fail with a typed ew::Error naming the stage ("evaluation: …", "σ² sweep: …",
// "noise: …"); the 2D view CSV, the plots and the results folder likewise. A walker whose
// frames cannot be fitted is skipped with a warning, not the end of the evaluation. One
// test per precondition.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <string_view>

#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/synthetic_walkers.h"
#include "core/experiments/experiments.h"
#include "core/experiments/results_folder.h"
#include "core/experiments/view_csv.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kOmega = 2.0 * std::numbers::pi * 0.9;
constexpr double kRateHz = 60.0;

using test::throwsError;

// `count` walkers of distinct subjects, each with 2 cycles of frames at 60 Hz.
std::vector<ExperimentWalker> walkers(int count) {
  const Eigen::MatrixXd w = syntheticWalkerSet(count, 12);
  std::vector<ExperimentWalker> out;
  for (int i = 0; i < count; ++i) {
    ExperimentWalker e;
    e.subject = "S" + std::to_string(i);
    e.id = e.subject + "/walk";
    e.source = "synthetic";
    e.fit.w = w.col(i);
    e.fit.omegaRadS = kOmega;
    e.rateHz = kRateHz;
    e.framesMm = synthesizeFrames(w.col(i), kOmega, 0.0, frameTimes(2 * 67, kRateHz));
    out.push_back(e);
  }
  return out;
}

EvaluationOptions options() {
  EvaluationOptions o;
  o.anglesDeg = {0.0, 45.0};
  o.sigma2GridMm2 = {10.0, 100.0};
  o.noiseLevelsMm = {0.0, 10.0};
  o.missingJointSets = {{"l_wrist", {8}}};
  o.model.components = 2;
  return o;
}

// [SECTION] The evaluation and its experiments

// Too few walkers is the data's fault (the CLI's exit 1), not a usage error (exit 2).
TEST(EvaluationPreconditions, FewerThanTwoWalkersIsBadData) {
  const auto two = walkers(2);
  for (const long count : {0L, 1L}) {
    const std::vector<ExperimentWalker> few(two.begin(), two.begin() + count);
    EXPECT_TRUE(throwsError(
        [&] { runEvaluation(few, {Experiment::Variance}, options()); }, ErrorKind::BadData,
        {"evaluation: a model needs at least 2 walkers, got " + std::to_string(count)}))
        << count;
  }
}

TEST(EvaluationPreconditions, ViewAnglesMustBeFinite) {
  for (const double a : {kNaN, kInf}) {
    EvaluationOptions o = options();
    o.anglesDeg = {0.0, a};
    EXPECT_TRUE(throwsError([&] { runEvaluation(walkers(4), {Experiment::KnownView}, o); },
                            ErrorKind::BadArgument, {"evaluation: view angles must be finite"}))
        << a;
  }
}

TEST(EvaluationPreconditions, AGivenSigma2MustBeFiniteAndNonNegative) {
  for (const double s2 : {kNaN, kInf, -5.0}) {
    EvaluationOptions o = options();
    o.sigma2Mm2 = s2;
    EXPECT_TRUE(throwsError([&] { runEvaluation(walkers(4), {Experiment::KnownView}, o); },
                            ErrorKind::BadArgument, {"evaluation: σ² must be finite and ≥ 0 mm²"}))
        << s2;
  }
}

// The sweep is read on a log axis: σ² = 0 there made the plot's tick loop spin forever.
TEST(EvaluationPreconditions, TheSigma2GridMustBePositiveFiniteAndNotEmpty) {
  const auto ws = walkers(4);
  const auto folds = buildFolds(ws, options().model, 1);
  for (const double s2 : {0.0, -10.0, kNaN, kInf}) {
    EvaluationOptions o = options();
    o.sigma2GridMm2 = {10.0, s2};
    EXPECT_TRUE(throwsError([&] { sigmaSweep(ws, folds, o); }, ErrorKind::BadArgument,
                            {"σ² sweep: grid values must be positive and finite"}))
        << s2;
  }
  EvaluationOptions empty = options();
  empty.sigma2GridMm2.clear();
  EXPECT_TRUE(throwsError([&] { sigmaSweep(ws, folds, empty); }, ErrorKind::BadArgument,
                          {"σ² sweep: the σ² grid is empty"}));
}

// With no folds the sweep reported a zero error for every σ² (a mean over no cells).
TEST(EvaluationPreconditions, TheSweepNeedsFolds) {
  EXPECT_TRUE(throwsError([] { sigmaSweep(walkers(4), {}, options()); }, ErrorKind::BadArgument,
                          {"σ² sweep: no folds to evaluate"}));
}

// Folds built from a longer walker list indexed past the end of a shorter one.
TEST(EvaluationPreconditions, FoldsMustIndexTheWalkersGiven) {
  const auto folds = buildFolds(walkers(5), options().model, 1);
  const auto fewer = walkers(3);
  std::vector<std::string> warnings;
  EXPECT_TRUE(
      throwsError([&] { knownViewErrors(fewer, folds, options(), 70.0); }, ErrorKind::BadArgument,
                  {"known view: fold 'S3' names walker 3 of 3: folds and walkers do not match"}));
  EXPECT_TRUE(throwsError([&] { unknownViewErrors(fewer, folds, options(), 70.0); },
                          ErrorKind::BadArgument, {"unknown view: fold 'S3'"}));
  EXPECT_TRUE(throwsError([&] { noiseErrors(fewer, folds, options(), 70.0, warnings); },
                          ErrorKind::BadArgument, {"noise: fold 'S3'"}));
  EXPECT_TRUE(throwsError([&] { missingJointErrors(fewer, folds, options(), 70.0); },
                          ErrorKind::BadArgument, {"missing joints: fold 'S3'"}));
  EXPECT_TRUE(throwsError([&] { sigmaSweep(fewer, folds, options()); }, ErrorKind::BadArgument,
                          {"σ² sweep: fold 'S3'"}));
}

TEST(EvaluationPreconditions, NoiseLevelsMustBeFiniteAndNonNegative) {
  const auto ws = walkers(4);
  const auto folds = buildFolds(ws, options().model, 1);
  for (const double level : {-1.0, kNaN, kInf}) {
    EvaluationOptions o = options();
    o.noiseLevelsMm = {0.0, level};
    std::vector<std::string> warnings;
    EXPECT_TRUE(throwsError([&] { noiseErrors(ws, folds, o, 70.0, warnings); },
                            ErrorKind::BadArgument,
                            {"noise: noise levels must be finite and ≥ 0 mm"}))
        << level;
  }
}

// The reference fit of a walker's frames failing (here: 20 frames, a third of a cycle)
// ended the whole evaluation; now that walker is skipped with a warning.
TEST(EvaluationPreconditions, AWalkerWhoseFramesCannotBeFittedIsSkippedWithAWarning) {
  auto ws = walkers(4);
  ws[1].framesMm = ws[1].framesMm.topRows(20).eval();
  const auto folds = buildFolds(ws, options().model, 1);
  std::vector<std::string> warnings;
  const auto rows = noiseErrors(ws, folds, options(), 70.0, warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("noise: walker S1/walk: its frames cannot be fitted"),
            std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("less than one gait cycle"), std::string::npos) << warnings[0];
  EXPECT_EQ(rows.size(), 3u * 2u * 2u * 2u);  // 3 walkers × 2 angles × 2 levels × 2 methods
  for (const auto& r : rows) EXPECT_NE(r.subject, "S1");
}

TEST(EvaluationPreconditions, MissingJointSetsAreCheckedAndNamed) {
  const auto ws = walkers(4);
  const auto folds = buildFolds(ws, options().model, 1);
  EvaluationOptions o = options();
  o.missingJointSets = {{"l_wrist", {8}}, {"sixteenth", {3, 15}}};
  EXPECT_TRUE(throwsError([&] { missingJointErrors(ws, folds, o, 70.0); }, ErrorKind::BadArgument,
                          {"missing joints: set 'sixteenth' has joint index 15 (0…14)"}));
  JointSet all{"everything", {}};
  for (int j = 0; j < 15; ++j) all.joints.push_back(j);
  all.joints.push_back(0);  // a repeat does not make it more than every joint
  o.missingJointSets = {all};
  EXPECT_TRUE(throwsError([&] { missingJointErrors(ws, folds, o, 70.0); }, ErrorKind::BadArgument,
                          {"missing joints: set 'everything' hides every joint"}));
}

// A fit that is not 3D: the column assignment is unchecked in a release build.
TEST(EvaluationPreconditions, AWalkerWithoutA3DFitIsNamed) {
  auto ws = walkers(3);
  ws[2].fit.w = Eigen::VectorXd();
  EXPECT_TRUE(throwsError(
      [&] { experimentWalkerMatrix(ws); }, ErrorKind::BadArgument,
      {"leave-one-subject-out: walker 'S2/walk' has 0 Fourier values, a 3D fit has 225"}));
  EXPECT_TRUE(
      throwsError([&] { buildFullModel(ws); }, ErrorKind::BadArgument, {"walker 'S2/walk'"}));
}

// [SECTION] The 2D view CSV

std::string viewCsv(const std::string& comment, const std::vector<std::string>& times) {
  std::string text = comment.empty() ? "" : comment + "\n";
  text += viewCsvHeader() + "\n";
  for (size_t i = 0; i < times.size(); ++i) {
    text += std::to_string(i) + "," + times[i];
    for (int c = 0; c < 30; ++c) text += ",1";
    text += "\n";
  }
  return text;
}

TEST(ViewCsvPreconditions, AStatedRateMustBePlausible) {
  for (const char* rate : {"nan", "inf", "0", "-60", "1e300", "0.001"}) {
    EXPECT_TRUE(throwsError(
        [&] {
          parseViewCsv(viewCsv(std::string("# rate_hz=") + rate, {"0", "1"}), "v.csv");
        },
        ErrorKind::Malformed, {"v.csv: line 1: rate_hz=", "is outside the plausible 1-10000 Hz"}))
        << rate;
  }
}

// Without a stated rate the time column gives it: a missing time there made
// nth_element compare NaNs (its ordering then undefined).
TEST(ViewCsvPreconditions, AMissingTimeWithoutAStatedRateNamesItsLine) {
  EXPECT_TRUE(throwsError(
      [] {
        parseViewCsv(viewCsv("", {"0", "0.01", "", "0.03"}), "v.csv");
      },
      ErrorKind::BadData, {"v.csv: line 4: time_s is missing"}));
  EXPECT_TRUE(throwsError(
      [] {
        parseViewCsv(viewCsv("", {"0", "nan", "0.02"}), "v.csv");
      },
      ErrorKind::BadData, {"v.csv: line 3: time_s is missing"}));
  // With a stated rate the time column is not used: gaps there are fine.
  EXPECT_EQ(parseViewCsv(viewCsv("# rate_hz=100", {"0", "", "0.02"}), "v.csv").rateHz, 100.0);
}

TEST(ViewCsvPreconditions, TimesInMillisecondsGiveAnImplausibleRate) {
  EXPECT_TRUE(throwsError(
      [] {
        parseViewCsv(viewCsv("", {"0", "16.7", "33.3", "50"}), "ms.csv");
      },
      ErrorKind::BadData, {"ms.csv: time_s: the times give a frame rate of", "milliseconds"}));
}

TEST(ViewCsvPreconditions, WritingNeedsAFiniteRate) {
  const fs::path dir = test::makeTempDir("view_csv_preconditions");
  for (const double rate : {kInf, kNaN, 0.0}) {
    EXPECT_TRUE(throwsError(
        [&] {
          writeViewCsv(dir / "v.csv", {Eigen::MatrixXd::Zero(3, 30), rate});
        },
        ErrorKind::BadArgument, {"v.csv", "a positive rate"}))
        << rate;
  }
  EXPECT_FALSE(fs::exists(dir / "v.csv"));
  fs::remove_all(dir);
}

// [SECTION] Plots and the results folder

TEST(ResultsFolderPreconditions, ThePathMustEndInAFolderName) {
  EvaluationResults r;
  for (const char* dir : {"", ".", "a/..", "a/b/../.."}) {
    EXPECT_TRUE(throwsError(
        [&] {
          writeResultsFolder(dir, r, {}, {});
        },
        ErrorKind::BadArgument, {"results folder: the path must end in a folder name"}))
        << dir;
  }
}

}  // namespace
}  // namespace ew
