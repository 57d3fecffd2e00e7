// The keyframe file (core/tracking/keyframes.h): a round trip, every malformed case named
// with the file and the keyframe, and keyframes taken from a detector's track.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/common/nan.h"
#include "core/tracking/keyframes.h"
#include "core/tracking/track_compare.h"
#include "core/tracking/track_confidence.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

std::string withKeyframes(const std::string& list) {
  return R"({"format": "eigenwalker-keyframes", "version": 1, "video": "clip.mp4", "keyframes": )" +
         list + "}";
}

TEST(Keyframes, ReadBackWhatWasWrittenSortedWithUnmarkedJointsMissing) {
  Keyframes k;
  k.video = "clip.mp4";
  Keyframe late{60, Eigen::RowVectorXd::LinSpaced(kDims2, 10.0, 300.0)};
  Keyframe early{5, Eigen::RowVectorXd::LinSpaced(kDims2, 1.5, 30.25)};
  early.jointsPx(2 * index(Joint::LWrist)) = early.jointsPx(2 * index(Joint::LWrist) + 1) = kNaN;
  k.keyframes = {late, early};
  const fs::path file = test::makeTempDir("keyframes") / "k.json";
  writeKeyframes(file, k);
  const Keyframes back = readKeyframes(file);
  EXPECT_EQ(back.video, "clip.mp4");
  ASSERT_EQ(back.keyframes.size(), 2u);
  EXPECT_EQ(back.keyframes[0].frame, 5);
  EXPECT_EQ(back.keyframes[1].frame, 60);
  EXPECT_TRUE(std::isnan(back.keyframes[0].jointsPx(2 * index(Joint::LWrist))));
  EXPECT_TRUE(test::bitwiseEqual(back.keyframes[1].jointsPx, late.jointsPx));
  EXPECT_DOUBLE_EQ(back.keyframes[0].jointsPx(0), 1.5);
}

TEST(Keyframes, AJointLeftOutIsNotMarked) {
  const Keyframes k = parseKeyframes(
      withKeyframes(R"([{"frame": 3, "joints": {"r_ankle": [100, 200.5]}}])"), "k.json");
  ASSERT_EQ(k.keyframes.size(), 1u);
  EXPECT_DOUBLE_EQ(k.keyframes[0].jointsPx(2 * index(Joint::RAnkle) + 1), 200.5);
  EXPECT_TRUE(std::isnan(k.keyframes[0].jointsPx(0)));
}

TEST(Keyframes, MalformedFilesAreNamedWithTheirProblem) {
  using test::throwsError;
  const auto parse = [](const std::string& text) {
    return [text] { parseKeyframes(text, "k.json"); };
  };
  EXPECT_TRUE(throwsError(parse("{"), ErrorKind::Malformed, {"k.json", "not JSON"}));
  EXPECT_TRUE(throwsError(parse(R"({"people": []})"), ErrorKind::Malformed,
                          {"k.json", "not a keyframe file"}));
  EXPECT_TRUE(
      throwsError(parse(R"({"format": "eigenwalker-keyframes", "version": 2, "keyframes": []})"),
                  ErrorKind::Malformed, {"version"}));
  EXPECT_TRUE(throwsError(parse(withKeyframes(R"([{"frame": 1, "joints": {"nose": [1, 2]}}])")),
                          ErrorKind::Malformed, {"keyframe 0", "unknown joint \"nose\""}));
  EXPECT_TRUE(throwsError(parse(withKeyframes(R"([{"frame": 1, "joints": {"head": [1]}}])")),
                          ErrorKind::Malformed, {"keyframe 0 head", "[x, y]"}));
  EXPECT_TRUE(throwsError(parse(withKeyframes(R"([{"frame": 1, "joints": {"head": ["1", 2]}}])")),
                          ErrorKind::Malformed, {"not a number"}));
  EXPECT_TRUE(throwsError(parse(withKeyframes(R"([{"frame": -1, "joints": {"head": [1, 2]}}])")),
                          ErrorKind::Malformed, {"frame -1"}));
  EXPECT_TRUE(throwsError(parse(withKeyframes(R"([{"frame": 1.5, "joints": {}}])")),
                          ErrorKind::Malformed, {"integer \"frame\""}));
  EXPECT_TRUE(
      throwsError(parse(withKeyframes(
                      R"([{"frame": 4, "joints": {"head": [1, 2]}}, {"frame": 4, "joints": {}}])")),
                  ErrorKind::Malformed, {"keyframe 1", "frame 4 is marked twice"}));
  EXPECT_TRUE(throwsError(parse(withKeyframes(R"([{"frame": 4, "joints": {"head": null}}])")),
                          ErrorKind::BadData, {"no keyframe has a marked joint"}));
  EXPECT_TRUE(throwsError([] { readKeyframes("/nonexistent/k.json"); }, ErrorKind::Io,
                          {"/nonexistent/k.json"}));
}

