// The model loop (video/model_loop.h): tracks guided by the eigenwalker fitted to the previous
// track, on synthetic footage with known truth (tests/video/walking_footage.h), and a clip the
// fit refuses keeping its first track.

#include <gtest/gtest.h>

#include <iostream>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/camera/clip_reconstruction.h"
#include "core/engine/default_model.h"
#include "core/engine/fourier.h"
#include "core/engine/metrics.h"
#include "core/engine/walker_set.h"
#include "core/experiments/leave_one_out.h"
#include "core/gait/dataset.h"
#include "core/tracking/track_compare.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"
#include "tests/video/walking_footage.h"
#include "video/model_loop.h"
#include "video/synthetic_footage.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

TrackDistance loopedDistance(int rounds, ModelLoopResult* out = nullptr) {
  const test::WalkingFootage& footage = test::walkingFootage();
  VideoSource video(footage.file);
  ModelLoopOptions loop;
  loop.rounds = rounds;
  ModelLoopResult r =
      trackWithModel(video, keyframesFromTrack(footage.truthPx, {0}, footage.file.string()),
                     defaultRealModel(), {}, loop);
  const TrackDistance d = compareTracks(r.track.jointsPx, 0, footage.truthPx);
  std::cout << rounds << " round(s): median " << d.medianAllPx << " px, p95 " << d.p95AllPx
            << " px;";
  for (const ModelLoopRound& q : r.rounds)
    std::cout << " fit " << q.reprojectionRmsPx << " px at " << q.strideHz << " Hz, "
              << q.hiddenJointFrames << " joint-frames hidden;";
  std::cout << " true stride " << footage.strideHz << " Hz\n";
  if (out) *out = std::move(r);
  return d;
}

// Measured (docs/TRACKING.md): without the loop median 10.8 px, p95 170 px; one round 10.5 /
// 59.3 px. The fit strides at the trunk's bob, 0.915 Hz against the walker's own 0.932 Hz;
// the tail falls to about a third, the median hardly moves, and issue 14's 3 px is not reached.
TEST(ModelLoop, OneRoundHalvesTheTrackersTailOnAWalker) {
  ModelLoopResult looped;
  const TrackDistance alone = loopedDistance(0), once = loopedDistance(1, &looped);
  ASSERT_EQ(looped.rounds.size(), 1u);
  EXPECT_TRUE(looped.stoppedBecause.empty()) << looped.stoppedBecause;
  EXPECT_EQ(once.jointFrames, alone.jointFrames);
  EXPECT_LT(once.p95AllPx, 0.6 * alone.p95AllPx);  // measured 0.46
  EXPECT_LT(once.medianAllPx, alone.medianAllPx + 1.0);
  EXPECT_NEAR(looped.rounds[0].strideHz, test::walkingFootage().strideHz,
              0.03 * test::walkingFootage().strideHz);
  // Seen 30° off the side, the walk hides some joints behind the body (measured 115 of 1425
  // joint-frames); the round placed those where the walk puts them.
  EXPECT_GT(looped.rounds[0].hiddenJointFrames, 0);
  EXPECT_LT(looped.rounds[0].hiddenJointFrames, once.jointFrames / 4);
}

TEST(ModelLoop, AClipTheFitRefusesKeepsItsFirstTrackAndSaysWhy) {
  const test::WalkingFootage& footage = test::walkingFootage();
  VideoSource video(footage.file);
  TrackerOptions o;
  o.lastFrame = 9;  // ten frames: a third of a stride, no foot strikes to fit
  ModelLoopOptions loop;
  loop.rounds = 2;
  const Keyframes keys = keyframesFromTrack(footage.truthPx, {0}, footage.file.string());
  const ModelLoopResult r = trackWithModel(video, keys, defaultRealModel(), o, loop);
  EXPECT_TRUE(r.rounds.empty());
  EXPECT_NE(r.stoppedBecause.find(footage.file.string()), std::string::npos) << r.stoppedBecause;
  VideoSource again(footage.file);
  EXPECT_TRUE(test::bitwiseEqual(r.track.jointsPx, trackJoints(again, keys, o).jointsPx));
  loop.rounds = 11;
  EXPECT_TRUE(test::throwsError([&] { trackWithModel(again, keys, defaultRealModel(), o, loop); },
                                ErrorKind::BadArgument, {"0-10"}));
}

