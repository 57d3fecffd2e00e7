// Issue 11: every engine stage checks its own preconditions and fails with a typed
// ew::Error whose message names the stage ("Fourier fit: …", "model: …",
// "reconstruction: …") and, where one is known, the file or the walker. Empty inputs,
// single frames, non-finite values, zero or negative rates and frequencies, mismatched
// sizes and absurd counts are each rejected on purpose: a typed error, never a NaN result,
// a crash or a hang. One test per precondition.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string_view>

#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/minimize_1d.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/model_file.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/eigenwalker/synthetic_walkers.h"
#include "core/eigenwalker/walker_set.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kOmega = 2.0 * std::numbers::pi * 0.9;  // rad/s
constexpr double kRateHz = 120.0;

// [SECTION] Helpers

using test::throwsError;

// `seconds` of the synthetic base walker at `rateHz` (T × 45, mm).
Eigen::MatrixXd walkFrames(double rateHz = kRateHz, double seconds = 3.0) {
  const int n = static_cast<int>(std::lround(seconds * rateHz));
  return synthesizeFrames(syntheticBaseWalker(), kOmega, 0.0, frameTimes(n, rateHz));
}

FourierFitOptions named(const std::string& file) {
  FourierFitOptions o;
  o.file = file;
  return o;
}

struct Population {
  Eigen::MatrixXd w;
  std::vector<std::string> ids, subjects;
  Eigen::VectorXd omegas;
};

Population population(int r) {
  Population p{syntheticWalkerSet(r, 3), {}, {}, Eigen::VectorXd::Constant(r, 6.0)};
  for (int i = 0; i < r; ++i) {
    p.subjects.push_back("S" + std::to_string(i));
    p.ids.push_back(p.subjects.back() + "/walk");
  }
  return p;
}

EigenwalkerModel smallModel() {
  const Population p = population(8);
  return buildModel(p.w, p.ids, p.subjects, p.omegas);
}

Eigen::VectorXd observedAt(double alphaDeg) {
  return projectToView(syntheticWalkerSet(1, 77).col(0), alphaDeg);
}

// [SECTION] Fourier fit: frames

TEST(FourierFitPreconditions, NoFramesIsBadDataNamingTheFile) {
  EXPECT_TRUE(throwsError([] { fitFourier(Eigen::MatrixXd(0, 45), kRateHz, named("empty.c3d")); },
                          ErrorKind::BadData, {"empty.c3d", "Fourier fit: no frames"}));
}

TEST(FourierFitPreconditions, ASingleFrameIsTooFew) {
  EXPECT_TRUE(throwsError([] { fitFourier(walkFrames().topRows(1), kRateHz, named("one.trc")); },
                          ErrorKind::BadData,
                          {"one.trc", "Fourier fit:", "too few frames", "1 complete"}));
}

TEST(FourierFitPreconditions, ColumnsOtherThan45Or30AreACallerMistake) {
  EXPECT_TRUE(throwsError([] { fitFourier(walkFrames().leftCols(44), kRateHz, named("w.csv")); },
                          ErrorKind::BadArgument, {"w.csv", "Fourier fit:", "got 44"}));
}

TEST(FourierFitPreconditions, RateMustBePositiveAndFinite) {
  const Eigen::MatrixXd frames = walkFrames();
  for (const double rate : {0.0, -120.0, kNaN, kInf}) {
    EXPECT_TRUE(throwsError([&] { fitFourier(frames, rate, named("rate.csv")); },
                            ErrorKind::BadArgument,
                            {"rate.csv", "Fourier fit: frame rate must be positive and finite"}))
        << rate;
  }
}

TEST(FourierFitPreconditions, AllFramesMissingIsBadData) {
  const Eigen::MatrixXd frames = Eigen::MatrixXd::Constant(300, 45, kNaN);
  EXPECT_TRUE(throwsError([&] { fitFourier(frames, kRateHz, named("gaps.c3d")); },
                          ErrorKind::BadData,
                          {"gaps.c3d", "Fourier fit: 300 of 300 frames have missing values"}));
}

// An infinite sample is a missing sample: its frame is dropped, the fit stays finite.
TEST(FourierFitPreconditions, AnInfiniteSampleDropsItsFrameNotTheFit) {
  Eigen::MatrixXd frames = walkFrames();
  frames(17, 4) = kInf;
  frames(90, 30) = -kInf;
  const FourierFit fit = fitFourier(frames, kRateHz);
  EXPECT_EQ(fit.framesDropped, 2);
  EXPECT_TRUE(fit.w.allFinite());
  EXPECT_NEAR(fit.omegaRadS, kOmega, 1e-6 * kOmega);
}

// Coordinates whose squares overflow: today's scan finds no peak and reads past an empty
// list; now a typed error.
TEST(FourierFitPreconditions, CoordinatesWhoseSquaresOverflowAreBadData) {
  const Eigen::MatrixXd frames = walkFrames() * 1e160;
  EXPECT_TRUE(throwsError([&] { fitFourier(frames, kRateHz, named("huge.c3d")); },
                          ErrorKind::BadData, {"huge.c3d", "Fourier fit: coordinates too large"}));
}