// A mark far outside the picture (a keyframe file of another video, a coordinate typed wrong,
// a hostile 1e300) is an error naming the file, the frame and the joint; one a little outside
// (a foot the edge cuts off) is kept.
TEST(Keyframes, MarksFarOutsideThePictureAreRefused) {
  const auto marked = [](double x, double y) {
    return parseKeyframes(withKeyframes(R"([{"frame": 7, "joints": {"l_ankle": [)" + std::to_string(x) + ", " +
                                        std::to_string(y) + "]}}]"),
                          "k.json");
  };
  EXPECT_NO_THROW(checkMarksWithin(marked(-10.0, 730.0), 1280, 720, "k.json"));
  EXPECT_NO_THROW(checkMarksWithin(marked(1280.0 + 319.0, -179.0), 1280, 720, "k.json"));
  // (The pair's members copied: clang 14 cannot capture a structured binding in a lambda.)
  for (const std::pair<double, double>& at : {std::pair{1e300, 5.0}, std::pair{5.0, -1e300},
                                              std::pair{-321.0, 5.0}, std::pair{5.0, 720.0 + 181.0}}) {
    const double x = at.first, y = at.second;
    EXPECT_TRUE(test::throwsError([&] { checkMarksWithin(marked(x, y), 1280, 720, "k.json"); },
                                  ErrorKind::BadData, {"k.json", "frame 7 l_ankle", "outside the 1280x720 picture"}))
        << x << ", " << y;
  }
}

TEST(Keyframes, FromATrackAtChosenFrames) {
  Eigen::MatrixXd track = Eigen::MatrixXd::Constant(10, kDims2, kNaN);
  track.row(2).setLinSpaced(kDims2, 0.0, 29.0);
  const Keyframes k = keyframesFromTrack(track, {2}, "v.mp4");
  ASSERT_EQ(k.keyframes.size(), 1u);
  EXPECT_TRUE(test::bitwiseEqual(k.keyframes[0].jointsPx, track.row(2)));
  EXPECT_TRUE(test::throwsError([&] { keyframesFromTrack(track, {10}, "v.mp4"); },
                                ErrorKind::BadArgument, {"frame 10", "outside"}));
  EXPECT_TRUE(test::throwsError([&] { keyframesFromTrack(track, {3}, "v.mp4"); },
                                ErrorKind::BadArgument, {"frame 3", "no joint"}));
}

TEST(TrackCompare, DistancesPerJointOverTheFramesBothHave) {
  // Reference: frames 0-9; the track starts at frame 5 and runs past the reference's end.
  Eigen::MatrixXd reference = Eigen::MatrixXd::Zero(10, kDims2);
  Eigen::MatrixXd track = Eigen::MatrixXd::Zero(8, kDims2);
  for (Eigen::Index r = 0; r < track.rows(); ++r)
    track(r, 2 * index(Joint::RKnee)) = 3.0;      // 3 px off in x
  track(0, 2 * index(Joint::Head) + 1) = 4.0;     // one frame 4 px off
  reference(7, 2 * index(Joint::LAnkle)) = kNaN;  // a missing detection
  const TrackDistance d = compareTracks(track, 5, reference);
  EXPECT_EQ(d.frames[index(Joint::RKnee)], 5);  // frames 5-9
  EXPECT_DOUBLE_EQ(d.medianPx[index(Joint::RKnee)], 3.0);
  EXPECT_EQ(d.frames[index(Joint::LAnkle)], 4);
  EXPECT_DOUBLE_EQ(d.medianPx[index(Joint::Head)], 0.0);
  EXPECT_GT(d.p95Px[index(Joint::Head)], 0.0);
  EXPECT_EQ(d.jointFrames, 15 * 5 - 1);
  EXPECT_DOUBLE_EQ(d.medianAllPx, 0.0);
  // Within 12 px (the default): every joint-frame; within 3.5 px: all but the head's 4 px.
  EXPECT_DOUBLE_EQ(d.shareWithinAll, 1.0);
  const TrackDistance tight = compareTracks(track, 5, reference, allJoints(), 3.5);
  EXPECT_DOUBLE_EQ(tight.shareWithin[index(Joint::Head)], 0.8);
  EXPECT_DOUBLE_EQ(tight.shareWithin[index(Joint::RKnee)], 1.0);
  EXPECT_DOUBLE_EQ(tight.shareWithinAll, 73.0 / 74.0);
  const TrackDistance tighter = compareTracks(track, 5, reference, allJoints(), 2.0);
  EXPECT_DOUBLE_EQ(tighter.shareWithin[index(Joint::RKnee)], 0.0);
}

// The least sure frames: lowest mean confidence first, no keyframe, each `apart` from the
// ones chosen before it; fewer when the track has fewer.
TEST(TrackConfidence, LeastSureFramesAreTheWeakestApartAndNoKeyframe) {
  Eigen::MatrixXd confidence = Eigen::MatrixXd::Constant(20, kJointCount, 0.9);
  confidence.row(3).setConstant(0.1);   // frame 13 (the track starts at frame 10)
  confidence.row(4).setConstant(0.15);  // frame 14: next to 13
  confidence.row(12).setConstant(0.2);  // frame 22
  confidence.row(0).setConstant(0.05);  // frame 10: a keyframe
  confidence(8, 0) = 0.0;               // frame 18: one joint lost, the mean hardly lower
  const Eigen::VectorXd means = confidence.rowwise().mean();
  EXPECT_EQ(leastSureFrames(means, 10, {10}, 3, 3), (std::vector<int>{13, 22, 18}));
  EXPECT_EQ(leastSureFrames(means, 10, {10}, 2, 1), (std::vector<int>{13, 14}));
  EXPECT_EQ(leastSureFrames(means, 10, {}, 1, 1), (std::vector<int>{10}));
  EXPECT_EQ(leastSureFrames(means.head(1), 10, {10}, 3, 1), std::vector<int>{});
}

}  // namespace
}  // namespace ew
