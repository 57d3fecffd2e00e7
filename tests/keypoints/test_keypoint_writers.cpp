// Keypoint clips written as MediaPipe CSV and OpenPose JSON (core/keypoints/keypoint_writers.h)
// read back by the project's own readers to the same points; people grouped by their ids
// when the ids follow them (KeypointFrames::trackIdsFollowPeople).
#include <gtest/gtest.h>

#include <cmath>

#include "core/camera/walk_camera.h"
#include "core/common/errors.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_layout.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/keypoints/keypoint_writers.h"
#include "core/keypoints/openpose_writer.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

// Two people over `frames` frames, 33 points each; person 1 is missing on frame 2 and its
// point 5 on every frame.
KeypointFrames twoPeople(int frames) {
  KeypointFrames k;
  k.file = "clip";
  k.format = "test";
  k.pointCount = 33;
  k.imageSize = KeypointImageSize{1280, 720};
  k.rateHz = 25.0;
  k.frames.resize(static_cast<std::size_t>(frames));
  for (int f = 0; f < frames; ++f)
    for (int person = 0; person < 2; ++person) {
      if (person == 1 && f == 2) continue;
      KeypointDetection d;
      d.trackId = person;
      d.points.resize(33, 3);
      for (int p = 0; p < 33; ++p) d.points.row(p) << 100.0 + 500 * person + 3.25 * p + f, 80.0 + 9.5 * p, 0.25 + p / 66.0;
      if (person == 1) d.points.row(5) << std::nan(""), std::nan(""), 0.0;
      k.frames[static_cast<std::size_t>(f)].push_back(d);
    }
  return k;
}

TEST(KeypointWriters, AMediaPipeCsvReadsBackToTheSamePoints) {
  const KeypointFrames k = twoPeople(4);
  const auto file = test::makeTempDir("mediapipe_csv") / "walker.csv";
  writeMediaPipeCsv(file, k, 1, keypointLayoutNamed("MediaPipe-33").points);
  const KeypointFrames back = readKeypointCsv(file);
  ASSERT_EQ(back.frameCount(), 4);
  EXPECT_EQ(back.format, "MediaPipe CSV");
  ASSERT_TRUE(back.imageSize.has_value());
  EXPECT_EQ(back.imageSize->width, 1280);
  ASSERT_TRUE(back.rateHz.has_value());
  EXPECT_NEAR(*back.rateHz, 25.0, 1e-9);
  EXPECT_TRUE(back.frames[2].empty());  // person 1 was not on frame 2
  for (int f : {0, 1, 3}) {
    ASSERT_EQ(back.frames[static_cast<std::size_t>(f)].size(), 1u);
    const auto& got = back.frames[static_cast<std::size_t>(f)][0].points;
    const auto& want = k.frames[static_cast<std::size_t>(f)][1].points;
    for (int p = 0; p < 33; ++p) {
      if (p == 5) {
        EXPECT_TRUE(std::isnan(got(p, 0)));
        continue;
      }
      EXPECT_NEAR(got(p, 0), want(p, 0), 1e-5);
      EXPECT_NEAR(got(p, 1), want(p, 1), 1e-5);
      EXPECT_NEAR(got(p, 2), want(p, 2), 1e-9);
    }
  }
}