// Sampling at or below 4 × the stride frequency aliases the second harmonic: the normal
// equations are singular and the aliased coefficients came back as silent zeros.
TEST(FourierFitPreconditions, ARateThatAliasesTheSecondHarmonicIsBadData) {
  const double strideHz = 2.0, rateHz = 8.0;  // 2ω·Δt = π: sin 2ωt vanishes at every frame
  const Eigen::MatrixXd frames = synthesizeFrames(
      syntheticBaseWalker(), 2.0 * std::numbers::pi * strideHz, 0.0, frameTimes(40, rateHz));
  FourierFitOptions o = named("slow.csv");
  o.omegaFixedRadS = 2.0 * std::numbers::pi * strideHz;
  EXPECT_TRUE(throwsError([&] { fitFourier(frames, rateHz, o); }, ErrorKind::BadData,
                          {"slow.csv", "Fourier fit:", "cannot resolve the second harmonic"}));
}

// 100 frames at 0.001 Hz span a day: the ω grid would need millions of points.
TEST(FourierFitPreconditions, AScanGridBeyondItsCapIsRefusedBeforeAllocating) {
  const Eigen::MatrixXd frames = walkFrames(kRateHz, 100.0 / kRateHz);
  EXPECT_TRUE(throwsError([&] { fitFourier(frames, 1e-3, named("ms.csv")); }, ErrorKind::BadData,
                          {"ms.csv", "Fourier fit:", "frequency scan points"}));
}

// A rate so small that the duration overflows a double (the grid size cast was undefined).
TEST(FourierFitPreconditions, ADurationThatOverflowsIsBadData) {
  EXPECT_TRUE(throwsError([] { fitFourier(walkFrames(), 1e-307, named("tiny.csv")); },
                          ErrorKind::BadData,
                          {"tiny.csv", "Fourier fit:", "longer than a double holds"}));
}

// [SECTION] Fourier fit: options

TEST(FourierFitPreconditions, AFixedOmegaMustBePositiveAndFinite) {
  const Eigen::MatrixXd frames = walkFrames();
  for (const double omega : {kNaN, kInf, 0.0, -kOmega}) {
    FourierFitOptions o = named("fixed.c3d");
    o.omegaFixedRadS = omega;
    EXPECT_TRUE(throwsError([&] { fitFourier(frames, kRateHz, o); }, ErrorKind::BadArgument,
                            {"fixed.c3d", "Fourier fit: the fixed ω must be positive and finite"}))
        << omega;
  }
}

TEST(FourierFitPreconditions, AnOmegaHintMustBePositiveAndFinite) {
  const Eigen::MatrixXd frames = walkFrames();
  for (const double omega : {kNaN, kInf, 0.0, -kOmega}) {
    FourierFitOptions o = named("hint.c3d");
    o.omegaHintRadS = omega;
    EXPECT_TRUE(throwsError([&] { fitFourier(frames, kRateHz, o); }, ErrorKind::BadArgument,
                            {"hint.c3d", "Fourier fit: the ω hint must be positive and finite"}))
        << omega;
  }
}

TEST(FourierFitPreconditions, TheScanRangeMustBeOrderedPositiveAndFinite) {
  const Eigen::MatrixXd frames = walkFrames();
  const std::pair<double, double> ranges[] = {
      {6.0, 3.0}, {0.0, 10.0}, {kNaN, 10.0}, {2.0, kInf}, {2.0, kNaN}};
  for (const auto& [lo, hi] : ranges) {
    FourierFitOptions o = named("range.c3d");
    o.omegaMinRadS = lo;
    o.omegaMaxRadS = hi;
    EXPECT_TRUE(throwsError([&] { fitFourier(frames, kRateHz, o); }, ErrorKind::BadArgument,
                            {"range.c3d", "Fourier fit: the ω scan range"}))
        << lo << " " << hi;
  }
}

TEST(FourierFitPreconditions, TheMissingFractionMustBeAFraction) {
  const Eigen::MatrixXd frames = walkFrames();
  for (const double f : {-0.1, 1.5, kNaN}) {
    FourierFitOptions o = named("f.c3d");
    o.maxMissingFraction = f;
    EXPECT_TRUE(throwsError([&] { fitFourier(frames, kRateHz, o); }, ErrorKind::BadArgument,
                            {"f.c3d", "Fourier fit: the allowed missing fraction"}))
        << f;
  }
}

// [SECTION] Fourier synthesis, frame times, rephase

TEST(FourierSynthesisPreconditions, NonFiniteOmegaPhaseOrTimesAreRefusedNotSynthesisedAsNaN) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const Eigen::VectorXd t = frameTimes(10, kRateHz);
  EXPECT_TRUE(throwsError([&] { synthesizeFrames(w, kNaN, 0.0, t); }, ErrorKind::BadArgument,
                          {"Fourier synthesis: ω and φ must be finite"}));
  EXPECT_TRUE(throwsError([&] { synthesizeFrames(w, kOmega, kInf, t); }, ErrorKind::BadArgument,
                          {"Fourier synthesis: ω and φ must be finite"}));
  Eigen::VectorXd badTimes = t;
  badTimes(3) = kNaN;
  EXPECT_TRUE(throwsError([&] { synthesizeFrames(w, kOmega, 0.0, badTimes); },
                          ErrorKind::BadArgument, {"Fourier synthesis: the times must be finite"}));
}

