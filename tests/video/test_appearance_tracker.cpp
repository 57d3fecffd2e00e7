// Zou et al.'s appearance tracker (video/appearance_tracker.h): its histogram distance, its
// search on a picture with a known answer, and the tracker beside the optical-flow tracker
// on synthetic footage with known truth (video/synthetic_footage.h).

#include <gtest/gtest.h>

#include <iostream>
#include <opencv2/imgproc.hpp>

#include "core/tracking/track_compare.h"
#include "tests/common/test_support.h"
#include "video/appearance_tracker.h"
#include "video/joint_tracker.h"
#include "tests/video/walking_footage.h"

namespace ew {
namespace {

const SearchBone& shank() {
  for (const SearchBone& b : kSearchTree)
    if (b.child == Joint::RAnkle) return b;
  throw std::logic_error("no shank in the search tree");
}

// A grey picture with a red bar from (300, 200) to (300, 400), 30 px wide.
cv::Mat redBarPicture() {
  cv::Mat image(600, 600, CV_8UC3, cv::Scalar(128, 128, 128));
  cv::rectangle(image, cv::Point(285, 200), cv::Point(315, 400), cv::Scalar(30, 30, 220), cv::FILLED);
  return image;
}

TEST(AppearanceTracker, BhattacharyyaDistanceIsZeroForTheSameColoursAndOneForNoneInCommon) {
  const cv::Mat image = redBarPicture();
  const double personPx = 30.0 / (2.0 * shank().halfWidthShare);  // the bar as wide as a shank
  const ColourHistogram onBar =
      segmentHistogram(image, {300.0f, 205.0f}, {300.0f, 330.0f}, shank(), personPx);
  const ColourHistogram onBarToo =
      segmentHistogram(image, {300.0f, 220.0f}, {300.0f, 320.0f}, shank(), personPx);
  const ColourHistogram offBar =
      segmentHistogram(image, {100.0f, 205.0f}, {100.0f, 330.0f}, shank(), personPx);
  EXPECT_NEAR(bhattacharyyaDistance(onBar, onBarToo), 0.0, 1e-3);  // float sums of one bin
  EXPECT_NEAR(bhattacharyyaDistance(onBar, offBar), 1.0, 1e-9);
  const ColourHistogram outside =
      segmentHistogram(image, {-500.0f, -500.0f}, {-400.0f, -500.0f}, shank(), personPx);
  EXPECT_NEAR(bhattacharyyaDistance(onBar, outside), 1.0, 1e-9);  // empty: nothing in common
  // Half the rectangle on the bar, half beside it: in between.
  const ColourHistogram half =
      segmentHistogram(image, {300.0f - 15.0f, 205.0f}, {300.0f - 15.0f, 330.0f}, shank(), personPx);
  const double d = bhattacharyyaDistance(onBar, half);
  EXPECT_GT(d, 0.3);
  EXPECT_LT(d, 0.9);
}

// One pass from a keyframe on the bar: the bar turned by 20° about its top (the "knee"), and
// the "ankle" is found at its new end to within the search grid's pixel.
TEST(AppearanceTracker, FindsATurnedSegmentWhereItsColoursAre) {
  cv::Mat before = redBarPicture();
  cv::Mat after(600, 600, CV_8UC3, cv::Scalar(128, 128, 128));
  const double turn = 20.0 * 3.14159265358979323846 / 180.0;
  const cv::Point2f knee(300.0f, 200.0f);
  const cv::Point2f ankle = knee + cv::Point2f(static_cast<float>(-160.0 * std::sin(turn)),
                                               static_cast<float>(160.0 * std::cos(turn)));
  cv::line(after, knee, knee + (ankle - knee) * 1.25f, cv::Scalar(30, 30, 220), 30);
  // A grey "person" around the bar: the root's template needs something to hold on to.
  for (cv::Mat* m : {&before, &after})
    cv::rectangle(*m, cv::Rect(240, 120, 120, 70), cv::Scalar(40, 160, 40), cv::FILLED);
  Keyframe key;
  key.frame = 0;
  key.jointsPx = Eigen::RowVectorXd::Constant(kDims2, std::nan(""));
  key.jointsPx.segment<2>(2 * index(Joint::RKnee)) << 300.0, 200.0;
  key.jointsPx.segment<2>(2 * index(Joint::RAnkle)) << 300.0, 360.0;
  AppearanceOptions o;
  o.personPx = 30.0 / (2.0 * shank().halfWidthShare);
  o.maxSearchShare = 80.0 / o.personPx;  // wide enough for the turn in one frame
  o.minSearchShare = 70.0 / o.personPx;
  const auto pass = makeAppearancePass(key, before, o);
  ASSERT_TRUE(pass->tracks(index(Joint::RAnkle)));
  EXPECT_FALSE(pass->tracks(index(Joint::Head)));
  const auto confidence = pass->advance(after, 1);
  const cv::Point2f found = pass->position(index(Joint::RAnkle));
  // The knee, the root here, is found by its patch, which holds the top of the bar that
  // turned: near, not exact (measured 7.3 px off). Along the bar the colours do not say
  // where the ankle is; across it they do.
  EXPECT_NEAR(pass->position(index(Joint::RKnee)).x, 300.0f, 10.0f);
  const cv::Point2f direction = (ankle - knee) / static_cast<float>(cv::norm(ankle - knee));
  const cv::Point2f off = found - knee;
  EXPECT_NEAR(off.x * direction.y - off.y * direction.x, 0.0, 4.0) << found;
  EXPECT_GT(confidence[index(Joint::RAnkle)], 0.7);  // measured 0.80: the drawn bar's ends are round
}

TrackDistance trackedBy(TrackerKind kind, const test::WalkingFootage& footage) {
  VideoSource video(footage.file);
  TrackerOptions o;
  o.kind = kind;
  const JointTrack track =
      trackJoints(video, keyframesFromTrack(footage.truthPx, {0}, footage.file.string()), o);
  const TrackDistance d = compareTracks(track.jointsPx, 0, footage.truthPx);
  std::cout << trackerName(kind) << ": median " << d.medianAllPx << " px, p95 " << d.p95AllPx << " px;";
  for (int j = 0; j < kJointCount; ++j) std::cout << " " << kJointNames[j] << " " << d.medianPx[j];
  std::cout << "\n";
  return d;
}

// Issue 16: the appearance tracker beside the optical-flow tracker on the same clip, from
// one keyframe with the true joints. Measured (docs/TRACKING_DESIGN.md): flow median 10.8 px, p95
// 170 px; appearance median 19.8 px, p95 93.0 px. Guards against either getting worse
// (about a quarter above the measured); neither meets issue 14's bar (3 px).
TEST(AppearanceTracker, FollowsASyntheticWalkerBesideTheFlowTracker) {
  const test::WalkingFootage& footage = test::walkingFootage();
  const TrackDistance flow = trackedBy(TrackerKind::OpticalFlow, footage);
  const TrackDistance appearance = trackedBy(TrackerKind::Appearance, footage);
  EXPECT_EQ(appearance.jointFrames, flow.jointFrames);
  EXPECT_GT(appearance.jointFrames, 0);
  EXPECT_EQ(flow.jointFrames, kJointCount * footage.truthPx.rows());
  EXPECT_LE(flow.medianAllPx, 14.0);
  EXPECT_LE(appearance.medianAllPx, 26.0);
  EXPECT_LE(appearance.p95AllPx, 110.0);
}

}  // namespace
}  // namespace ew
