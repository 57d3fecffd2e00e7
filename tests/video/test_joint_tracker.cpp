// The joint tracker (video/joint_tracker.h) on footage with known truth, painted by
// video/synthetic_footage.h (1280×720, pinhole, textured limbs over a noise background) and
// tracked from keyframes with the true joints. Not yet here: issue 14's walking footage
// (median ≤ 3 px, p95 ≤ 10 px) — on a walking synthetic walker the tracker still loses the
// legs (docs/TRACKING_DESIGN.md, "Measured").

#include <gtest/gtest.h>

#include <iostream>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/common/nan.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/synth/population.h"
#include "core/tracking/keyframes.h"
#include "core/tracking/track_compare.h"
#include "core/tracking/track_confidence.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"
#include "video/joint_tracker.h"
#include "video/synthetic_footage.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

struct Footage {
  fs::path file;
  Eigen::MatrixXd truthPx;
};

// One still pose of a synthetic walker carried forward at 1.3 m/s for 2 s, filmed at 30 fps
// from 30° off the side view, 4 m away: the figure's look barely changes, so what the
// tracker must do is follow it — its flow, its segments' strips and its filter together.
const Footage& glidingFigure() {
  static const Footage footage = [] {
    PopulationOptions o;
    o.count = 1;
    o.simulation.rateHz = 30.0;
    const SynthWalker walker = generatePopulation(o).front();
    Eigen::MatrixXd frames(60, kDims3);
    for (Eigen::Index f = 0; f < frames.rows(); ++f) {
      frames.row(f) = walker.trial.positionsMm.row(0);
      for (int j = 0; j < kJointCount; ++j)
        frames(f, 3 * j + 1) += 1300.0 * static_cast<double>(f) / 30.0;
    }
    Footage out;
    out.file = test::makeTempDir("tracker_footage") / "figure.avi";
    out.truthPx = writeFootage(out.file, frames, cameraBeside(frames, 30.0, 4000.0), 30.0);
    return out;
  }();
  return footage;
}

void printDistance(const TrackDistance& d) {
  std::cout << "median " << d.medianAllPx << " px, p95 " << d.p95AllPx
            << " px; per joint median/p95:";
  for (int j = 0; j < kJointCount; ++j)
    std::cout << " " << kJointNames[j] << " " << d.medianPx[j] << "/" << d.p95Px[j];
  std::cout << "\n";
}

TEST(JointTracker, FollowsAGlidingFigureFromOneKeyframe) {
  const Footage& footage = glidingFigure();
  VideoSource video(footage.file);
  ASSERT_EQ(video.info().frameCount, footage.truthPx.rows());
  const Keyframes keys = keyframesFromTrack(footage.truthPx, {0}, footage.file.string());
  const JointTrack track = trackJoints(video, keys);
  ASSERT_EQ(track.jointsPx.rows(), footage.truthPx.rows());
  const TrackDistance d = compareTracks(track.jointsPx, 0, footage.truthPx);
  printDistance(d);
  EXPECT_EQ(d.jointFrames, kJointCount * footage.truthPx.rows());
  // Measured 4.0 px median: frame-to-frame flow drifts (docs/TRACKING_DESIGN.md). A guard against
  // getting worse, not issue 14's bar (3 px on a walker).
  EXPECT_LE(d.medianAllPx, 5.5);
  EXPECT_LE(d.p95AllPx, 35.0);  // measured 28.1
}

TEST(JointTracker, KeyframesInTheMiddleAndAtTheEndTrackBackwardAndForward) {
  const Footage& footage = glidingFigure();
  VideoSource video(footage.file);
  const int last = static_cast<int>(footage.truthPx.rows()) - 1;
  const Keyframes keys =
      keyframesFromTrack(footage.truthPx, {last / 2, last}, footage.file.string());
  TrackerOptions o;
  o.frameBufferBytes = 20 * 1280 * 720;  // backward in pieces of 20 frames
  const JointTrack track = trackJoints(video, keys, o);
  EXPECT_TRUE(test::bitwiseEqual(track.jointsPx.row(last), footage.truthPx.row(last)));
  EXPECT_TRUE(test::bitwiseEqual(track.jointsPx.row(last / 2), footage.truthPx.row(last / 2)));
  EXPECT_DOUBLE_EQ(track.confidence(last, 0), 1.0);
  const TrackDistance d = compareTracks(track.jointsPx, 0, footage.truthPx);
  printDistance(d);
  // Two keyframes and a pass from each side shorten the stretch each pass drifts over:
  // measured 0.5 px median, 5.0 px p95.
  EXPECT_LE(d.medianAllPx, 1.0);
  EXPECT_LE(d.p95AllPx, 8.0);
}