TEST(FourierSynthesisPreconditions, ANonFiniteWalkerIsRefused) {
  Eigen::VectorXd w = syntheticBaseWalker();
  w(100) = kNaN;
  EXPECT_TRUE(throwsError([&] { synthesizeFrames(w, kOmega, 0.0, frameTimes(10, kRateHz)); },
                          ErrorKind::BadArgument, {"Fourier synthesis: w has non-finite values"}));
}

TEST(FourierSynthesisPreconditions, FrameTimesNeedACountAndAPositiveRate) {
  EXPECT_TRUE(throwsError([] { frameTimes(-1, kRateHz); }, ErrorKind::BadArgument,
                          {"frame times: the frame count must be ≥ 0, got -1"}));
  for (const double rate : {0.0, -1.0, kNaN, kInf}) {
    EXPECT_TRUE(throwsError([&] { frameTimes(10, rate); }, ErrorKind::BadArgument,
                            {"frame times: frame rate must be positive and finite"}))
        << rate;
  }
  // The boundaries that are fine: no frames, and one frame at t = 0.
  EXPECT_EQ(frameTimes(0, kRateHz).size(), 0);
  ASSERT_EQ(frameTimes(1, kRateHz).size(), 1);
  EXPECT_EQ(frameTimes(1, kRateHz)(0), 0.0);
}

TEST(FourierSynthesisPreconditions, RephaseNeedsAFourierVectorAndFinitePhases) {
  EXPECT_TRUE(throwsError([] { rephase(Eigen::VectorXd::Zero(7), 0.0, 1.0); },
                          ErrorKind::BadArgument,
                          {"rephase: w must have 225 or 150 values, got 7"}));
  EXPECT_TRUE(throwsError([] { rephase(syntheticBaseWalker(), kNaN, 1.0); }, ErrorKind::BadArgument,
                          {"rephase: phases must be finite"}));
}

// [SECTION] Model

TEST(ModelPreconditions, NoWalkersAndOneWalkerAreTooFew) {
  const Population p = population(3);
  EXPECT_TRUE(throwsError([&] { buildModel(p.w.leftCols(0), {}, {}, p.omegas.head(0)); },
                          ErrorKind::BadArgument,
                          {"model: a model needs at least 2 walkers, got 0"}));
  EXPECT_TRUE(throwsError([&] { buildModel(p.w.leftCols(1), {"a"}, {"a"}, p.omegas.head(1)); },
                          ErrorKind::BadArgument,
                          {"model: a model needs at least 2 walkers, got 1"}));
}

TEST(ModelPreconditions, MismatchedListsSayTheirSizes) {
  const Population p = population(4);
  EXPECT_TRUE(throwsError([&] { buildModel(p.w, p.ids, p.subjects, p.omegas.head(3)); },
                          ErrorKind::BadArgument,
                          {"model: walker ids, subjects and frequencies", "(4), got 4, 4 and 3"}));
}

TEST(ModelPreconditions, ANonFiniteCoefficientNamesItsWalker) {
  Population p = population(5);
  p.w(40, 3) = kNaN;
  EXPECT_TRUE(throwsError([&] { buildModel(p.w, p.ids, p.subjects, p.omegas); },
                          ErrorKind::BadArgument,
                          {"model: walker 'S3/walk' has non-finite Fourier coefficients"}));
}

TEST(ModelPreconditions, AStrideFrequencyMustBePositiveAndFinite) {
  for (const double omega : {kNaN, kInf, 0.0, -1.0}) {
    Population p = population(5);
    p.omegas(2) = omega;
    EXPECT_TRUE(
        throwsError([&] { buildModel(p.w, p.ids, p.subjects, p.omegas); }, ErrorKind::BadArgument,
                    {"model: walker 'S2/walk' has a non-positive or non-finite stride frequency"}))
        << omega;
  }
}

TEST(ModelPreconditions, TheVarianceThresholdMustBeAShare) {
  const Population p = population(5);
  for (const double share : {0.0, -0.5, 1.5, 95.0, kNaN}) {
    ModelOptions o;
    o.varianceThreshold = share;
    EXPECT_TRUE(throwsError([&] { buildModel(p.w, p.ids, p.subjects, p.omegas, o); },
                            ErrorKind::BadArgument,
                            {"model: the variance threshold must be in (0, 1]"}))
        << share;
  }
  ModelOptions all;
  all.varianceThreshold = 1.0;  // the boundary itself is fine: every direction
  EXPECT_EQ(buildModel(p.w, p.ids, p.subjects, p.omegas, all).componentCount(), 4);
}

TEST(ModelPreconditions, AtLeastOneComponent) {
  const Population p = population(5);
  ModelOptions o;
  o.components = 0;
  EXPECT_TRUE(throwsError([&] { buildModel(p.w, p.ids, p.subjects, p.omegas, o); },
                          ErrorKind::BadArgument,
                          {"model: the model needs at least one component, got 0"}));
}

TEST(ModelPreconditions, LeavingOutASubjectMustLeaveTwoWalkers) {
  Population p = population(3);
  p.subjects = {"A", "A", "B"};
  EXPECT_TRUE(throwsError([&] { buildModelWithoutSubject(p.w, p.ids, p.subjects, p.omegas, "A"); },
                          ErrorKind::BadArgument,
                          {"model: leaving out subject 'A' leaves 1 walker(s)"}));
  EXPECT_TRUE(throwsError([&] { buildModelWithoutSubject(p.w, p.ids, p.subjects, p.omegas, "Z"); },
                          ErrorKind::BadArgument, {"model: no walker of subject 'Z'"}));
}

