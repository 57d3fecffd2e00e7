// Joints a marker set lacks (core/gait/missing_joints.h, core/eigenwalker/joint_completion.h):
// prepare tolerates joints missing throughout, the minimum is enforced with a typed error,
// completion from a model beats the mean walker, a full walker passes through unchanged,
// and a 2D view with a joint missing throughout still reconstructs every joint.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/eigenwalker/joint_completion.h"
#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/eigenwalker/synthetic_walkers.h"
#include "core/eigenwalker/walker_set.h"
#include "core/experiments/lower_body.h"
#include "core/gait/prepare.h"
#include "core/io/load_trial.h"
#include "core/mapping/joint_mapping.h"
#include "tests/common/synthetic_gait.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

JointMask upperBody() {
  JointMask m{};
  for (Joint j : {Joint::Head, Joint::Sternum, Joint::RShoulder, Joint::RElbow, Joint::RWrist,
                  Joint::LShoulder, Joint::LElbow, Joint::LWrist})
    m[static_cast<size_t>(index(j))] = true;
  return m;
}

JointMask only(Joint j) {
  JointMask m{};
  m[static_cast<size_t>(index(j))] = true;
  return m;
}

JointMask measured(const JointMask& missing) {
  JointMask m{};
  for (size_t j = 0; j < m.size(); ++j) m[j] = !missing[j];
  return m;
}

// Columns (dims per joint) of the masked joints set to NaN in every frame.
Eigen::MatrixXd blank(Eigen::MatrixXd frames, const JointMask& mask) {
  const auto dims = static_cast<int>(frames.cols()) / kJointCount;
  for (int j = 0; j < kJointCount; ++j)
    if (mask[static_cast<size_t>(j)]) frames.middleCols(dims * j, dims).setConstant(kNaN);
  return frames;
}

// Entries of w (225) of the masked joints, every block.
Eigen::VectorXd blankW(Eigen::VectorXd w, const JointMask& mask) {
  for (int b = 0; b < kFourierBlocks; ++b)
    for (int j = 0; j < kJointCount; ++j)
      if (mask[static_cast<size_t>(j)]) w.segment<3>(b * kDims3 + 3 * j).setConstant(kNaN);
  return w;
}

// A model of 39 synthetic walkers and a 40th held out of it.
struct HeldOut {
  EigenwalkerModel model;
  Eigen::VectorXd w;
};

HeldOut syntheticHeldOut() {
  const Eigen::MatrixXd all = syntheticWalkerSet(40, 20070501);
  const int r = static_cast<int>(all.cols()) - 1;
  std::vector<std::string> ids, subjects;
  for (int i = 0; i < r; ++i) {
    ids.push_back("w" + std::to_string(i));
    subjects.push_back("s" + std::to_string(i));
  }
  HeldOut h;
  h.model = buildModel(all.leftCols(r), ids, subjects,
                       Eigen::VectorXd::Constant(r, 2.0 * std::numbers::pi * 0.9));
  h.w = all.col(r);
  return h;
}

// [SECTION] Completion of a Fourier vector

TEST(JointCompletion, RecoversHeldOutUpperBodyBetterThanTheMeanWalker) {
  const HeldOut h = syntheticHeldOut();
  const JointMask missing = upperBody();
  const JointCompletion c = completeJoints(h.model, blankW(h.w, missing), missing);
  EXPECT_EQ(c.modelEstimated, missing);
  // The mean walker's joints in place of the missing ones: the baseline.
  Eigen::VectorXd baseline = h.w;
  for (int b = 0; b < kFourierBlocks; ++b)
    for (int j = 0; j < kJointCount; ++j)
      if (missing[static_cast<size_t>(j)])
        baseline.segment<3>(b * kDims3 + 3 * j) = h.model.mean.segment<3>(b * kDims3 + 3 * j);
  const double completed = meanOverJoints(mpjpePerJoint(h.w, c.w), missing);
  const double mean = meanOverJoints(mpjpePerJoint(h.w, baseline), missing);
  std::printf(
      "held-out synthetic walker, upper body estimated: MPJPE %.2f mm (mean walker %.2f mm)\n",
      completed, mean);
  EXPECT_LT(completed, 0.8 * mean);
  // Measured joints are kept as measured.
  EXPECT_EQ(meanOverJoints(mpjpePerJoint(h.w, c.w), measured(missing)), 0.0);
}

TEST(JointCompletion, FullWalkerPassesThroughUnchanged) {
  const HeldOut h = syntheticHeldOut();
  const JointCompletion c = completeJoints(h.model, h.w, JointMask{});
  EXPECT_TRUE(c.w == h.w);
  EXPECT_FALSE(anyJoint(c.modelEstimated));
  EXPECT_EQ(c.k.size(), h.model.componentCount());
}

