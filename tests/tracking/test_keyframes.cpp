// The keyframe file (core/tracking/keyframes.h): a round trip, every malformed case named
// with the file and the keyframe, and keyframes taken from a detector's track.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

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
  // Found by fuzz_keyframes: each once escaped as nlohmann's own exception.
  EXPECT_TRUE(throwsError(parse("1e388"), ErrorKind::Malformed, {"k.json", "not JSON a reader can hold"}));
  EXPECT_TRUE(throwsError(parse(R"({"format": 5})"), ErrorKind::Malformed, {"k.json", "not a keyframe file"}));
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

// Issue 53: a keyframe at frame 1e9 was reported as the tracker's "no keyframe within the
// tracked frames", naming the video. The keyframe file is at fault, and named.
TEST(Keyframes, AKeyframePastTheVideosLastFrameIsTheFilesFault) {
  const Keyframes keys = parseKeyframes(
      R"({"format": "eigenwalker-keyframes", "version": 1, "keyframes": [)"
      R"({"frame": 0, "joints": {"head": [1, 2]}}, {"frame": 1000000000, "joints": {"head": [1, 2]}}]})",
      "far.json");
  EXPECT_TRUE(test::throwsError([&] { checkKeyframesWithin(keys, 30, "far.json"); }, ErrorKind::BadData,
                                {"far.json", "keyframe on frame 1000000000", "the video has 30 frames (0-29)"}));
  Keyframes last = keys;
  last.keyframes.back().frame = 29;
  EXPECT_NO_THROW(checkKeyframesWithin(last, 30, "far.json"));
  last.keyframes.back().frame = 30;
  EXPECT_TRUE(test::throwsError([&] { checkKeyframesWithin(last, 30, "far.json"); }, ErrorKind::BadData,
                                {"keyframe on frame 30"}));
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


// A track whose joints all move `step(r)` px right from row r − 1 to row r.
Eigen::MatrixXd trackMoving(const std::vector<double>& steps) {
  Eigen::MatrixXd px = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(steps.size()), kDims2);
  for (Eigen::Index r = 1; r < px.rows(); ++r) {
    px.row(r) = px.row(r - 1);
    for (Eigen::Index j = 0; j < kDims2; j += 2) px(r, j) += steps[static_cast<size_t>(r)];
  }
  return px;
}

// The summed distance of every row to its nearest keyframe row, along the motion: what
// framesToMarkNext cuts most, counted the slow way.
double summedMotionDistance(const Eigen::VectorXd& cumulative, const std::vector<int>& rows) {
  double total = 0.0;
  for (Eigen::Index r = 0; r < cumulative.size(); ++r) {
    double nearest = std::numeric_limits<double>::infinity();
    for (int k : rows) nearest = std::min(nearest, std::abs(cumulative(r) - cumulative(k)));
    total += nearest;
  }
  return total;
}

// Where the joints move, not where time passes: a man marked standing still, who stands for
// 40 frames, lunges for 20 and holds the lunge for 40, is best marked again in the pose he
// holds (one mark serves its 40 frames), at the lunge's end, not at the clip's end; then in
// the lunge itself, not in the still frames.
TEST(TrackConfidence, TheFrameToMarkNextSplitsTheMotionNotTheTime) {
  std::vector<double> steps(100, 0.0);
  for (int r = 41; r <= 60; ++r) steps[static_cast<size_t>(r)] = 10.0;
  const Eigen::MatrixXd px = trackMoving(steps);
  const std::vector<int> next = framesToMarkNext(px, 200, {200}, 2);
  ASSERT_EQ(next.size(), 2u);
  EXPECT_EQ(next[0], 260);
  EXPECT_GE(next[1], 245);  // rows 45-55, frames 245-255: the lunge's middle half
  EXPECT_LE(next[1], 255);
  // A joint lost (NaN) is left out of the mean, not taken for a jump.
  Eigen::MatrixXd lost = px;
  lost.col(4).setConstant(std::nan(""));
  EXPECT_EQ(framesToMarkNext(lost, 200, {200}, 2), next);
  // Nothing moved: nothing to suggest. A keyframe outside the track is ignored.
  const Eigen::MatrixXd still = Eigen::MatrixXd::Zero(30, kDims2);
  EXPECT_TRUE(framesToMarkNext(still, 0, {0}, 3).empty());
  EXPECT_EQ(framesToMarkNext(px, 200, {5, 200, 900}, 2), next);
  EXPECT_TRUE(framesToMarkNext(Eigen::MatrixXd(0, kDims2), 0, {}, 1).empty());
}

// The prefix sums give the frame the slow count gives, with keyframes before, between and
// after, none, and each next frame chosen with the ones before it as keyframes.
TEST(TrackConfidence, TheFramesToMarkNextCutTheSummedDistanceMost) {
  std::vector<double> steps(80);
  for (size_t i = 0; i < steps.size(); ++i) steps[i] = std::fmod(static_cast<double>(i * 37 % 11), 7.0);
  const Eigen::MatrixXd px = trackMoving(steps);
  const Eigen::VectorXd cumulative = cumulativeMotionPx(px);
  EXPECT_NEAR(cumulative(79), std::accumulate(steps.begin() + 1, steps.end(), 0.0), 1e-9);
  for (const std::vector<int>& keys : {std::vector<int>{}, {0}, {79}, {20, 50}, {10, 11, 70}}) {
    std::vector<int> rows = keys;
    for (const int chosen : framesToMarkNext(px, 0, keys, 3)) {
      double best = std::numeric_limits<double>::infinity();
      for (int x = 0; x < 80; ++x) {
        if (std::find(rows.begin(), rows.end(), x) != rows.end()) continue;
        std::vector<int> with = rows;
        with.push_back(x);
        best = std::min(best, summedMotionDistance(cumulative, with));
      }
      std::vector<int> with = rows;
      with.push_back(chosen);
      EXPECT_NEAR(summedMotionDistance(cumulative, with), best, 1e-6) << "keyframes " << keys.size();
      EXPECT_EQ(std::count(rows.begin(), rows.end(), chosen), 0);
      rows.push_back(chosen);
    }
  }
}

}  // namespace
}  // namespace ew