TEST(ModelPreconditions, AnEmptyModelCannotSynthesiseOrProject) {
  const EigenwalkerModel empty;
  EXPECT_TRUE(throwsError([&] { synthesizeWalker(empty, Eigen::VectorXd()); },
                          ErrorKind::BadArgument,
                          {"model synthesis: the model is empty or inconsistent"}));
  EXPECT_TRUE(throwsError([&] { projectOntoModel(empty, syntheticBaseWalker()); },
                          ErrorKind::BadArgument,
                          {"model projection: the model is empty or inconsistent"}));
}

TEST(ModelPreconditions, NonFiniteCoefficientsOrWalkersAreRefusedNotPropagated) {
  const EigenwalkerModel m = smallModel();
  Eigen::VectorXd k = Eigen::VectorXd::Zero(m.componentCount());
  k(0) = kNaN;
  EXPECT_TRUE(throwsError([&] { synthesizeWalker(m, k); }, ErrorKind::BadArgument,
                          {"model: the coefficients k have non-finite values"}));
  Eigen::VectorXd w = syntheticBaseWalker();
  w(0) = kInf;
  EXPECT_TRUE(throwsError([&] { projectOntoModel(m, w); }, ErrorKind::BadArgument,
                          {"model: the walker vector has non-finite values"}));
  EXPECT_TRUE(throwsError([&] { projectOntoModel(m, Eigen::VectorXd::Zero(150)); },
                          ErrorKind::BadArgument,
                          {"model: walker vector must have 225 values, got 150"}));
}

// [SECTION] Walkers from a dataset

DatasetTrial syntheticTrial(const std::string& file, const Eigen::MatrixXd& frames,
                            double strideHz) {
  DatasetTrial t;
  t.info.file = file;
  t.info.subject = "S1";
  t.info.condition = "walk";
  t.info.source = "synthetic";
  t.trial.joints.file = file;
  t.trial.joints.rateHz = kRateHz;
  t.trial.joints.positionsMm = frames;
  t.trial.cycles.strideHz = strideHz;
  return t;
}

// Gait events that gave no usable frequency are not a hint (today an infinite stride
// frequency became one, and a warning about "inf Hz").
TEST(WalkerSetPreconditions, ANonFiniteStrideFrequencyIsNoHint) {
  for (const double strideHz : {kInf, kNaN, -0.9}) {
    Dataset d;
    d.trials.push_back(syntheticTrial("odd_events.c3d", walkFrames(), strideHz));
    std::vector<std::string> warnings;
    const auto walkers = makeWalkers(d, &warnings);
    ASSERT_EQ(walkers.size(), 1u) << strideHz;
    EXPECT_EQ(walkers[0].fit.omegaSource, "scan") << strideHz;
    EXPECT_TRUE(warnings.empty()) << warnings.front();
    EXPECT_TRUE(walkers[0].fit.warnings.empty()) << walkers[0].fit.warnings.front();
  }
}

// A walker averages 3D fits: a 2D trial is left out with a warning naming the file.
TEST(WalkerSetPreconditions, ATrialThatIsNot3DIsLeftOutWithAWarning) {
  Dataset d;
  d.trials.push_back(syntheticTrial("flat.csv", projectFramesToView(walkFrames(), 30.0), 0.9));
  std::vector<std::string> warnings;
  EXPECT_TRUE(makeWalkers(d, &warnings).empty());
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.front().find("flat.csv: walkers: the trial's joints have 30 columns"),
            std::string::npos)
      << warnings.front();
}

TEST(WalkerSetPreconditions, AModelOfNoWalkersOrOfA2DWalkerIsRefused) {
  EXPECT_TRUE(throwsError([] { buildModel(std::vector<Walker>{}); }, ErrorKind::BadArgument,
                          {"model: a model needs at least 2 walkers, got 0"}));
  std::vector<Walker> walkers(2);
  walkers[0].id = "A/walk";
  walkers[0].fit.w = syntheticBaseWalker();
  walkers[1].id = "B/walk";
  walkers[1].fit.w = Eigen::VectorXd::Zero(150);
  EXPECT_TRUE(throwsError([&] { walkerMatrix(walkers); }, ErrorKind::BadArgument,
                          {"model: walker 'B/walk' is not a 3D fit (150 values"}));
}

// [SECTION] Projection

TEST(ProjectionPreconditions, ANonFiniteViewAngleIsRefusedNotProjectedAsNaN) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const Eigen::MatrixXd frames = walkFrames();
  for (const double alpha : {kNaN, kInf, -kInf}) {
    EXPECT_TRUE(throwsError([&] { projectToView(w, alpha); }, ErrorKind::BadArgument,
                            {"projection: projectToView: the view angle must be finite"}));
    EXPECT_TRUE(throwsError([&] { depthAtView(w, alpha); }, ErrorKind::BadArgument,
                            {"projection: depthAtView: the view angle must be finite"}));
    EXPECT_TRUE(throwsError([&] { projectFramesToView(frames, alpha); }, ErrorKind::BadArgument,
                            {"projection: projectFramesToView: the view angle must be finite"}));
    EXPECT_TRUE(throwsError([&] { depthFramesAtView(frames, alpha); }, ErrorKind::BadArgument,
                            {"projection: depthFramesAtView: the view angle must be finite"}));
    EXPECT_TRUE(throwsError(
        [&] { composeFromView(projectToView(w, 0.0), depthAtView(w, 0.0), alpha); },
        ErrorKind::BadArgument, {"projection: composeFromView: the view angle must be finite"}));
    EXPECT_TRUE(throwsError([&] { projectionMatrix(alpha); }, ErrorKind::BadArgument,
                            {"projection: projectionMatrix: the view angle must be finite"}));
  }
}