// The model loop's prior (TrackerOptions::priorPx) with a joint the walk hides behind the body
// (priorHidden): that joint goes where the prior puts it, even where its flow holds (here the
// prior is the truth shifted 8 px right), at confidence 0.3; a joint not hidden keeps to its
// flow when the prior strays within the gate (the truth, here, beside a prior 8 px off).
TEST(JointTracker, AJointTheWalkHidesIsPlacedWhereTheWalkPutsIt) {
  const Footage& footage = glidingFigure();
  VideoSource video(footage.file);
  const Keyframes keys = keyframesFromTrack(footage.truthPx, {0}, footage.file.string());
  TrackerOptions o;
  o.priorPx = footage.truthPx;
  o.priorPx.col(2 * index(Joint::LShoulder)).array() += 8.0;
  o.priorPx.col(2 * index(Joint::Head)).array() += 8.0;
  o.priorHidden = Eigen::MatrixXd::Zero(footage.truthPx.rows(), kJointCount);
  o.priorHidden.col(index(Joint::LShoulder)).setOnes();
  const JointTrack track = trackJoints(video, keys, o);
  const Eigen::Index last = track.jointsPx.rows() - 1;
  const auto missAt = [&](Joint j) {
    return (track.jointsPx.row(last).segment<2>(2 * index(j)) -
            footage.truthPx.row(last).segment<2>(2 * index(j)))
        .eval();
  };
  EXPECT_NEAR(missAt(Joint::LShoulder).x(), 8.0, 1.0);
  EXPECT_NEAR(missAt(Joint::LShoulder).y(), 0.0, 1.0);
  EXPECT_DOUBLE_EQ(track.confidence(last, index(Joint::LShoulder)), 0.3);
  EXPECT_LT(missAt(Joint::Head).norm(), 2.0);  // measured 0.7 px alone
}

// A square of blurred noise, grey levels lo-hi.
cv::Mat printOf(cv::Size size, double lo, double hi) {
  cv::Mat print(size, CV_8UC3);
  cv::randu(print, cv::Scalar::all(lo), cv::Scalar::all(hi));
  cv::GaussianBlur(print, print, cv::Size(0, 0), 1.5);
  return print;
}

// Two still things on a grey field: a dark vertical stripe with a faint print (an edge each
// side and little along it, as a leg seen from behind) and a square with a strong print.
fs::path stripeAndPrint(int frames) {
  cv::Mat image(720, 1280, CV_8UC3, cv::Scalar::all(200));
  printOf({12, 300}, 40, 120).copyTo(image(cv::Rect(394, 200, 12, 300)));
  printOf({80, 80}, 30, 220).copyTo(image(cv::Rect(760, 310, 80, 80)));
  const fs::path file = test::makeTempDir("tracker_aperture") / "stripe.avi";
  cv::VideoWriter writer(file.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                         30.0, image.size());
  EXPECT_TRUE(writer.isOpened()) << file;
  for (int f = 0; f < frames; ++f) writer.write(image);
  return file;
}