TEST(JointCompletion, UsesTheModelsStoredSigma2) {
  HeldOut h = syntheticHeldOut();
  const JointMask missing = upperBody();
  EXPECT_EQ(completeJoints(h.model, h.w, missing).sigma2Mm2, kPaperSigma2Mm2);
  h.model.sigma2Optimum = Sigma2Optimum{};
  h.model.sigma2Optimum->sigma2Mm2 = 350.0;
  EXPECT_EQ(completeJoints(h.model, h.w, missing).sigma2Mm2, 350.0);
  CompletionOptions o;
  o.sigma2Mm2 = 5.0;
  EXPECT_EQ(completeJoints(h.model, h.w, missing, o).sigma2Mm2, 5.0);
}

TEST(JointCompletion, RejectsBadInputWithTypedErrors) {
  const HeldOut h = syntheticHeldOut();
  JointMask all{};
  all.fill(true);
  EXPECT_THROW(completeJoints(h.model, h.w, all), Error);
  EXPECT_THROW(completeJoints(h.model, Eigen::VectorXd::Zero(150), JointMask{}), Error);
  // A NaN at a measured joint is not a missing joint.
  EXPECT_THROW(completeJoints(h.model, blankW(h.w, only(Joint::RKnee)), upperBody()), Error);
  CompletionOptions o;
  o.sigma2Mm2 = -1.0;
  EXPECT_THROW(completeJoints(h.model, h.w, upperBody(), o), Error);
}

// [SECTION] prepare with joints missing throughout

test::AnalyticGait gait() {
  test::AnalyticGait g;
  g.durationS = 4.0;
  return g;
}

TEST(MissingJoints, AreNotGapsAndTheMeasuredJointsPrepareAsBefore) {
  const JointTrial full = test::analyticWalkTrial(gait());
  JointTrial partial = full;
  partial.positionsMm = blank(full.positionsMm, upperBody());
  const WalkingTrial a = prepareWalkingTrial(full);
  const WalkingTrial b = prepareWalkingTrial(partial);
  EXPECT_EQ(b.joints.missing, upperBody());
  EXPECT_EQ(a.windowBegin, b.windowBegin);
  EXPECT_EQ(a.windowEnd, b.windowEnd);
  EXPECT_NEAR(a.cycles.strideHz, b.cycles.strideHz, 1e-9);
  for (int j = 0; j < kJointCount; ++j) {
    const auto ca = a.joints.positionsMm.middleCols<3>(3 * j);
    const auto cb = b.joints.positionsMm.middleCols<3>(3 * j);
    if (upperBody()[static_cast<size_t>(j)]) {
      EXPECT_TRUE(cb.array().isNaN().all()) << kJointNames[static_cast<size_t>(j)];
    } else {
      EXPECT_LT((ca - cb).cwiseAbs().maxCoeff(), 1e-6) << kJointNames[static_cast<size_t>(j)];
    }
  }
  for (const auto& w : b.joints.warnings) EXPECT_EQ(w.find("gap"), std::string::npos) << w;
}

TEST(MissingJoints, FlaggedMissingJointsAreBlankedEvenWithData) {
  JointTrial t = test::analyticWalkTrial(gait());
  t.missing[static_cast<size_t>(index(Joint::Head))] = true;
  const WalkingTrial w = prepareWalkingTrial(t);
  EXPECT_TRUE(w.joints.missing[static_cast<size_t>(index(Joint::Head))]);
  EXPECT_TRUE(w.joints.positionsMm.middleCols<3>(0).array().isNaN().all());
}

TEST(MissingJoints, MissingPelvisIsStoodInForByTheHips) {
  JointTrial t = test::analyticWalkTrial(gait());
  JointMask missing = upperBody();
  missing[static_cast<size_t>(index(Joint::Pelvis))] = true;
  t.positionsMm = blank(t.positionsMm, missing);
  const WalkingTrial w = prepareWalkingTrial(t);
  EXPECT_EQ(w.joints.missing, missing);
  EXPECT_NEAR(w.speedMps, gait().speedMps, 0.05);
}

JointMask withMissing(std::initializer_list<Joint> joints) {
  JointMask m = upperBody();
  for (Joint j : joints) m[static_cast<size_t>(index(j))] = true;
  return m;
}

// The error prepare gives for a trial missing these joints (and the upper body), or "".
std::string prepareError(const JointMask& missing) {
  JointTrial t = test::analyticWalkTrial(gait());
  t.positionsMm = blank(t.positionsMm, missing);
  try {
    prepareWalkingTrial(t);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadData);
    EXPECT_NE(std::string(e.what()).find("analytic"), std::string::npos) << e.what();
    return e.what();
  }
  return "";
}