TEST(ProjectionPreconditions, WrongShapesSayWhatTheyGot) {
  EXPECT_TRUE(throwsError([] { projectToView(Eigen::VectorXd::Zero(150), 0.0); },
                          ErrorKind::BadArgument,
                          {"projection: projectToView: expected 225 rows, got 150"}));
  EXPECT_TRUE(throwsError([] { depthFramesAtView(Eigen::MatrixXd::Zero(4, 30), 0.0); },
                          ErrorKind::BadArgument,
                          {"projection: depthFramesAtView needs T × 45 frames, got 30 columns"}));
}

// The boundary kept on purpose: a missing sample (NaN) stays missing, its neighbours and
// the other frames are projected as usual.
TEST(ProjectionPreconditions, MissingSamplesPassThroughAsMissing) {
  Eigen::MatrixXd frames = walkFrames().topRows(5);
  frames(2, 0) = kNaN;  // head x of frame 2
  const Eigen::MatrixXd uv = projectFramesToView(frames, 30.0);
  EXPECT_TRUE(std::isnan(uv(2, 0)));
  EXPECT_TRUE(std::isfinite(uv(2, 1)));
  EXPECT_TRUE(uv.row(1).allFinite());
}

// [SECTION] Reconstruction

TEST(ReconstructionPreconditions, AnEmptyOrInconsistentModelIsRefused) {
  EXPECT_TRUE(throwsError([] { precomputeModelGram(EigenwalkerModel{}); }, ErrorKind::BadArgument,
                          {"reconstruction: the model is empty or inconsistent"}));
  EigenwalkerModel m = smallModel();
  m.eigenvalues.conservativeResize(m.eigenvalues.size() - 1);
  EXPECT_TRUE(throwsError([&] { precomputeModelGram(m); }, ErrorKind::BadArgument,
                          {"reconstruction: the model is empty or inconsistent"}));
}

// Today a NaN in the model gave a NaN reconstruction; a negative eigenvalue an infinite
// prior and NaN MAP coefficients.
TEST(ReconstructionPreconditions, ANonFiniteModelOrANegativeEigenvalueIsRefused) {
  EigenwalkerModel m = smallModel();
  m.mean(7) = kNaN;
  EXPECT_TRUE(throwsError([&] { precomputeModelGram(m); }, ErrorKind::BadArgument,
                          {"reconstruction: the model has non-finite values"}));
  m = smallModel();
  m.eigenwalkers(3, 1) = kInf;
  EXPECT_TRUE(throwsError([&] { precomputeModelGram(m); }, ErrorKind::BadArgument,
                          {"reconstruction: the model has non-finite values"}));
  m = smallModel();
  m.eigenvalues.setConstant(-1.0);
  EXPECT_TRUE(throwsError([&] { precomputeModelGram(m); }, ErrorKind::BadArgument,
                          {"reconstruction: the model has a negative eigenvalue"}));
}

TEST(ReconstructionPreconditions, MissingJointsMustBeJointsAndNotAll) {
  const EigenwalkerModel m = smallModel();
  EXPECT_TRUE(throwsError([&] { precomputeModelGram(m, {15}); }, ErrorKind::BadArgument,
                          {"reconstruction: missing joint index out of range: 15"}));
  EXPECT_TRUE(throwsError([&] { precomputeModelGram(m, {-1}); }, ErrorKind::BadArgument,
                          {"reconstruction: missing joint index out of range: -1"}));
  std::vector<int> all;
  for (int j = 0; j < kJointCount; ++j) all.push_back(j);
  EXPECT_TRUE(throwsError([&] { precomputeModelGram(m, all); }, ErrorKind::BadArgument,
                          {"reconstruction: every joint is marked missing"}));
}

// A default ModelGram (never precomputed) used to fail deep in the projection with a
// message about 0 rows; now it says what is wrong.
TEST(ReconstructionPreconditions, AGramThatWasNeverPrecomputedIsRefused) {
  const ModelGram empty;
  EXPECT_TRUE(throwsError([&] { reconstructLsq(empty, observedAt(0.0), 0.0); },
                          ErrorKind::BadArgument,
                          {"reconstruction: the model Gram is empty or inconsistent"}));
  EXPECT_TRUE(throwsError([&] { searchViewAngle(empty, observedAt(0.0)); }, ErrorKind::BadArgument,
                          {"reconstruction: the model Gram is empty or inconsistent"}));
}

TEST(ReconstructionPreconditions, The2DVectorMustHave150Values) {
  const ModelGram gram = precomputeModelGram(smallModel());
  EXPECT_TRUE(throwsError(
      [&] { reconstructLsq(gram, Eigen::VectorXd::Zero(149), 0.0); }, ErrorKind::BadArgument,
      {"reconstruction: observed 2D Fourier vector must have 150 values, got 149"}));
  EXPECT_TRUE(
      throwsError([&] { reconstructLsq(gram, Eigen::VectorXd(), 0.0); }, ErrorKind::BadArgument,
                  {"reconstruction: observed 2D Fourier vector must have 150 values, got 0"}));
}