// The model loop's prior within the gate: a joint on the stripe slides along it to where the
// prior puts it (nothing in its window says where along), but not across it; a joint on the
// print keeps to its flow. The prior is 8 px along the stripe and 3 px across from the marks.
TEST(JointTracker, AJointOnAPlainEdgeSlidesAlongItToTheModelsPlace) {
  constexpr int kFrames = 20;
  const fs::path file = stripeAndPrint(kFrames);
  VideoSource video(file);
  Keyframes keys;
  Keyframe key;
  key.frame = 0;
  key.jointsPx = Eigen::RowVectorXd::Constant(kDims2, kNaN);
  key.jointsPx.segment<2>(2 * index(Joint::RKnee)) << 400.0, 350.0;
  key.jointsPx.segment<2>(2 * index(Joint::LKnee)) << 800.0, 350.0;
  keys.keyframes.push_back(key);
  TrackerOptions o;
  o.priorPx = Eigen::MatrixXd::Constant(kFrames, kDims2, kNaN);
  for (Joint j : {Joint::RKnee, Joint::LKnee}) {
    o.priorPx.col(2 * index(j)).setConstant(key.jointsPx(2 * index(j)) + 3.0);
    o.priorPx.col(2 * index(j) + 1).setConstant(key.jointsPx(2 * index(j) + 1) + 8.0);
  }
  const JointTrack track = trackJoints(video, keys, o);
  const auto movedBy = [&](Joint j) {
    return (track.jointsPx.row(kFrames - 1).segment<2>(2 * index(j)) -
            key.jointsPx.segment<2>(2 * index(j)))
        .eval();
  };

  EXPECT_NEAR(movedBy(Joint::RKnee).y(), 8.0, 1.0);
  EXPECT_NEAR(movedBy(Joint::RKnee).x(), 0.0, 0.5);
  EXPECT_LT(movedBy(Joint::LKnee).norm(), 0.5);
}

fs::path balancingTrialDir() { return test::sharedDataDir() / "pose2sim-balancing"; }

// OpenPose's detections on the balancing trial's camera 1, at the video's frame rate.
KeypointTrial cam01OpenPose(const VideoSource& video) {
  KeypointOptions k;
  k.fps = video.info().fps;
  return readKeypointTrial(balancingTrialDir() / "pose/cam01_json", k);
}

// Pose2Sim's balancing man bends forward with bare shoulders: their own flow slides along
// the arms and stays 80 px from OpenPose's shoulders at the median; held to the pelvis→sternum
// line they follow his trunk (16–18 px, docs/TRACKING_DESIGN.md, "Holding the trunk").
TEST(JointTracker, HoldingTheTrunkKeepsTheBalancingMansShouldersOnHim) {
  EW_REQUIRE_SHARED_DATA();
  VideoSource video(balancingTrialDir() / "videos/cam01.mp4");
  const KeypointTrial openPose = cam01OpenPose(video);
  const Keyframes keys = keyframesFromTrack(openPose.jointsPx, {0}, "cam01");
  std::array<bool, kJointCount> shoulders{};
  shoulders[index(Joint::RShoulder)] = shoulders[index(Joint::LShoulder)] = true;
  const auto shoulderMedianPx = [&](bool hold) {
    TrackerOptions o;
    o.lastFrame = 99;
    o.holdTheTrunk = hold;
    const JointTrack t = trackJoints(video, keys, o);
    return compareTracks(t.jointsPx, t.firstFrame, openPose.jointsPx, shoulders).medianAllPx;
  };
  const double own = shoulderMedianPx(false), held = shoulderMedianPx(true);
  std::cout << "cam01 shoulders to OpenPose's, median: own flow " << own << " px, held " << held
            << " px\n";
  EXPECT_GT(own, 50.0);
  EXPECT_LT(held, 25.0);
}

