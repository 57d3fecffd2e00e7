// The model loop (video/model_loop.h): tracks guided by the eigenwalker fitted to the previous
// track, on synthetic footage with known truth (tests/video/walking_footage.h), and a clip the
// fit refuses keeping its first track.

#include <gtest/gtest.h>

#include <iostream>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/camera/clip_reconstruction.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/walker_set.h"
#include "core/experiments/leave_one_out.h"
#include "core/gait/dataset.h"
#include "core/tracking/track_compare.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"
#include "tests/video/walking_footage.h"
#include "video/model_loop.h"
#include "video/synthetic_footage.h"
#include "video/track_study.h"

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

// Measured (docs/TRACKING_DESIGN.md): without the loop median 10.8 px, p95 170 px; one round 10.9 /
// 61.9 px. The fit strides at the trunk's bob, 0.915 Hz against the walker's own 0.932 Hz;
// the tail falls to about a third, the median hardly moves, and issue 14's 3 px is not reached.
TEST(ModelLoop, OneRoundHalvesTheTrackersTailOnAWalker) {
  ModelLoopResult looped;
  const TrackDistance alone = loopedDistance(0), once = loopedDistance(1, &looped);
  ASSERT_EQ(looped.rounds.size(), 1u);
  EXPECT_TRUE(looped.stoppedBecause.empty()) << looped.stoppedBecause;
  EXPECT_EQ(once.jointFrames, alone.jointFrames);
  EXPECT_LT(once.p95AllPx, 0.6 * alone.p95AllPx);  // measured 0.36
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

std::vector<ExperimentWalker> sharedWalkers() {
  const Dataset dataset = loadDataset({test::sharedDataDir() / "walkers.csv"});
  return experimentWalkers(makeWalkers(dataset), dataset);
}

// A held-out shared walker filmed 6 m away (video/track_study.h, what `track-study` runs), fitted
// at the default model's σ² as `track --reconstruct` and `reconstruct --unknown-camera` fit.
TrackStudyOptions filmedAsTheStudy() {
  TrackStudyOptions o;
  o.sigma2Mm2 = defaultSigma2Mm2(defaultRealModel());
  return o;
}

// Issue 14's bar for the walk from a track: within 1.3× the MPJPE of the same fit to the true
// 2D. CMU06 filmed 30° off the side view and tracked from its true joints on frame 0. The
// tracker alone misses (1.39×; docs/TRACKING_DESIGN.md has four more walkers, 1.8–2.5×); three
// rounds of the model loop bring it within the bar (measured 1.14).
TEST(ModelLoopOnSharedWalkers, ThreeRoundsBringAHeldOutWalkersFitWithinTheBar) {
  EW_REQUIRE_SHARED_DATA();
  const FilmedHeldOutWalker walker(sharedWalkers(), "CMU06", 30.0, filmedAsTheStudy());
  const double fromTruth = walker.mpjpeFromTruthMm();
  VideoSource alone(walker.file());
  const double fromTrack = walker.mpjpeFromTrackMm(trackJoints(alone, walker.firstFrameMarked()));
  VideoSource again(walker.file());
  const ModelLoopResult looped =
      trackWithModel(again, walker.firstFrameMarked(), walker.model(), {}, ModelLoopOptions{3});
  ASSERT_EQ(looped.rounds.size(), 3u) << looped.stoppedBecause;
  const double fromLoop = walker.mpjpeFromTrackMm(looped.track);
  std::cout << "MPJPE from the true 2D " << fromTruth << " mm, from the track " << fromTrack
            << " mm (" << fromTrack / fromTruth << "x), after three rounds " << fromLoop << " mm ("
            << fromLoop / fromTruth << "x)\n";
  EXPECT_LT(fromTruth, 40.0);
  EXPECT_GT(fromTrack / fromTruth, 1.3);
  EXPECT_LE(fromLoop / fromTruth, 1.3);
}

// Issue 14's whole bar for synthetic footage: the track from one keyframe within 3 px at the
// median and 10 px at the 95th percentile, the walk from it within 1.3× the true 2D's MPJPE.
// `subject` filmed from `azimuthDeg` (track-study's azimuth), one round of the model loop.
void expectTheWholeBarAfterOneRound(const std::string& subject, double azimuthDeg) {
  const FilmedHeldOutWalker walker(sharedWalkers(), subject, azimuthDeg, filmedAsTheStudy());
  VideoSource video(walker.file());
  const ModelLoopResult looped =
      trackWithModel(video, walker.firstFrameMarked(), walker.model(), {}, ModelLoopOptions{1});
  ASSERT_EQ(looped.rounds.size(), 1u) << looped.stoppedBecause;
  const TrackDistance d = compareTracks(looped.track.jointsPx, 0, walker.truthPx());
  const double ratio = walker.mpjpeFromTrackMm(looped.track) / walker.mpjpeFromTruthMm();
  std::cout << subject << " from " << azimuthDeg << " deg: track median " << d.medianAllPx
            << " px, p95 " << d.p95AllPx << " px; MPJPE " << ratio << "x the true 2D's\n";
  EXPECT_EQ(d.jointFrames, static_cast<int>(walker.truthPx().size() / 2));  // every joint, every frame
  EXPECT_LE(d.medianAllPx, 3.0);
  EXPECT_LE(d.p95AllPx, 10.0);
  EXPECT_LE(ratio, 1.3);
}

// Met from the front: CMU06 coming towards the camera (measured 1.7 / 6.3 px, 1.00×; the five
// walkers of docs/TRACKING_DESIGN.md 1.4–1.8 / 5.0–6.6 px, 1.00–1.06×). From the side the far
// limbs pass behind the body and the bar is not met (the test above).
TEST(ModelLoopOnSharedWalkers, FromTheFrontOneRoundTracksAHeldOutWalkerWithinTheWholeBar) {
  EW_REQUIRE_SHARED_DATA();
  expectTheWholeBarAfterOneRound("CMU06", -90.0);
}

// From behind the legs are straight stripes whose knees the flow cannot place along them; the
// model's place does (slideAlongTheAperture, video/joint_tracker.cpp). SM2014001 walking away
// (measured 2.3 / 8.4 px, 0.98×; 3 of the five walkers meet the bar from behind, none did
// before the slide: their knees drifted 7-20 px down the leg).
TEST(ModelLoopOnSharedWalkers, FromBehindOneRoundTracksAHeldOutWalkerWithinTheWholeBar) {
  EW_REQUIRE_SHARED_DATA();
  expectTheWholeBarAfterOneRound("SM2014001", 90.0);
}

}  // namespace
}  // namespace ew
