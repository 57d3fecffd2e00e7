// The built-in pose detector (video/blazepose.h, video/pose_detector.h; issue 52): on real
// footage against OpenPose, on videos with nobody, too small or hostile, and its left/right
// consistency on made-up walkers.
#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/common/errors.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/tracking/track_compare.h"
#include "tests/common/test_support.h"
#include "tests/video/pose_models.h"
#include "video/detection_cache.h"
#include "video/pose_detector.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

fs::path balancingTrial() { return test::sharedDataDir() / "pose2sim-balancing"; }

// A video of `frames` frames of `size`, each filled by `paint` (MJPG in AVI: every OpenCV build writes it).
fs::path writeVideo(const fs::path& file, cv::Size size, int frames, const std::function<void(cv::Mat&, int)>& paint) {
  cv::VideoWriter writer(file.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30.0, size);
  EXPECT_TRUE(writer.isOpened());
  for (int f = 0; f < frames; ++f) {
    cv::Mat frame(size, CV_8UC3, cv::Scalar(90, 110, 120));
    paint(frame, f);
    writer.write(frame);
  }
  return file;
}

// [SECTION] real footage

TEST(PoseDetector, FollowsTheBalancingManAsOpenPoseSeesHim) {
  EW_REQUIRE_SHARED_DATA();
  EW_REQUIRE_POSE_MODELS();
  PoseDetectionOptions o;
  o.lastFrame = 39;
  const PoseDetectionRun run = detectPoses(balancingTrial() / "videos" / "cam01.mp4", o);
  ASSERT_EQ(run.poses.size(), 40u);
  EXPECT_EQ(run.people, 1);
  for (const auto& frame : run.poses) EXPECT_EQ(frame.size(), 1u);
  const KeypointTrial ours = cleanKeypoints(keypointFramesOf(run));
  KeypointOptions k;
  k.fps = run.video.fps;
  const KeypointTrial openPose = readKeypointTrial(balancingTrial() / "pose" / "cam01_json", k);
  // OpenPose's file n is the video's frame n + 1 (docs/DETECTOR.md): shoulders to ankles
  // without the hips, as the bar (15 px median on a 1080 x 1920 picture).
  std::array<bool, kJointCount> limbs{};
  for (int j = 3; j < kJointCount; ++j) limbs[static_cast<std::size_t>(j)] = j != 9 && j != 12;
  const TrackDistance d = compareTracks(ours.jointsPx.bottomRows(ours.jointsPx.rows() - 1), 0, openPose.jointsPx, limbs);
  EXPECT_GT(d.jointFrames, 300);
  EXPECT_LT(d.medianAllPx, 15.0);
}

// A cut: the first 20 frames of cam01, then the first 20 of cam03 (the same man seen from
// elsewhere in the room), as one clip at 540 x 960. The crop that followed him before the cut
// loses him or finds him again; either way he is followed on the frames after it.
TEST(PoseDetector, AfterACutThePersonIsFoundAgain) {
  EW_REQUIRE_SHARED_DATA();
  EW_REQUIRE_POSE_MODELS();
  std::vector<cv::Mat> frames;
  for (const char* camera : {"cam01.mp4", "cam03.mp4"}) {
    cv::VideoCapture in((balancingTrial() / "videos" / camera).string());
    cv::Mat f, small;
    for (int i = 0; i < 20 && in.read(f); ++i) {
      cv::resize(f, small, {540, 960}, 0, 0, cv::INTER_AREA);
      frames.push_back(small.clone());
    }
  }
  ASSERT_EQ(frames.size(), 40u);
  const fs::path video = writeVideo(test::makeTempDir("cut") / "cut.avi", {540, 960}, 40,
                                    [&](cv::Mat& m, int f) { frames[static_cast<std::size_t>(f)].copyTo(m); });
  const PoseDetectionRun run = detectPoses(video);
  ASSERT_EQ(run.poses.size(), 40u);
  int before = 0, after = 0;
  for (int f = 0; f < 40; ++f) (f < 20 ? before : after) += run.poses[static_cast<std::size_t>(f)].empty() ? 0 : 1;
  EXPECT_EQ(before, 20);
  EXPECT_GE(after, 18);  // re-found within two frames of the cut at most
  EXPECT_GE(run.people, 1);
  EXPECT_LE(run.people, 2);
}