// Where to mark a second frame of the balancing trial: he stands still, lunges and swings his
// arms, and the tracker drifts with that motion. The frame framesToMarkNext names (62), marked
// from OpenPose like frame 0, brings the track to 12.9 px from OpenPose's detections at the
// median; the least sure frame (85) to 19.9 px, no better than frame 0 alone (19.2 px). Every
// second keyframe from 5 to 99 gives 13.4-25.4 px (docs/TRACKING_DESIGN.md, "Holding the trunk").
TEST(JointTracker, TheFrameToMarkNextHelpsTheBalancingTrialMoreThanTheLeastSure) {
  EW_REQUIRE_SHARED_DATA();
  VideoSource video(balancingTrialDir() / "videos/cam01.mp4");
  const KeypointTrial openPose = cam01OpenPose(video);
  TrackerOptions o;
  o.lastFrame = 99;
  o.holdTheTrunk = true;
  const auto trackFrom = [&](const std::vector<int>& frames) {
    return trackJoints(video, keyframesFromTrack(openPose.jointsPx, frames, "cam01"), o);
  };
  const auto medianPx = [&](const JointTrack& t) {
    return compareTracks(t.jointsPx, t.firstFrame, openPose.jointsPx).medianAllPx;
  };
  const JointTrack first = trackFrom({0});
  const std::vector<int> next = framesToMarkNext(first.jointsPx, first.firstFrame, {0}, 1);
  const std::vector<int> least =
      leastSureFrames(first.confidence.rowwise().mean(), first.firstFrame, {0}, 1, 1);
  ASSERT_EQ(next.size(), 1u);
  ASSERT_EQ(least.size(), 1u);
  const double alone = medianPx(first), marked = medianPx(trackFrom({0, next[0]})),
               leastSure = medianPx(trackFrom({0, least[0]}));
  std::cout << "cam01 from frame 0: " << alone << " px; with frame " << next[0] << " to mark next "
            << marked << " px; with the least sure frame " << least[0] << " " << leastSure << " px\n";
  EXPECT_LT(marked, 14.0);
  EXPECT_LT(marked, leastSure - 4.0);
}

TEST(JointTracker, RefusesARangeWithoutKeyframesOrOutsideTheVideo) {
  const Footage& footage = glidingFigure();
  VideoSource video(footage.file);
  const Keyframes keys = keyframesFromTrack(footage.truthPx, {50}, footage.file.string());
  TrackerOptions o;
  o.lastFrame = 40;
  EXPECT_TRUE(test::throwsError([&] { trackJoints(video, keys, o); }, ErrorKind::BadArgument,
                                {"no keyframe within the tracked frames 0-40"}));
  o.lastFrame = 100000;
  EXPECT_TRUE(test::throwsError([&] { trackJoints(video, keys, o); }, ErrorKind::BadArgument,
                                {"not within"}));
  o.lastFrame = -1;
  EXPECT_TRUE(test::throwsError([&] { trackJoints(video, keys, o, [](double) { return false; }); },
                                ErrorKind::BadArgument, {"cancelled"}));
  // A mark far outside the picture (once a crash in OpenCV's patch cut): an error.
  Keyframes far = keys;
  far.keyframes.front().jointsPx(0) = 1e300;
  EXPECT_TRUE(test::throwsError([&] { trackJoints(video, far, o); }, ErrorKind::BadData,
                                {"frame 50 head", "far outside"}));
}

// Issue 53: a 1 × 1-pixel video was "tracked" for 10 frames at confidence 0. A picture too
// small for a walker is refused, naming the video (OpenCV writes nothing under 2 × 2: the
// smallest it writes, and two pixels under the bound); one of the smallest side tracked is not.
TEST(JointTracker, RefusesAPictureTooSmallForAWalker) {
  const fs::path dir = test::makeTempDir("tracker_tiny");
  const auto clip = [&](int side) {
    const fs::path file = dir / ("side_" + std::to_string(side) + ".avi");
    cv::VideoWriter writer(file.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0,
                           cv::Size(side, side));
    EXPECT_TRUE(writer.isOpened()) << side;
    for (int k = 0; k < 10; ++k) writer.write(cv::Mat(side, side, CV_8UC3, cv::Scalar(20.0 * k, 90, 160)));
    return file;
  };
  Keyframes keys;
  keys.keyframes.push_back({0, Eigen::RowVectorXd::Constant(kDims2, 0.5 * kMinTrackedSidePx)});
  for (const int side : {2, kMinTrackedSidePx - 2}) {  // MJPG keeps even sides
    VideoSource tiny(clip(side));
    const std::string size = std::to_string(side) + "x" + std::to_string(side);
    EXPECT_TRUE(test::throwsError([&] { trackJoints(tiny, keys); }, ErrorKind::BadData,
                                  {"side_" + std::to_string(side) + ".avi",
                                   "frame size " + size + " px is too small to track a walker in",
                                   "at least " + std::to_string(kMinTrackedSidePx) + " px"}));
  }
  VideoSource smallest(clip(kMinTrackedSidePx));
  EXPECT_EQ(trackJoints(smallest, keys).jointsPx.rows(), 10);
}

}  // namespace
}  // namespace ew