TEST(KeypointWriters, OpenPoseJsonKeepsEverybodyAndTheirIds) {
  const KeypointFrames k = twoPeople(3);
  const auto dir = test::makeTempDir("openpose_json");
  writeOpenPoseJson(dir / "keypoints", "clip", k);
  EXPECT_TRUE(std::filesystem::exists(dir / "keypoints" / "clip_000000000000_keypoints.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "keypoints.tmp"));
  const KeypointFrames back = readKeypointFrames(dir / "keypoints");
  ASSERT_EQ(back.frameCount(), 3);
  EXPECT_EQ(back.pointCount, 33);
  ASSERT_EQ(back.frames[0].size(), 2u);
  EXPECT_EQ(back.frames[2].size(), 1u);
  EXPECT_EQ(back.frames[0][1].trackId, 1);
  EXPECT_NEAR(back.frames[1][1].points(7, 0), k.frames[1][1].points(7, 0), 1e-9);
  EXPECT_TRUE(std::isnan(back.frames[1][1].points(5, 0)));  // written 0, 0, 0: missing
}

// The camera experiment's AlphaPose COCO-17 clips (openpose_writer.h) read back as COCO-17 to
// the same joints: the limbs and the head (the ears' centre) where they were, the sternum and
// the pelvis, which COCO-17 lacks, at the shoulders' and the hips' midpoints.
TEST(KeypointWriters, AnAlphaPoseCoco17ClipReadsBackToItsJoints) {
  const EigenwalkerModel& model = defaultRealModel();
  const Eigen::VectorXd t = frameTimes(20, 25.0);
  WalkCamera camera;
  camera.alphaDeg = 60;
  camera.pxPerMm = 0.3;
  camera.cxPx = 640;
  camera.cyPx = 500;
  camera.speedMmS = 1300;
  const Eigen::MatrixXd px = projectWalk(synthesizeFrames(model.mean, model.omegasRadS.mean(), 0.0, t), t, camera);
  const auto folder = test::makeTempDir("alphapose_coco17");
  writeAlphaPoseCoco17(folder / "alphapose-results.json", {{px, {}}});
  KeypointOptions o;
  o.fps = 25.0;
  o.detectorOffsets = false;
  const KeypointTrial trial = readKeypointTrial(folder / "alphapose-results.json", o);
  EXPECT_EQ(trial.format, "AlphaPose JSON");
  ASSERT_NE(trial.layout, nullptr);
  EXPECT_EQ(trial.layout->name, "COCO-17");
  ASSERT_EQ(trial.jointsPx.rows(), px.rows());
  const auto at = [](const Eigen::MatrixXd& m, Eigen::Index f, Joint j) {
    return Eigen::Vector2d(m(f, 2 * index(j)), m(f, 2 * index(j) + 1));
  };
  for (Eigen::Index f = 0; f < px.rows(); ++f) {
    for (Joint j : {Joint::Head, Joint::RShoulder, Joint::LElbow, Joint::RWrist, Joint::LHip, Joint::RKnee, Joint::LAnkle})
      EXPECT_LT((at(trial.jointsPx, f, j) - at(px, f, j)).norm(), 1e-6) << kJointNames[static_cast<std::size_t>(index(j))];
    EXPECT_LT((at(trial.jointsPx, f, Joint::Sternum) - 0.5 * (at(px, f, Joint::RShoulder) + at(px, f, Joint::LShoulder))).norm(), 1e-6);
    EXPECT_LT((at(trial.jointsPx, f, Joint::Pelvis) - 0.5 * (at(px, f, Joint::RHip) + at(px, f, Joint::LHip))).norm(), 1e-6);
  }
}

TEST(KeypointWriters, WithoutAnImageSizeACsvIsRefused) {
  KeypointFrames k = twoPeople(1);
  k.imageSize.reset();
  const auto file = test::makeTempDir("no_size") / "w.csv";
  EXPECT_THROW(writeMediaPipeCsv(file, k, 0, keypointLayoutNamed("MediaPipe-33").points), Error);
  EXPECT_FALSE(std::filesystem::exists(file));
}

// Someone who leaves is not continued by another who appears where they were.
TEST(KeypointTracks, IdsThatFollowPeopleAreKeptApart) {
  KeypointFrames k;
  k.file = "ids";
  k.format = "test";
  k.pointCount = 33;
  k.frames.resize(20);
  for (int f = 0; f < 20; ++f) {
    KeypointDetection d;
    d.trackId = f < 10 ? 4 : 9;  // person 4 leaves at frame 10; 9 appears on the same spot
    d.points.resize(33, 3);
    for (int p = 0; p < 33; ++p) d.points.row(p) << 300.0 + f + p, 100.0 + 8.0 * p, 0.9;
    k.frames[static_cast<std::size_t>(f)].push_back(d);
  }
  EXPECT_EQ(trackPeople(k).size(), 1u);  // by nearness: one person
  k.trackIdsFollowPeople = true;
  const auto people = trackPeople(k);
  ASSERT_EQ(people.size(), 2u);
  EXPECT_EQ(people[0].frames.size(), 10u);
  EXPECT_EQ(people[1].frames.front(), people[0].frames.front() == 0 ? 10 : 0);
}

}  // namespace
}  // namespace ew