TEST(PoseDetector, AVideoWithNobodyInItHasNobody) {
  EW_REQUIRE_POSE_MODELS();
  const fs::path video = writeVideo(test::makeTempDir("nobody") / "empty.avi", {320, 240}, 12, [](cv::Mat& m, int f) {
    cv::rectangle(m, cv::Rect(10 + f * 5, 40, 60, 30), cv::Scalar(20, 200, 60), cv::FILLED);  // a moving box
  });
  const PoseDetectionRun run = detectPoses(video);
  EXPECT_EQ(run.people, 0);
  ASSERT_EQ(run.poses.size(), 12u);
  for (const auto& frame : run.poses) EXPECT_TRUE(frame.empty());
  try {
    cleanKeypoints(keypointFramesOf(run));
    FAIL() << "a clip with nobody was cleaned";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nobody"), std::string::npos) << e.what();
  }
}

TEST(PoseDetector, APictureTooSmallForAPersonIsRefused) {
  EW_REQUIRE_POSE_MODELS();
  const fs::path video = writeVideo(test::makeTempDir("tiny") / "tiny.avi", {16, 16}, 5, [](cv::Mat&, int) {});
  try {
    detectPoses(video);
    FAIL() << "a 16 x 16 video was searched";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadData);
    EXPECT_NE(std::string(e.what()).find("tiny.avi"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("too small"), std::string::npos) << e.what();
  }
}

TEST(PoseDetector, AFileThatIsNoVideoIsNamed) {
  EW_REQUIRE_POSE_MODELS();
  const fs::path file = test::makeTempDir("corrupt") / "corrupt.mp4";
  std::string bytes(3012, '\x5a');
  bytes.replace(0, 12, std::string("\x00\x00\x00\x18" "ftypmp42", 12));  // an MP4's first box, then noise
  test::writeBinaryFile(file, bytes);
  try {
    detectPoses(file);
    FAIL() << "a corrupt file was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("corrupt.mp4"), std::string::npos) << e.what();
  }
}