// Issue 14's bar for the walk from a track: within 1.3× the MPJPE of the same fit to the true
// 2D. A held-out shared walker (CMU06: the model is built without it) carried forward for
// three strides, filmed 6 m away 30° off the side view, tracked from its true joints on frame
// 0; both fits at the default model's σ² with the stride held at the trunk's bob for the track,
// as `track --reconstruct` and `reconstruct --unknown-camera` fit. The tracker alone misses
// (1.46×; docs/TRACKING.md has four more walkers, 1.8–2.5×); three rounds of the model loop
// bring it within the bar (measured 1.19).
TEST(ModelLoopOnSharedWalkers, ThreeRoundsBringAHeldOutWalkersFitWithinTheBar) {
  EW_REQUIRE_SHARED_DATA();
  const Dataset dataset = loadDataset({test::sharedDataDir() / "walkers.csv"});
  const std::vector<ExperimentWalker> walkers = experimentWalkers(makeWalkers(dataset), dataset);
  const auto held = std::find_if(walkers.begin(), walkers.end(),
                                 [](const ExperimentWalker& w) { return w.subject == "CMU06"; });
  ASSERT_NE(held, walkers.end());
  std::vector<ExperimentWalker> others;
  std::copy_if(walkers.begin(), walkers.end(), std::back_inserter(others),
               [&](const ExperimentWalker& w) { return w.subject != held->subject; });
  const EigenwalkerModel model = buildFullModel(others);

  const double fps = 30.0, strideS = 2.0 * std::numbers::pi / held->fit.omegaRadS;
  const int frames = static_cast<int>(std::ceil(3.0 * strideS * fps)) + 1;
  const Eigen::VectorXd times = frameTimes(frames, fps);
  const Eigen::MatrixXd inPlace = synthesizeFrames(held->fit.w, held->fit.omegaRadS, 0.0, times);
  Eigen::MatrixXd walking = inPlace;
  for (int f = 0; f < frames; ++f)
    for (int j = 0; j < kJointCount; ++j) walking(f, 3 * j + 1) += 1200.0 * times[f];
  const fs::path dir = test::makeTempDir("held_out_loop");
  const fs::path file = dir / "walk.avi";
  const Eigen::MatrixXd truthPx =
      writeFootage(file, walking, cameraBeside(walking, 30.0, 6000.0), fps);

  CameraFitOptions options;
  options.estimator = {Estimator::Map, defaultSigma2Mm2(defaultRealModel())};
  const auto mpjpeOf = [&](const KeypointTrial& joints, bool tracked) {
    CameraFitOptions o = options;
    if (tracked) holdTheTrunksStride(joints, o);
    const ClipReconstruction c = reconstructKeypointTrial(model, joints, o);
    const Eigen::MatrixXd walk = synthesizeFrames(c.fit.w, c.fit.omegaRadS, c.fit.phaseRad, times);
    return mpjpeWithoutTranslation(walk, inPlace);
  };
  KeypointOptions atFps;
  atFps.fps = fps;
  const double fromTruth =
      mpjpeOf(trialFromJoints(truthPx, Eigen::MatrixXd::Ones(frames, kJointCount), file.string(),
                              "true 2D", atFps),
              false);
  const Keyframes keys = keyframesFromTrack(truthPx, {0}, file.string());
  VideoSource alone(file);
  const double fromTrack = mpjpeOf(keypointTrialOf(trackJoints(alone, keys), file.string()), true);
  VideoSource again(file);
  const ModelLoopResult looped = trackWithModel(again, keys, model, {}, ModelLoopOptions{3});
  ASSERT_EQ(looped.rounds.size(), 3u) << looped.stoppedBecause;
  const double fromLoop = mpjpeOf(keypointTrialOf(looped.track, file.string()), true);
  std::cout << "MPJPE from the true 2D " << fromTruth << " mm, from the track " << fromTrack
            << " mm (" << fromTrack / fromTruth << "x), after three rounds " << fromLoop << " mm ("
            << fromLoop / fromTruth << "x)\n";
  EXPECT_LT(fromTruth, 40.0);
  EXPECT_GT(fromTrack / fromTruth, 1.3);
  EXPECT_LE(fromLoop / fromTruth, 1.3);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace ew