TEST(ReconstructionPreconditions, NaNAtAnObservedJointIsRefusedAtAMissingJointIgnored) {
  const EigenwalkerModel m = smallModel();
  Eigen::VectorXd obs = observedAt(30.0);
  obs(2 * index(Joint::LWrist)) = kNaN;  // p0, l_wrist u
  EXPECT_TRUE(throwsError([&] { reconstructLsq(precomputeModelGram(m), obs, 30.0); },
                          ErrorKind::BadArgument,
                          {"reconstruction: observed 2D Fourier vector has non-finite values at "
                           "joints not marked missing"}));
  const Reconstruction rec =
      reconstructLsq(precomputeModelGram(m, {index(Joint::LWrist)}), obs, 30.0);
  EXPECT_TRUE(rec.w.allFinite());
  EXPECT_TRUE(rec.wDataPreserving.allFinite());
}

TEST(ReconstructionPreconditions, ANonFiniteViewAngleIsRefusedNotReconstructedAsNaN) {
  const ModelGram gram = precomputeModelGram(smallModel());
  const Eigen::VectorXd obs = observedAt(30.0);
  for (const double alpha : {kNaN, kInf}) {
    EXPECT_TRUE(throwsError([&] { reconstructLsq(gram, obs, alpha); }, ErrorKind::BadArgument,
                            {"reconstruction: the view angle must be finite"}));
    EXPECT_TRUE(throwsError([&] { reconstructMap(gram, obs, alpha, 70.0); }, ErrorKind::BadArgument,
                            {"reconstruction: the view angle must be finite"}));
  }
  Eigen::VectorXd alphas = Eigen::VectorXd::LinSpaced(5, -90, 90);
  alphas(2) = kNaN;
  EXPECT_TRUE(throwsError([&] { viewObjective(gram, obs, alphas); }, ErrorKind::BadArgument,
                          {"reconstruction: view objective: the angles must be finite"}));
}

TEST(ReconstructionPreconditions, MapSigma2MustBeFiniteAndNonNegative) {
  const ModelGram gram = precomputeModelGram(smallModel());
  const Eigen::VectorXd obs = observedAt(30.0);
  for (const double s2 : {-1.0, kNaN, kInf}) {
    EXPECT_TRUE(throwsError([&] { reconstructMap(gram, obs, 30.0, s2); }, ErrorKind::BadArgument,
                            {"reconstruction: MAP needs a finite σ² ≥ 0 mm²"}))
        << s2;
    EXPECT_TRUE(throwsError(
        [&] {
          searchViewAngle(gram, obs, {Estimator::Map, s2});
        },
        ErrorKind::BadArgument, {"reconstruction: MAP needs a finite σ² ≥ 0 mm²"}))
        << s2;
  }
  EXPECT_TRUE(reconstructMap(gram, obs, 30.0, 0.0).w.allFinite());  // σ² = 0 is LSQ
}

// Finite but enormous image coordinates overflow J: a typed error, not an infinite
// objective or NaN coefficients.
TEST(ReconstructionPreconditions, CoordinatesWhoseSquaresOverflowAreBadData) {
  const ModelGram gram = precomputeModelGram(smallModel());
  const Eigen::VectorXd obs = observedAt(30.0) * 1e170;
  EXPECT_TRUE(throwsError([&] { reconstructLsq(gram, obs, 30.0); }, ErrorKind::BadData,
                          {"reconstruction: observed 2D coordinates too large"}));
  EXPECT_TRUE(throwsError([&] { searchViewAngle(gram, obs); }, ErrorKind::BadData,
                          {"reconstruction: observed 2D coordinates too large"}));
}

TEST(ReconstructionPreconditions, ViewSearchOptionsAreBounded) {
  const ModelGram gram = precomputeModelGram(smallModel());
  const Eigen::VectorXd obs = observedAt(30.0);
  // A step of 1e-9° asked for 3.6e11 grid points (an int overflow, then the allocation).
  for (const double step : {0.0, 1e-9, 45.0, kNaN}) {
    ViewSearchOptions o;
    o.coarseStepDeg = step;
    EXPECT_TRUE(
        throwsError([&] { searchViewAngle(gram, obs, {}, o); }, ErrorKind::BadArgument,
                    {"reconstruction: view search: the coarse step must be in [0.001°, 30°]"}))
        << step;
  }
  for (const double tol : {0.0, -1.0, kNaN, kInf}) {
    ViewSearchOptions o;
    o.toleranceDeg = tol;
    EXPECT_TRUE(
        throwsError([&] { searchViewAngle(gram, obs, {}, o); }, ErrorKind::BadArgument,
                    {"reconstruction: view search: the tolerance must be positive and finite"}))
        << tol;
  }
  ViewSearchOptions o;
  o.relationToleranceDeg = -5.0;
  EXPECT_TRUE(throwsError([&] { searchViewAngle(gram, obs, {}, o); }, ErrorKind::BadArgument,
                          {"reconstruction: view search: the relation tolerance"}));
}

// [SECTION] Error measures