TEST(MissingJoints, TooFewMeasuredIsATypedErrorNamingThem) {
  const std::string prefix = "too few joints measured to estimate the rest: ";
  // No phase reference.
  EXPECT_NE(
      prepareError(withMissing({Joint::LAnkle, Joint::RHip})).find(prefix + "l_ankle missing"),
      std::string::npos);
  // No left-right pair for the heading.
  EXPECT_NE(prepareError(withMissing({Joint::RHip, Joint::LKnee}))
                .find(prefix + "r_hip, l_knee missing (needs both ankles, both hips or both knees"),
            std::string::npos);
  // No body centre.
  EXPECT_NE(prepareError(withMissing({Joint::Pelvis, Joint::LHip}))
                .find(prefix + "pelvis, l_hip missing"),
            std::string::npos);
}

TEST(MissingJoints, KneesStandInForMissingHipsAndHipsForAMissingPelvis) {
  EXPECT_EQ(prepareError(withMissing({Joint::RHip, Joint::LHip})), "");
  EXPECT_EQ(prepareError(withMissing({Joint::Pelvis})), "");
  EXPECT_EQ(prepareError(withMissing({Joint::RKnee, Joint::LKnee})), "");
  JointTrial t = test::analyticWalkTrial(gait());
  const WalkingTrial full = prepareWalkingTrial(t);
  t.positionsMm = blank(t.positionsMm, withMissing({Joint::RHip, Joint::LHip}));
  const WalkingTrial noHips = prepareWalkingTrial(t);
  EXPECT_NEAR(noHips.speedMps, full.speedMps, 0.02);
  EXPECT_NEAR(noHips.cycles.strideHz, full.cycles.strideHz, 0.02);
}

// [SECTION] Completion of a prepared trial

TEST(CompleteWalkingTrial, FillsAndFlagsOnlyTheMissingJoints) {
  const HeldOut h = syntheticHeldOut();
  JointTrial t = test::analyticWalkTrial(gait());
  t.positionsMm = blank(t.positionsMm, upperBody());
  const WalkingTrial prepared = prepareWalkingTrial(t);
  const CompletedTrial c = completeWalkingTrial(prepared, h.model);
  EXPECT_EQ(c.trial.modelEstimated, upperBody());
  EXPECT_TRUE(c.trial.joints.positionsMm.allFinite());
  EXPECT_TRUE(c.fit.w.allFinite());
  for (int j = 0; j < kJointCount; ++j) {
    if (upperBody()[static_cast<size_t>(j)]) continue;
    EXPECT_TRUE(c.trial.joints.positionsMm.middleCols<3>(3 * j) ==
                prepared.joints.positionsMm.middleCols<3>(3 * j));
  }
}

TEST(CompleteWalkingTrial, FullTrialPassesThroughUnchanged) {
  const HeldOut h = syntheticHeldOut();
  const WalkingTrial prepared = prepareWalkingTrial(test::analyticWalkTrial(gait()));
  const CompletedTrial c = completeWalkingTrial(prepared, h.model);
  EXPECT_FALSE(anyJoint(c.trial.modelEstimated));
  EXPECT_TRUE(c.trial.joints.positionsMm == prepared.joints.positionsMm);
}

// [SECTION] 2D view with a joint missing throughout

struct TwoDResult {
  double measuredMpjpe = 0.0;
  Eigen::VectorXd perJoint;
};

TwoDResult reconstruct2d(const HeldOut& h, const JointMask& missing, double alphaDeg) {
  const double omega = 2.0 * std::numbers::pi * 0.9, rate = 100.0;
  const Eigen::MatrixXd frames3d = synthesizeFrames(h.w, omega, 0.0, frameTimes(300, rate));
  const Eigen::MatrixXd view = blank(projectFramesToView(frames3d, alphaDeg), missing);
  FourierFitOptions o;
  o.omegaFixedRadS = omega;
  const FourierFit fit2d = fitFourierMeasured(view, rate, missing, o);
  std::vector<int> missingJoints;
  for (int j = 0; j < kJointCount; ++j)
    if (missing[static_cast<size_t>(j)]) missingJoints.push_back(j);
  const Reconstruction rec = reconstructMap(precomputeModelGram(h.model, missingJoints), fit2d.w,
                                            alphaDeg, kPaperSigma2Mm2);
  const FourierFit truth = fitFourier(frames3d, rate, o);
  TwoDResult r;
  r.perJoint = mpjpePerJoint(truth.w, rephase(rec.w, fit2d.phaseRad, truth.phaseRad));
  r.measuredMpjpe = meanOverJoints(r.perJoint, measured(missing));
  return r;
}

