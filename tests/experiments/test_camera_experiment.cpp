// Experiment "camera" (core/experiments/camera_experiment.h) on five synthetic walkers, one
// random camera each at 2 px noise: every clip goes through OpenPose JSON and back and is
// reconstructed with everything unknown; the options are checked.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "core/common/errors.h"
#include "core/eigenwalker/synthetic_walkers.h"
#include "core/eigenwalker/walker_set.h"
#include "core/experiments/camera_experiment.h"
#include "core/experiments/leave_one_out.h"
#include "core/experiments/results_folder.h"
#include "core/gait/dataset.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

std::vector<ExperimentWalker> syntheticWalkers(int count) {
  const Eigen::MatrixXd w = syntheticWalkerSet(count, 2027);
  std::vector<ExperimentWalker> out;
  for (int i = 0; i < count; ++i) {
    ExperimentWalker e;
    e.id = e.subject = "SYN" + std::to_string(i);
    e.fit.w = w.col(i);
    e.fit.omegaRadS = 2 * std::numbers::pi * (0.9 + 0.02 * i);
    out.push_back(e);
  }
  return out;
}

TEST(CameraExperiment, ClipsGoThroughOpenPoseJsonAndBack) {
  const auto walkers = syntheticWalkers(5);
  const auto folds = buildFolds(walkers, ModelOptions{}, 2);
  CameraExperimentOptions o;
  o.camerasPerWalker = 1;
  o.noisePx = {2.0};
  o.threads = 2;
  o.sigma2Mm2 = 70.0;
  const auto rows = cameraErrors(walkers, folds, o);
  ASSERT_EQ(rows.size(), 5u);
  int ok = 0;
  double unguided = 0, guided = 0;
  for (const auto& r : rows) {
    SCOPED_TRACE(r.walker + " " + r.error);
    EXPECT_GT(r.frames, 0);
    EXPECT_GE(r.trueElevationDeg, 0.0);
    EXPECT_LE(r.trueElevationDeg, 30.0);
    // The other engines, given the true camera, answer every clip the reader read.
    ASSERT_TRUE(r.skeleton && r.skeletonGuided && r.skeletonTable2 && r.skeletonEigenwalkerBones && r.snippet);
    EXPECT_EQ(r.skeleton->error, "");
    EXPECT_EQ(r.snippet->error, "");
    // Measured 212-349 mm (skeleton, own bones) and 148-329 mm (snippet) on these clips:
    // the depth branches, not the camera (docs/RESULTS.md). A wrong camera or progression
    // gives 500-1000 mm.
    EXPECT_LT(r.skeleton->mpjpeMm, 450.0);
    EXPECT_LT(r.snippet->mpjpeMm, 450.0);
    unguided += r.skeleton->mpjpeMm;
    guided += r.skeletonGuided->mpjpeMm;
    if (!r.error.empty()) continue;
    ++ok;
    EXPECT_LT(r.mpjpeMm, 100.0);
    EXPECT_LT(r.alphaErrorDeg, 20.0);
  }
  EXPECT_GE(ok, 4);
  // The eigenwalker's fit choosing the branches: summed over the 5 clips 1371 mm with
  // the skeleton engine's own rule, 1108 mm guided.
  EXPECT_LT(guided, 0.9 * unguided);
  const auto summary = summarizeCamera(rows);
  ASSERT_EQ(summary.size(), 1u);
  EXPECT_EQ(summary[0].clips, 5);
  EXPECT_EQ(summary[0].failures, 5 - ok);
  const std::string csv = cameraCsv(rows);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), kCameraHeader);
  // The same seed films the same cameras.
  EXPECT_EQ(cameraErrors(walkers, folds, o)[0].trueAlphaDeg, rows[0].trueAlphaDeg);
}

TEST(CameraExperiment, OptionsAreChecked) {
  const auto walkers = syntheticWalkers(3);
  const auto folds = buildFolds(walkers, ModelOptions{}, 1);
  const auto expectBad = [&](CameraExperimentOptions o, const char* part) {
    EXPECT_TRUE(test::throwsError([&] { cameraErrors(walkers, folds, o); }, ErrorKind::BadArgument, {part}));
  };
  CameraExperimentOptions o;
  o.camerasPerWalker = 0;
  expectBad(o, "at least one camera");
  o = {};
  o.noisePx = {-1};
  expectBad(o, "noise levels");
  o = {};
  o.dropShare = 2;
  expectBad(o, "shares");
  o = {};
  o.fps = 0;
  expectBad(o, "frame rate");
  o = {};
  o.clipStrides = 0.2;
  expectBad(o, "0.5-10 strides");
  o = {};
  o.walkerHeightPx = 5;
  expectBad(o, "walker's height");
  o = {};
  o.minSpeedMps = 2.0;
  expectBad(o, "speeds");
  o = {};
  o.maxElevationDeg = 90;
  expectBad(o, "elevations");
  o = {};
  o.horizonReadSdDeg = -1;
  expectBad(o, "horizon's reading error");
  o = {};
  o.horizonReadBiasDeg = 45;
  expectBad(o, "horizon's reading bias");
}