TEST(MetricsPreconditions, NonFiniteWalkersAreRefusedNotScoredAsNaN) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  Eigen::VectorXd bad = w;
  bad(30) = kNaN;
  EXPECT_TRUE(throwsError([&] { depthErrors(w, bad, 30.0); }, ErrorKind::BadArgument,
                          {"error measures: reconstruction has non-finite values"}));
  EXPECT_TRUE(throwsError([&] { depthErrors(bad, w, 30.0); }, ErrorKind::BadArgument,
                          {"error measures: true walker has non-finite values"}));
  EXPECT_TRUE(throwsError([&] { mpjpe(w, bad); }, ErrorKind::BadArgument,
                          {"error measures: reconstruction has non-finite values"}));
  EXPECT_TRUE(throwsError([&] { depthVarianceMm2(bad, 0.0); }, ErrorKind::BadArgument,
                          {"error measures: true walker has non-finite values"}));
  EXPECT_TRUE(throwsError([&] { depthErrors(w, w, kNaN); }, ErrorKind::BadArgument,
                          {"the view angle must be finite"}));
}

TEST(MetricsPreconditions, FrameErrorsNeedAPositiveFiniteRate) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  const Eigen::MatrixXd frames = walkFrames();
  for (const double rate : {0.0, -1.0, kNaN, kInf}) {
    EXPECT_TRUE(throwsError([&] { depthErrorsFrames(frames, rate, w, kOmega, 0.0, 30.0); },
                            ErrorKind::BadArgument,
                            {"error measures: frame rate must be positive and finite"}))
        << rate;
    EXPECT_TRUE(throwsError([&] { mpjpeFrames(frames, rate, w, kOmega, 0.0); },
                            ErrorKind::BadArgument,
                            {"error measures: frame rate must be positive and finite"}))
        << rate;
  }
}

// σ_m² against frames is a temporal variance: one complete frame has none, and E_r was 0/0.
TEST(MetricsPreconditions, DepthErrorsAgainstFramesNeedTwoCompleteFrames) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  Eigen::MatrixXd frames = walkFrames().topRows(3);
  frames(0, 0) = kNaN;
  frames(2, 5) = kNaN;
  EXPECT_TRUE(throwsError(
      [&] { depthErrorsFrames(frames, kRateHz, w, kOmega, 0.0, 30.0); }, ErrorKind::BadData,
      {"error measures: depth errors against frames need at least 2 complete frames"}));
  // MPJPE is a plain mean: one complete frame is enough.
  EXPECT_TRUE(std::isfinite(mpjpeFrames(frames, kRateHz, w, kOmega, 0.0)));
}

TEST(MetricsPreconditions, NoCompleteFrameOrNoFrameIsBadData) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  EXPECT_TRUE(throwsError([&] { mpjpeFrames(Eigen::MatrixXd(0, 45), kRateHz, w, kOmega, 0.0); },
                          ErrorKind::BadData,
                          {"error measures: no complete frame to compare with (of 0)"}));
  EXPECT_TRUE(throwsError(
      [&] { mpjpeFrames(Eigen::MatrixXd::Constant(4, 45, kNaN), kRateHz, w, kOmega, 0.0); },
      ErrorKind::BadData, {"error measures: no complete frame to compare with (of 4)"}));
}

// A sample count of INT_MAX asked for 720 GB of frames (std::bad_alloc, not ew::Error).
TEST(MetricsPreconditions, MpjpeSamplesAreBounded) {
  const Eigen::VectorXd w = syntheticBaseWalker();
  for (const int samples : {0, -3, std::numeric_limits<int>::max()}) {
    EXPECT_TRUE(throwsError([&] { mpjpe(w, w, samples); }, ErrorKind::BadArgument,
                            {"error measures: MPJPE needs 1 to 100000 samples"}))
        << samples;
  }
}

TEST(MetricsPreconditions, TheViewAngleErrorOfNonFiniteAnglesIsRefused) {
  EXPECT_TRUE(throwsError([] { viewAngleErrorDeg(kNaN, 30.0); }, ErrorKind::BadArgument,
                          {"error measures: view angle error of non-finite angles"}));
  EXPECT_TRUE(throwsError([] { viewAngleErrorDeg(30.0, kInf); }, ErrorKind::BadArgument,
                          {"error measures: view angle error of non-finite angles"}));
}

// [SECTION] Synthetic walkers and the 1-D minimiser

