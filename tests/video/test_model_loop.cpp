// The model loop (video/model_loop.h): tracks guided by the eigenwalker fitted to the previous
// track, on synthetic footage with known truth (tests/video/walking_footage.h), and a clip the
// fit refuses keeping its first track.

#include <gtest/gtest.h>

#include <iostream>

#include "core/engine/default_model.h"
#include "core/tracking/track_compare.h"
#include "tests/common/error_matchers.h"
#include "tests/video/walking_footage.h"
#include "video/model_loop.h"

namespace ew {
namespace {

TrackDistance loopedDistance(int rounds, ModelLoopResult* out = nullptr) {
  const test::WalkingFootage& footage = test::walkingFootage();
  VideoSource video(footage.file);
  ModelLoopOptions loop;
  loop.rounds = rounds;
  ModelLoopResult r = trackWithModel(video, keyframesFromTrack(footage.truthPx, {0}, footage.file.string()),
                                     defaultRealModel(), {}, loop);
  const TrackDistance d = compareTracks(r.track.jointsPx, 0, footage.truthPx);
  std::cout << rounds << " round(s): median " << d.medianAllPx << " px, p95 " << d.p95AllPx << " px;";
  for (const ModelLoopRound& q : r.rounds) std::cout << " fit " << q.reprojectionRmsPx << " px at " << q.strideHz << " Hz;";
  std::cout << " true stride " << footage.strideHz << " Hz\n";
  if (out) *out = std::move(r);
  return d;
}

// Measured (docs/TRACKING.md): without the loop median 15.6 px, p95 122 px; one round 14.8 /
// 54.6 px. The fit strides at the trunk's bob, 0.918 Hz against the walker's own 0.932 Hz
// (its lost ankles alone read 2.03 Hz, and the fit then strode at 1.83 Hz); the tail halves,
// the median barely moves (the far hip and shoulder, hidden, are 13-18 px off in both), and
// issue 14's 3 px is not reached.
TEST(ModelLoop, OneRoundHalvesTheTrackersTailOnAWalker) {
  ModelLoopResult looped;
  const TrackDistance alone = loopedDistance(0), once = loopedDistance(1, &looped);
  ASSERT_EQ(looped.rounds.size(), 1u);
  EXPECT_TRUE(looped.stoppedBecause.empty()) << looped.stoppedBecause;
  EXPECT_EQ(once.jointFrames, alone.jointFrames);
  EXPECT_LT(once.p95AllPx, 0.6 * alone.p95AllPx);  // measured 0.46
  EXPECT_LT(once.medianAllPx, alone.medianAllPx + 1.0);
  EXPECT_NEAR(looped.rounds[0].strideHz, test::walkingFootage().strideHz, 0.03 * test::walkingFootage().strideHz);
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

}  // namespace
}  // namespace ew