// The eigenwalker alone at 2 px, as the widened experiment runs it, at the synthetic walkers' σ².
CameraExperimentOptions eigenwalkerAloneAt2Px(int camerasPerWalker) {
  CameraExperimentOptions o;
  o.camerasPerWalker = camerasPerWalker;
  o.noisePx = {2.0};
  o.threads = 2;
  o.sigma2Mm2 = 70.0;
  o.skeleton = o.snippet = false;
  return o;
}

// The widened experiment's hardest clips (issue 55): a stride and a bit (1.2), the walker
// 120 px tall, walking fast, written as AlphaPose COCO-17 (no neck, no mid-hip) at 25 fps,
// the camera up to 35° above. Each factor shapes the clip as asked, and the fit answers every
// clip: measured on these 5 clips 28-63 mm, elevation within 0.7-3.2°, α within 0.2-5.9° (the
// worst seen from 17° behind), distance within 7-35 %; the tolerances are about twice the worst.
// Before issue 55's fixes such clips were mostly refused "not walking: no regular foot
// strikes" (16 of the 24 real walkers' in the widened experiment).
TEST(CameraExperiment, TheHardestWideClipsAreReconstructed) {
  const auto walkers = syntheticWalkers(5);
  const auto folds = buildFolds(walkers, ModelOptions{}, 2);
  const CameraExperimentOptions base = eigenwalkerAloneAt2Px(1);
  const auto conditions = cameraWideConditions(base, {"hardest"});
  ASSERT_EQ(conditions.size(), 6u);  // the base and the hardest: as it is, image, focal length, edge, horizon
  const CameraExperimentOptions& o = conditions[1].options;
  EXPECT_EQ(o.clipStrides, 1.2);
  EXPECT_EQ(o.walkerHeightPx, 120.0);
  EXPECT_EQ(o.layout, ClipLayout::Coco17);
  EXPECT_EQ(o.fps, 25.0);
  EXPECT_FALSE(o.imageSizeKnown);
  const auto rows = cameraErrors(walkers, folds, o);
  ASSERT_EQ(rows.size(), 5u);
  for (const auto& r : rows) {
    SCOPED_TRACE(r.walker + " " + r.error);
    EXPECT_NEAR(r.strides, 1.2, 0.05);
    EXPECT_NEAR(r.walkerHeightPx, 120.0, 1e-6);
    EXPECT_LE(r.trueElevationDeg, 35.0);
    EXPECT_GE(r.trueElevationDeg, 0.0);
    EXPECT_FALSE(r.skeleton || r.snippet);
    ASSERT_EQ(r.error, "");
    EXPECT_LT(r.mpjpeMm, 120.0);
    EXPECT_LT(r.elevationErrorDeg, 6.0);
    // The angle the walker is seen from: the camera's tilt less the pelvis's angle above the
    // optical axis at mid-clip (within 0.5°: the mean over the clip, the walker off the centre
    // column), and the fit's within the tilt's bound.
    const double pelvisAboveAxisDeg =
        std::atan(r.framingOffsetOfHeight * r.walkerHeightPx / r.trueFocalPx) * 180.0 / std::numbers::pi;
    EXPECT_NEAR(r.trueViewElevationDeg, r.trueElevationDeg - pelvisAboveAxisDeg, 0.5);
    EXPECT_LT(r.viewElevationErrorDeg, 6.0);
    EXPECT_LT(r.alphaErrorDeg, 12.0);
    EXPECT_LT(r.distanceRelError, 0.7);
  }
  // Given the focal length, the fit holds it: the distance then rests on the walker's size.
  ASSERT_TRUE(conditions[3].options.focalKnown);
  for (const auto& r : cameraErrors(walkers, folds, conditions[3].options)) {
    ASSERT_EQ(r.error, "") << r.walker;
    EXPECT_LT(r.focalRelError, 1e-9) << r.walker;
  }
  CameraWideRow one{"hardest", "x", rows[0]};
  const std::string csv = cameraWideCsv({one});
  EXPECT_EQ(csv.substr(0, csv.find('\n')), kCameraWideHeader);
  const auto summary = summarizeCameraWide({one, one});
  ASSERT_EQ(summary.size(), 1u);
  EXPECT_EQ(summary[0].clips, 2);
  EXPECT_EQ(summary[0].refusals, 0);
  EXPECT_DOUBLE_EQ(summary[0].medianMpjpeMm, rows[0].mpjpeMm);
}