TEST(MissingJoints2D, WristMissingThroughoutStillReconstructsEveryJoint) {
  const HeldOut h = syntheticHeldOut();
  const JointMask wrist = only(Joint::RWrist);
  for (double alpha : {30.0, 90.0}) {
    const TwoDResult full = reconstruct2d(h, JointMask{}, alpha);
    const TwoDResult partial = reconstruct2d(h, wrist, alpha);
    const double fullMeasured = meanOverJoints(full.perJoint, measured(wrist));
    std::printf(
        "alpha %.0f: MPJPE measured joints %.2f mm (full input %.2f mm); r_wrist "
        "model-estimated %.2f mm (measured %.2f mm)\n",
        alpha, partial.measuredMpjpe, fullMeasured, partial.perJoint(5), full.perJoint(5));
    EXPECT_TRUE(partial.perJoint.allFinite());
    EXPECT_LT(partial.measuredMpjpe, 1.25 * fullMeasured + 1.0);
  }
}

TEST(MissingJoints2D, AnkleMissingThroughoutIsTooFew) {
  const HeldOut h = syntheticHeldOut();
  EXPECT_THROW(reconstruct2d(h, only(Joint::LAnkle), 30.0), Error);
}

// [SECTION] A real trial with its upper body blanked (the "316 of 316 frames" case)

TEST(MissingJointsRealData, LowerBodyOfARealTrialPrepares) {
  EW_REQUIRE_SHARED_DATA();
  const auto file =
      test::sharedDataDir() / "schreiber-moissenet-2019" / "2014001" / "2014001_C4_05.c3d";
  const JointTrial full = toJointTrial(readRawTrial(file));
  JointTrial partial = full;
  partial.positionsMm = blank(full.positionsMm, upperBody());
  const WalkingTrial a = prepareWalkingTrial(full);
  const WalkingTrial b = prepareWalkingTrial(partial);
  EXPECT_EQ(b.joints.missing, upperBody());
  EXPECT_NEAR(a.cycles.strideHz, b.cycles.strideHz, 0.02 * a.cycles.strideHz);
  const FourierFit fit =
      fitFourierMeasured(b.joints.positionsMm, b.joints.rateHz, b.joints.missing);
  EXPECT_GT(fit.h1Share, 0.5);
}

}  // namespace
}  // namespace ew

namespace ew {
namespace {

// [SECTION] A model is not built from its own estimates

TEST(MissingJointsWalkers, PartialTrialsAreLeftOutOfTheModelWithAWarning) {
  Dataset dataset;
  for (const char* name : {"full", "lower"}) {
    JointTrial t = test::analyticWalkTrial(gait());
    t.file = name;
    if (std::string(name) == "lower") t.positionsMm = blank(t.positionsMm, upperBody());
    dataset.trials.push_back({{name, name, "test", "walk", {}}, prepareWalkingTrial(t)});
  }
  std::vector<std::string> warnings;
  const std::vector<Walker> walkers = makeWalkers(dataset, &warnings);
  ASSERT_EQ(walkers.size(), 1u);
  EXPECT_EQ(walkers[0].subject, "full");
  bool named = false;
  for (const auto& w : warnings)
    named = named || (w.find("lower") != std::string::npos &&
                      w.find("joints not measured (head, sternum") != std::string::npos);
  EXPECT_TRUE(named);
}

}  // namespace
}  // namespace ew

namespace ew {
namespace {

// [SECTION] The lower-body experiment on the shared walkers

TEST(LowerBodyRealData, ModelEstimatesTheUpperBodyBetterThanTheMeanWalker) {
  EW_REQUIRE_SHARED_DATA();
  const Dataset dataset = loadDataset({test::sharedDataDir() / "walkers.csv"});
  const auto walkers = experimentWalkers(makeWalkers(dataset), dataset);
  const auto folds = buildFolds(walkers, {}, 2);
  const auto rows = lowerBodyErrors(walkers, folds, true, true, 1000.0, 2);
  double map = 0, mean = 0;
  for (const auto& s : summarizeLowerBody(rows)) {
    if (s.joint != "all") continue;
    if (s.method == "map") map = s.meanMpjpeMm;
    if (s.method == "mean") mean = s.meanMpjpeMm;
  }
  std::printf("lower body, 24 walkers: MAP %.1f mm, mean walker %.1f mm\n", map, mean);
  EXPECT_EQ(rows.size(), walkers.size() * 8 * 3);
  EXPECT_GT(map, 0.0);
  EXPECT_LT(map, 0.8 * mean);
}

}  // namespace
}  // namespace ew