TEST(PoseDetector, MissingModelsSayWhichCommandFetchesThem) {
  const fs::path empty = test::makeTempDir("no_models");
  const char* before = std::getenv("EIGENWALKER_MODELS");
  const std::string saved = before ? before : "";
  setenv("EIGENWALKER_MODELS", empty.c_str(), 1);
  EXPECT_FALSE(findPoseModels().has_value());
  try {
    requirePoseModels();
    FAIL() << "missing models were not noticed";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    EXPECT_NE(std::string(e.what()).find("tools/pose_model/fetch_model.sh"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(empty.string()), std::string::npos) << e.what();
  }
  if (before) setenv("EIGENWALKER_MODELS", saved.c_str(), 1);
  else unsetenv("EIGENWALKER_MODELS");
}

TEST(PoseDetector, HostileFramesAndCropsFindNobody) {
  EW_REQUIRE_POSE_MODELS();
  const PoseModelFiles files = requirePoseModels();
  LandmarkModel landmarks(files.landmarks);
  PersonDetector people(files.personDetector);
  const cv::Mat frame(240, 320, CV_8UC3, cv::Scalar(30, 30, 30));
  const double nan = std::nan("");
  for (const PoseRoi& roi : {PoseRoi{{nan, 100}, 100, 0}, PoseRoi{{100, 100}, nan, 0}, PoseRoi{{100, 100}, 100, nan},
                             PoseRoi{{100, 100}, 0, 0}, PoseRoi{{100, 100}, 1e300, 0}, PoseRoi{{1e12, 5}, 100, 0}}) {
    EXPECT_EQ(landmarks.detect(frame, roi).poseScore, 0.0);
  }
  EXPECT_EQ(landmarks.detect(cv::Mat(), PoseRoi{{100, 100}, 100, 0}).poseScore, 0.0);
  EXPECT_TRUE(people.detect(cv::Mat()).empty());
  EXPECT_TRUE(people.detect(cv::Mat(1, 1, CV_8UC3, cv::Scalar::all(0))).empty());
  EXPECT_TRUE(people.detect(frame, cv::Rect(5000, 5000, 10, 10)).empty());
  EXPECT_TRUE(detectPeopleWithTiles(people, frame).empty());  // a plain grey frame
}

// [SECTION] left and right through time

// A walker in profile, 200 px tall: each left/right pair swings in counter-phase, so the
// legs and arms cross twice a stride; `swapped` frames have their labels exchanged, as the
// model exchanges them.
std::vector<PoseLandmarks> profileWalker(int frames, double fps, const std::vector<int>& swapped) {
  std::vector<PoseLandmarks> out(static_cast<std::size_t>(frames));
  for (int f = 0; f < frames; ++f) {
    PoseLandmarks& p = out[static_cast<std::size_t>(f)];
    p.roi = PoseRoi{{300.0 + 2.0 * f, 200.0}, 250.0, 0.0};
    const double phase = 2.0 * M_PI * 0.9 * f / fps;
    for (int i = 0; i < kBlazePoseLandmarks; ++i) {
      const bool left = i % 2 == 1;
      const double height = 200.0 * (1.0 - i / 33.0);
      const double swing = (i >= 13 ? 40.0 : 4.0) * std::sin(phase + (left ? M_PI : 0.0)) * (i / 33.0);
      p.points[static_cast<std::size_t>(i)] = {p.roi.centre.x + swing, 300.0 - height, 0, 1, 1};
    }
    if (std::find(swapped.begin(), swapped.end(), f) != swapped.end()) swapLeftRight(p);
  }
  return out;
}

std::vector<const PoseLandmarks*> pointers(const std::vector<PoseLandmarks>& poses) {
  std::vector<const PoseLandmarks*> out;
  for (const auto& p : poses) out.push_back(&p);
  return out;
}

TEST(ConsistentLeftRight, UndoesTheSwapsTheModelMakesAndNoOthers) {
  const std::vector<int> swapped = {10, 11, 12, 13, 14, 40, 71, 72};
  const auto poses = profileWalker(90, 30.0, swapped);
  const auto swaps = consistentLeftRight(pointers(poses));
  for (int f = 0; f < 90; ++f)
    EXPECT_EQ(swaps[static_cast<std::size_t>(f)], std::find(swapped.begin(), swapped.end(), f) != swapped.end())
        << "frame " << f;
}

TEST(ConsistentLeftRight, LeavesLimbsThatCrossAlone) {
  // Two seconds of walking at 25 fps: the legs cross seven times, and nothing is swapped.
  const auto poses = profileWalker(50, 25.0, {});
  const auto swaps = consistentLeftRight(pointers(poses));
  EXPECT_EQ(std::count(swaps.begin(), swaps.end(), true), 0);
  EXPECT_TRUE(consistentLeftRight({}).empty());
}

// [SECTION] the detection cache

TEST(DetectionCache, ARunReadsBackAsItWasAndADamagedFileIsIgnored) {
  PoseDetectionRun run;
  run.video = {"v.mp4", 640, 480, 25.0, 2, "avc1"};
  run.firstFrame = 3;
  run.people = 1;
  FollowedPose p;
  p.personId = 0;
  p.landmarks.poseScore = 0.9;
  p.landmarks.roi = PoseRoi{{1.5, 2.5}, 300, 0.1};
  for (int i = 0; i < kBlazePoseLandmarks; ++i) p.landmarks.points[static_cast<std::size_t>(i)] = {i * 1.25, i * 2.5, -1.0 * i, 0.5, 0.75};
  run.poses = {{p}, {}};
  const fs::path dir = test::makeTempDir("cache");
  ASSERT_EQ(saveCachedDetections(dir / "c.json", run), "");
  const auto back = loadCachedDetections(dir / "c.json", "v.mp4");
  ASSERT_TRUE(back.has_value());
  ASSERT_EQ(back->poses.size(), 2u);
  ASSERT_EQ(back->poses[0].size(), 1u);
  EXPECT_EQ(back->firstFrame, 3);
  EXPECT_EQ(back->poses[0][0].landmarks.points[7].x, 7 * 1.25);
  EXPECT_EQ(back->poses[0][0].landmarks.roi.rotationRad, 0.1);
  test::writeBinaryFile(dir / "c.json", test::readTextFile(dir / "c.json").substr(0, 200));
  EXPECT_FALSE(loadCachedDetections(dir / "c.json", "v.mp4").has_value());
  run.cancelled = true;
  EXPECT_NE(saveCachedDetections(dir / "d.json", run), "");
  EXPECT_FALSE(fs::exists(dir / "d.json"));
}

TEST(DetectionCache, TheKeyIsTheContentNotTheName) {
  const fs::path dir = test::makeTempDir("content_key");
  test::writeBinaryFile(dir / "a.mp4", "same bytes");
  test::writeBinaryFile(dir / "b.mp4", "same bytes");
  test::writeBinaryFile(dir / "c.mp4", "same bytez");
  EXPECT_EQ(videoContentKey(dir / "a.mp4"), videoContentKey(dir / "b.mp4"));
  EXPECT_NE(videoContentKey(dir / "a.mp4"), videoContentKey(dir / "c.mp4"));
  PoseDetectionOptions full, heavy;
  heavy.model = PoseModelSize::Heavy;
  EXPECT_NE(detectionCacheFile("k", full), detectionCacheFile("k", heavy));
  EXPECT_THROW(videoContentKey(dir / "missing.mp4"), Error);
}

}  // namespace
}  // namespace ew