// A real detector reports no point off its picture (the `edge` factor): the clips kept and read
// back then hold every seen joint inside the 1920 × 1080 picture, while as written before some
// lie outside it (the walker's head and feet as it enters and leaves: 4 % of the samples of the
// camera experiment's clips of the shared walkers), and every clip is still fitted.
TEST(CameraExperiment, PointsOffThePictureCanBeDropped) {
  const auto walkers = syntheticWalkers(4);
  const auto folds = buildFolds(walkers, ModelOptions{}, 2);
  // One camera a walker: as drawn, the walker's head and feet leave the picture in 70 of 72
  // clips (docs/CAMERA.md, "edge").
  CameraExperimentOptions o = eigenwalkerAloneAt2Px(1);
  const auto offPicture = [&](bool dropped) {
    o.offPictureDropped = dropped;
    o.keepClipsDir = test::makeTempDir(dropped ? "edge_dropped" : "edge_kept");
    for (const CameraRow& r : cameraErrors(walkers, folds, o)) EXPECT_EQ(r.error, "") << r.walker;
    int outside = 0;
    for (const auto& clip : std::filesystem::directory_iterator(*o.keepClipsDir)) {
      KeypointOptions k;
      k.fps = o.fps;
      const KeypointTrial t = readKeypointTrial(clip.path(), k);
      for (Eigen::Index f = 0; f < t.jointsPx.rows(); ++f)
        for (int j = 0; j < kJointCount; ++j) {
          const double u = t.jointsPx(f, 2 * j), v = t.jointsPx(f, 2 * j + 1);
          outside += std::isfinite(u) && !(u >= 0 && u < 1920 && v >= 0 && v < 1080);
        }
    }
    return outside;
  };
  EXPECT_GT(offPicture(false), 0);
  EXPECT_EQ(offPicture(true), 0);
}

// The scene's horizon reaches the fit as read: read 8° too high in the picture (a camera looking
// 8° further down), the fitted cameras look further down than read true, and read 8° too low,
// less far; read true, the angle the walker is seen from is as right as without it. Measured: the
// mean tilt error −0.3° read true, +2.0° and −0.8° read 8° off either way: from 3.5-8 m the image
// resists most of a wrong horizon, which it cannot from 25 m (the camera fit's own test).
TEST(CameraExperiment, TheScenesHorizonIsGivenToTheFitAsRead) {
  const auto walkers = syntheticWalkers(4);
  const auto folds = buildFolds(walkers, ModelOptions{}, 2);
  CameraExperimentOptions o = eigenwalkerAloneAt2Px(1);
  o.imageSizeKnown = true;
  const auto meanTiltError = [&](std::optional<double> biasDeg, double& viewError) {
    o.horizonReadSdDeg = biasDeg ? std::optional<double>(0.0) : std::nullopt;
    o.horizonReadBiasDeg = biasDeg.value_or(0.0);
    double tilt = 0;
    viewError = 0;
    const auto rows = cameraErrors(walkers, folds, o);
    for (const CameraRow& r : rows) {
      EXPECT_EQ(r.error, "") << r.walker;
      tilt += r.elevationDeg - r.trueElevationDeg;
      viewError += r.viewElevationErrorDeg;
    }
    viewError /= static_cast<double>(rows.size());
    return tilt / static_cast<double>(rows.size());
  };
  double viewAlone = 0, viewRead = 0, ignored = 0;
  meanTiltError(std::nullopt, viewAlone);
  const double read = meanTiltError(0.0, viewRead);
  const double high = meanTiltError(8.0, ignored), low = meanTiltError(-8.0, ignored);
  EXPECT_GT(high, read);
  EXPECT_LT(low, read);
  EXPECT_LT(viewRead, viewAlone + 0.1);
}