// INT_MAX walkers asked for 3.6 TB (std::bad_alloc, not ew::Error).
TEST(SyntheticWalkersPreconditions, TheCountIsBounded) {
  for (const int count : {0, -1, 100'001, std::numeric_limits<int>::max()}) {
    EXPECT_TRUE(throwsError([&] { syntheticWalkerSet(count, 1); }, ErrorKind::BadArgument,
                            {"synthetic walkers: the count must be in [1, 100000]"}))
        << count;
  }
}

TEST(Minimize1dPreconditions, TheBracketAndToleranceMustBeUsable) {
  const auto f = [](double x) { return (x - 1.0) * (x - 1.0); };
  EXPECT_TRUE(throwsError([&] { minimizeBrent(f, 2.0, 0.0, 1e-6); }, ErrorKind::BadArgument,
                          {"1-D minimisation: needs a finite bracket lo ≤ hi"}));
  EXPECT_TRUE(throwsError([&] { minimizeBrent(f, kNaN, 2.0, 1e-6); }, ErrorKind::BadArgument,
                          {"1-D minimisation"}));
  EXPECT_TRUE(throwsError([&] { minimizeBrent(f, 0.0, kInf, 1e-6); }, ErrorKind::BadArgument,
                          {"1-D minimisation"}));
  EXPECT_TRUE(throwsError([&] { minimizeBrent(f, 0.0, 2.0, 0.0); }, ErrorKind::BadArgument,
                          {"1-D minimisation"}));
  EXPECT_NEAR(minimizeBrent(f, 0.0, 2.0, 1e-9).x, 1.0, 1e-6);
  EXPECT_EQ(minimizeBrent(f, 1.5, 1.5, 1e-9).x, 1.5);  // an empty bracket is its only point
}

// [SECTION] Model files

class ModelFilePreconditions : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::makeTempDir("model_file_preconditions"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  static std::string read(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }

  static std::string hex(std::uint64_t v) {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
    return buf;
  }

  static std::uint64_t fnv(std::string_view s) {
    std::uint64_t h = 14695981039346656037ull;
    for (const unsigned char c : s) h = (h ^ c) * 1099511628211ull;
    return h;
  }

  // A valid model file whose value `index` of array `arrayIndex` is replaced by `value`,
  // every checksum recomputed: damage the checksums cannot see.
  std::filesystem::path withValue(int arrayIndex, Eigen::Index index, double value) {
    const auto file = dir_ / "model.ewm";
    saveModel(smallModel(), file);
    const std::string bytes = read(file);
    const size_t e1 = bytes.find('\n'), e2 = bytes.find('\n', e1 + 1),
                 e3 = bytes.find('\n', e2 + 1);
    auto meta = nlohmann::json::parse(bytes.substr(e1 + 1, e2 - e1 - 1));
    std::string payload = bytes.substr(e3 + 1);
    size_t offset = 0;
    for (int a = 0; a < arrayIndex; ++a)
      offset += 8 * meta["arrays"][static_cast<size_t>(a)]["rows"].get<size_t>() *
                meta["arrays"][static_cast<size_t>(a)]["cols"].get<size_t>();
    const auto& spec = meta["arrays"][static_cast<size_t>(arrayIndex)];
    const size_t size = 8 * spec["rows"].get<size_t>() * spec["cols"].get<size_t>();
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, 8);
    for (int b = 0; b < 8; ++b)
      payload[offset + 8 * static_cast<size_t>(index) + static_cast<size_t>(b)] =
          static_cast<char>((bits >> (8 * b)) & 0xff);
    meta["arrays"][static_cast<size_t>(arrayIndex)]["fnv1a64"] =
        hex(fnv(std::string_view(payload).substr(offset, size)));
    const std::string metaLine = meta.dump();
    const auto damaged = dir_ / "damaged.ewm";
    std::ofstream(damaged, std::ios::binary)
        << bytes.substr(0, e1 + 1) << metaLine << "\nfnv1a64 " << hex(fnv(metaLine)) << "\n"
        << payload;
    return damaged;
  }

  std::filesystem::path dir_;
};

TEST_F(ModelFilePreconditions, ANaNInAnArrayIsMalformedNamingTheArray) {
  const auto file = withValue(0, 5, kNaN);  // mean
  EXPECT_TRUE(throwsError(
      [&] { loadModel(file); }, ErrorKind::Malformed,
      {"damaged.ewm", "model file: array 'mean' holds nan at index 5 (must be finite)"}));
}

TEST_F(ModelFilePreconditions, ANegativeEigenvalueIsMalformed) {
  const auto file = withValue(2, 0, -3.0);  // eigenvalues
  EXPECT_TRUE(throwsError([&] { loadModel(file); }, ErrorKind::Malformed,
                          {"damaged.ewm", "model file: array 'eigenvalues'", "(must be ≥ 0)"}));
}

TEST_F(ModelFilePreconditions, ANonPositiveFrequencyIsMalformed) {
  const auto file = withValue(5, 1, 0.0);  // omegas_rad_s
  EXPECT_TRUE(throwsError([&] { loadModel(file); }, ErrorKind::Malformed,
                          {"damaged.ewm", "model file: array 'omegas_rad_s'", "(must be > 0)"}));
}

// Today an empty model was written and only refused when read back.
TEST_F(ModelFilePreconditions, AModelThatCouldNotBeReadBackIsNotWritten) {
  const auto file = dir_ / "empty.ewm";
  EXPECT_TRUE(throwsError([&] { saveModel(EigenwalkerModel{}, file); }, ErrorKind::BadArgument,
                          {"empty.ewm", "model file: cannot save:", "empty or inconsistent"}));
  EXPECT_FALSE(std::filesystem::exists(file));
  EigenwalkerModel m = smallModel();
  m.coefficients(0, 0) = kNaN;
  EXPECT_TRUE(throwsError([&] { saveModel(m, file); }, ErrorKind::BadArgument,
                          {"empty.ewm", "model file: cannot save:", "non-finite coefficients"}));
  m = smallModel();
  m.subjects.pop_back();
  EXPECT_TRUE(throwsError([&] { saveModel(m, file); }, ErrorKind::BadArgument,
                          {"model file: cannot save: inconsistent sizes"}));
  EXPECT_FALSE(std::filesystem::exists(file));
}

}  // namespace
}  // namespace ew