// The conditions change one factor at a time from the base, which is the camera experiment's
// clip; --factor narrows them, and a factor not known is refused naming the known ones.
TEST(CameraExperiment, TheWideConditionsChangeOneFactorEach) {
  CameraExperimentOptions base;
  base.seed = 7;
  const auto all = cameraWideConditions(base);
  ASSERT_GE(all.size(), 10u);
  EXPECT_EQ(all[0].factor, "base");
  EXPECT_FALSE(all[0].options.clipStrides || all[0].options.walkerHeightPx);
  EXPECT_EQ(all[0].options.layout, ClipLayout::Body25);
  EXPECT_EQ(all[0].options.maxElevationDeg, 30.0);
  for (const auto& c : all) EXPECT_EQ(c.options.seed, 7u) << c.factor;  // the same cameras
  const auto lengths = cameraWideConditions(base, {"length"});
  ASSERT_EQ(lengths.size(), 5u);
  EXPECT_EQ(lengths[4].level, "1.2");
  EXPECT_EQ(lengths[4].options.clipStrides, 1.2);
  EXPECT_FALSE(lengths[4].options.walkerHeightPx);
  const auto layout = cameraWideConditions(base, {"layout"});
  ASSERT_EQ(layout.size(), 2u);
  EXPECT_EQ(layout[1].options.layout, ClipLayout::Coco17);
  const auto focal = cameraWideConditions(base, {"focal"});
  ASSERT_EQ(focal.size(), 3u);
  EXPECT_TRUE(focal[1].options.focalKnown && focal[2].options.focalKnown);
  EXPECT_EQ(focal[2].options.clipStrides, 1.2);
  EXPECT_FALSE(all[0].options.focalKnown);
  // The scene's horizon is read off a video, whose image's size is known too.
  const auto horizon = cameraWideConditions(base, {"horizon"});
  ASSERT_EQ(horizon.size(), 3u);
  for (std::size_t i = 1; i < 3; ++i) {
    EXPECT_TRUE(horizon[i].options.imageSizeKnown);
    EXPECT_EQ(horizon[i].options.horizonReadSdDeg, 0.5);
  }
  EXPECT_EQ(horizon[1].options.horizonReadBiasDeg, 0.0);
  EXPECT_EQ(horizon[2].options.horizonReadBiasDeg, 3.0);
  EXPECT_FALSE(all[0].options.horizonReadSdDeg);
  EXPECT_TRUE(test::throwsError([&] { cameraWideConditions(base, {"lenght"}); }, ErrorKind::BadArgument,
                                {"no factor 'lenght'", "length, height"}));
}

}  // namespace
}  // namespace ew

namespace ew {
namespace {

// [SECTION] How sure the fit is, on the shared walkers

// The SDs the fit gives its stature, speed and stride (CameraFit::sd) hold the held-out
// walkers' truth about as often as they say: ±1.96 SD held 92 % of the statures and 97 % /
// 99 % of the speeds and strides on the camera experiment's clips at 2 px, and 93 / 100 / 100 %
// at 1.2 strides (72 clips each; out of sample, on the other five cameras of `--cameras 8`,
// 92–93 / 94–97 / 94–99 %). The floors leave a few clips of room (one clip is 1.4 %); the
// stride's error over its SD must also spread (an SD of 0.83 and 0.61 here), or the SDs would
// be too wide to mean anything.
TEST(CameraExperimentOnSharedWalkers, TheFitsSdsHoldTheTruthAsOftenAsTheySay) {
  EW_REQUIRE_SHARED_DATA();
  const Dataset dataset = loadDataset({test::sharedDataDir() / "walkers.csv"});
  const auto walkers = experimentWalkers(makeWalkers(dataset), dataset);
  const auto folds = buildFolds(walkers, ModelOptions{}, 2);
  CameraExperimentOptions base;
  base.threads = 2;
  base.skeleton = base.snippet = false;
  base.noisePx = {2.0};
  for (const auto& condition : cameraWideConditions(base, {"length"})) {
    if (condition.level != "as the camera experiment" && condition.level != "1.2") continue;
    SCOPED_TRACE(condition.level);
    std::vector<CameraWideRow> rows;
    double sumZ2 = 0.0;
    int scored = 0;
    for (const CameraRow& r : cameraErrors(walkers, folds, condition.options)) {
      rows.push_back({condition.factor, condition.level, r});
      if (!r.error.empty() || !(r.strideLengthSdM > 0.0)) continue;
      sumZ2 += std::pow((r.strideLengthM - r.trueStrideLengthM) / r.strideLengthSdM, 2);
      ++scored;
    }
    const CameraWideSummary s = summarizeCameraWide(rows).front();
    EXPECT_EQ(s.clips, 72);
    EXPECT_GE(s.statureWithin2SdShare, 0.86);
    EXPECT_GE(s.speedWithin2SdShare, 0.90);
    EXPECT_GE(s.strideWithin2SdShare, 0.90);
    ASSERT_GT(scored, 60);
    EXPECT_GT(std::sqrt(sumZ2 / scored), 0.4);
  }
}

}  // namespace
}  // namespace ew
