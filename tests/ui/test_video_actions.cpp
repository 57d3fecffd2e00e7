// The viewer's video actions without a window (ui/app/video_actions.h): a joint let go while a
// track runs stops that track and tracks again with the new keyframe. The running track may see
// the cancel or finish first (the test cannot choose which); either way it is tracked again.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>

#include "core/keypoints/keypoint_trial.h"
#include "core/keypoints/openpose_writer.h"
#include "core/synth/population.h"
#include "core/tracking/keyframes.h"
#include "core/tracking/track_confidence.h"
#include "tests/common/test_support.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/undo.h"
#include "ui/app/video_poll.h"
#include "ui/panels/data_panel.h"
#include "video/synthetic_footage.h"

namespace ew::ui {
namespace {

// Polls until no track runs and none is waiting to start (at most a minute).
void settle(AppState& s) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while ((s.video.track.running() || s.video.session->trackAgainWhenStopped) &&
         std::chrono::steady_clock::now() < until) {
    pollVideo(s);
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

// A synthetic walker's first `rows` frames (30 fps) filmed 30° off the side into `video`; the
// true joints in pixels.
Eigen::MatrixXd filmWalker(const std::filesystem::path& video, Eigen::Index rows) {
  PopulationOptions o;
  o.count = 1;
  o.simulation.rateHz = 30.0;
  const Eigen::MatrixXd frames = generatePopulation(o).front().trial.positionsMm.topRows(rows);
  return writeFootage(video, frames, cameraBeside(frames, 30.0, 4500.0), 30.0);
}

// Equal element for element, NaN where the other is NaN.
bool same(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  return a.rows() == b.rows() && a.cols() == b.cols() &&
         ((a.array() == b.array()) || (a.array().isNaN() && b.array().isNaN())).all();
}

// A filmed walker in a fresh folder (walk.avi) with the keyframe file keys.json marked on
// `marked` from the true joints.
struct Filmed {
  std::filesystem::path dir, video, keys;
  Eigen::MatrixXd truthPx;
};

Filmed filmWithKeyframes(const std::string& name, Eigen::Index rows, const std::vector<int>& marked) {
  Filmed f;
  f.dir = test::makeTempDir(name);
  f.video = f.dir / "walk.avi";
  f.truthPx = filmWalker(f.video, rows);
  f.keys = f.dir / "keys.json";
  writeKeyframes(f.keys, keyframesFromTrack(f.truthPx, marked, "walk.avi"));
  return f;
}

// The filmed walker opened, its keyframes read and tracked.
void openAndTrack(AppState& s, const Filmed& f) {
  actions::openVideo(s, f.video);
  actions::loadKeyframes(s, f.keys);
  actions::startTracking(s);
  settle(s);
}

TEST(VideoActions, AJointLetGoWhileTrackingTracksAgainWithIt) {
  const Filmed f = filmWithKeyframes("video_actions", 90, {0, 60});
  const Eigen::MatrixXd& truthPx = f.truthPx;
  AppState s;
  openAndTrack(s, f);
  ASSERT_TRUE(s.video.session->tracked);
  EXPECT_EQ(s.video.session->tracked->keyframes.keyframes.size(), 2u);

  actions::startTracking(s);
  s.video.session->frame = 30;
  const int knee = index(Joint::RKnee);
  actions::markJoint(s, Joint::RKnee, truthPx(30, 2 * knee), truthPx(30, 2 * knee + 1));
  EXPECT_FALSE(actions::letGoOfJoint(s)) << "a track was running: it is asked to stop first";
  EXPECT_TRUE(s.video.session->trackAgainWhenStopped);
  settle(s);
  ASSERT_TRUE(s.video.session->tracked);
  EXPECT_FALSE(s.video.track.running());
  EXPECT_EQ(s.video.session->tracked->keyframes.keyframes.size(), 3u);
  EXPECT_EQ(s.video.session->trackError, "");
}

// The open video taken as detected (one person, no detections of its own) and fitted: what the
// marks correct. The detector itself is tested in tests/video.
void takeAsDetected(AppState& s, const Filmed& f) {
  auto d = std::make_shared<DetectedVideo>();
  d->video = f.video;
  d->frames = std::make_shared<const KeypointFrames>();
  d->people = 1;
  s.video.session->detected = d;
  actions::fitDetections(s);
}

// On a detected video a joint let go is a correction (issue 52): the detections are fitted
// again with the keyframes as their corrections, and undo, redo and removing a keyframe fit
// them again; guided marking waits for Done. A track made since takes the marks back.
TEST(VideoActions, OnADetectedVideoTheMarksAreCorrectionsOfTheFit) {
  const Filmed f = filmWithKeyframes("video_actions_correct", 30, {0});
  AppState s;
  actions::openVideo(s, f.video);
  EXPECT_FALSE(actions::correctsDetections(s)) << "not detected: mark and track";
  takeAsDetected(s, f);
  ASSERT_TRUE(actions::correctsDetections(s));
  ASSERT_TRUE(s.clip.settings);
  EXPECT_FALSE(s.clip.settings->corrections);

  const int knee = index(Joint::RKnee);
  s.video.session->frame = 12;
  actions::markJoint(s, Joint::RKnee, f.truthPx(12, 2 * knee) + 20.0, f.truthPx(12, 2 * knee + 1));
  EXPECT_TRUE(actions::letGoOfJoint(s)) << "the fit starts again";
  ASSERT_TRUE(s.clip.settings->corrections);
  const auto corrected = s.clip.settings->corrections;
  ASSERT_EQ(corrected->keyframes.size(), 1u);
  EXPECT_EQ(corrected->keyframes[0].frame, 12);
  EXPECT_EQ(corrected->keyframes[0].jointsPx.array().isFinite().count(), 2) << "the knee alone";
  EXPECT_EQ(corrected->keyframes[0].jointsPx(2 * knee), f.truthPx(12, 2 * knee) + 20.0);
  actions::fitDetections(s);
  EXPECT_EQ(s.clip.settings->corrections, corrected) << "the same corrections: no new fit";

  actions::undoKeyframes(s);
  EXPECT_FALSE(s.clip.settings->corrections);
  actions::redoKeyframes(s);
  ASSERT_TRUE(s.clip.settings->corrections);
  EXPECT_TRUE(sameKeyframes(*s.clip.settings->corrections, *corrected));
  actions::removeKeyframe(s, 12);
  EXPECT_FALSE(s.clip.settings->corrections);

  actions::startMarking(s);
  actions::markJoint(s, Joint::Head, 10.0, 10.0);
  EXPECT_FALSE(actions::letGoOfJoint(s));
  EXPECT_FALSE(s.clip.settings->corrections) << "while marking, the fit waits for Done";
  actions::stopMarking(s);
  ASSERT_TRUE(s.clip.settings->corrections);
  EXPECT_EQ(s.clip.settings->corrections->keyframes.size(), 1u);
}

// The app's undo (Ctrl+Z, ui/app/undo.h) takes back the latest change, whichever history holds
// it: a correction made after a setting's change is undone first, then the setting; redo
// retraces them. Before, outside guided marking it undid the settings only and skipped the
// correction the user had just made.
TEST(VideoActions, UndoTakesBackTheLatestChangeWhetherACorrectionOrASetting) {
  const Filmed f = filmWithKeyframes("video_actions_undo_order", 30, {0});
  AppState s;
  actions::openVideo(s, f.video);
  takeAsDetected(s, f);
  ASSERT_EQ(s.doc.mode, Mode::Clip);
  const auto settle = [&s] { s.history.observe(captureParameters(s), captureParameterContext(s), true); };
  settle();
  ASSERT_EQ(s.view.theme, Theme::Dark);
  s.view.theme = Theme::Light;  // a setting changed first
  settle();
  const int knee = index(Joint::RKnee);
  s.video.session->frame = 12;
  actions::markJoint(s, Joint::RKnee, f.truthPx(12, 2 * knee) + 20.0, f.truthPx(12, 2 * knee + 1));
  actions::letGoOfJoint(s);  // then a correction
  settle();
  ASSERT_TRUE(s.clip.settings->corrections);
  ASSERT_TRUE(canUndo(s));

  undo(s);
  EXPECT_FALSE(s.clip.settings->corrections) << "the correction, the latest change, first";
  EXPECT_EQ(s.view.theme, Theme::Light);
  undo(s);
  EXPECT_EQ(s.view.theme, Theme::Dark) << "then the setting";
  EXPECT_FALSE(canUndo(s));
  redo(s);
  EXPECT_EQ(s.view.theme, Theme::Light) << "redo retraces: the setting first";
  EXPECT_FALSE(s.clip.settings->corrections);
  redo(s);
  EXPECT_TRUE(s.clip.settings->corrections) << "then the correction";
  EXPECT_FALSE(canRedo(s));
  // A new change drops what could be redone, whichever history holds it.
  undo(s);
  ASSERT_TRUE(canRedo(s));
  s.view.theme = Theme::Dark;
  settle();
  EXPECT_FALSE(canRedo(s)) << "the correction undone before the setting's change";
  redo(s);
  EXPECT_FALSE(s.clip.settings->corrections);
  undo(s);
  EXPECT_EQ(s.view.theme, Theme::Light);
  redo(s);
  EXPECT_EQ(s.view.theme, Theme::Dark);
  redo(s);
  EXPECT_FALSE(s.clip.settings->corrections) << "still dropped";
  s.view.theme = Theme::Light;
  settle();
  actions::redoKeyframes(s);  // the marking panel's own Redo still has it
  ASSERT_TRUE(s.clip.settings->corrections);

  // Out of the clip mode the keyframes are not shown, and not undone there.
  s.doc.mode = Mode::Reconstruct;
  settle();
  undo(s);
  EXPECT_EQ(s.doc.mode, Mode::Clip) << "the mode's change undone, not the hidden correction";
  EXPECT_TRUE(s.clip.settings->corrections);
}

// Marks far outside the picture, from a keyframe file or a pose estimator's keypoints, are
// refused with the reason and leave the keyframes as they were (once, a track from them crashed).
TEST(VideoActions, MarksFarOutsideThePictureAreRefusedWhereverTheyComeFrom) {
  const auto dir = test::makeTempDir("video_actions_far");
  const auto video = dir / "walk.avi";
  Eigen::MatrixXd far = filmWalker(video, 12);
  far.col(0).array() += 1e6;  // the head, a million pixels to the right
  const auto keys = dir / "far.json";
  writeKeyframes(keys, keyframesFromTrack(far, {0}, "walk.avi"));
  writeOpenPoseBody25(dir / "far_keypoints", {OpenPosePerson{far, {}}});

  AppState s;
  actions::openVideo(s, video);
  const auto refused = [](const std::function<void()>& action) {
    try {
      action();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what()).find("far outside") != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(refused([&] { actions::loadKeyframes(s, keys); }));
  EXPECT_TRUE(refused([&] { actions::markFromKeypoints(s, dir / "far_keypoints"); }));
  EXPECT_TRUE(s.video.session->keyframes.keyframes.empty());
}

// A video cut short: the frame past the cut is said once in the banner, with the length the
// video is now taken to have (the frame cache's error was once seen by nobody).
TEST(VideoActions, AVideoCutShortSaysSoInTheBanner) {
  const auto dir = test::makeTempDir("video_actions_cut");
  const auto whole = dir / "whole.avi";
  filmWalker(whole, 60);
  const std::string bytes = test::readTextFile(whole);
  const auto cut = dir / "cut.avi";
  test::writeBinaryFile(cut, bytes.substr(0, bytes.size() / 2));

  AppState s;
  actions::openVideo(s, cut);
  const int announced = s.video.session->frameCount();
  for (int k = 0; k < announced && s.video.session->frames->error().empty(); ++k)
    s.video.session->frames->waitFrame(k);
  ASSERT_FALSE(s.video.session->frames->error().empty()) << "half the file decoded whole";
  pollVideo(s);
  ASSERT_TRUE(s.notices.banner.has_value());
  EXPECT_EQ(s.notices.banner->title, "Part of cut.avi cannot be decoded");
  EXPECT_NE(s.notices.banner->detail.find("taken to end after " +
                                       std::to_string(s.video.session->frameCount())),
            std::string::npos)
      << s.notices.banner->detail;
  actions::dismissNotice(s);
  pollVideo(s);
  EXPECT_FALSE(s.notices.banner.has_value()) << "said once";
}

// A video dropped on the window opens, and so does a keyframe file dropped alone (with the
// video it names beside it); until 2026-11-27 a drop refused both, and the file browser did not
// list them: only the command line opened a video.
TEST(VideoActions, AVideoOrItsKeyframeFileDroppedOpensIt) {
  const Filmed f = filmWithKeyframes("video_actions_drop", 12, {0, 6});
  const auto &dir = f.dir, &video = f.video, &keys = f.keys;

  AppState dropped;
  dropped.video.detectWhenOpens = false;  // opening only (the detector: the test below)
  actions::drop(dropped, {video});
  ASSERT_TRUE(dropped.video.session.has_value());
  EXPECT_EQ(dropped.video.session->path, video);
  EXPECT_EQ(dropped.doc.mode, Mode::Clip);

  AppState keysAlone;
  actions::drop(keysAlone, {keys});
  ASSERT_TRUE(keysAlone.video.session.has_value());
  EXPECT_EQ(keysAlone.video.session->path, video);
  EXPECT_EQ(keysAlone.video.session->keyframes.keyframes.size(), 2u);

  // Another video open: the keyframes open the video they name, beside them.
  const auto other = dir / "other.avi";
  filmWalker(other, 12);
  AppState otherOpen;
  actions::openVideo(otherOpen, other);
  actions::drop(otherOpen, {keys});
  ASSERT_TRUE(otherOpen.video.session.has_value());
  EXPECT_EQ(otherOpen.video.session->path, video);
  EXPECT_EQ(otherOpen.video.session->keyframes.keyframes.size(), 2u);

  EXPECT_EQ(browserFormat("walk.avi"), browserFormat("Clip.MP4"));
  EXPECT_GE(browserFormat("walk.avi"), 0);
  EXPECT_GE(browserFormat("keys.json"), 0);
  EXPECT_GE(browserFormat("model.ewm"), 0);
  EXPECT_EQ(browserFormat("notes.txt"), -1);
}

// Issue 52: a video dropped alone goes to the built-in detector; with its keyframe file it is
// for marking and is not detected. Without the models it opens all the same, and the amber
// banner says which command fetches them; tracking is refused while a detection runs.
TEST(VideoActions, AVideoDroppedAloneGoesToTheDetectorAndSaysWhenTheModelsAreMissing) {
  const Filmed f = filmWithKeyframes("video_actions_detect", 12, {0, 6});
  const auto noModels = f.dir / "no_models";
  std::filesystem::create_directories(noModels);
  const char* before = std::getenv("EIGENWALKER_MODELS");
  const std::string kept = before ? before : "";
  setenv("EIGENWALKER_MODELS", noModels.c_str(), 1);

  AppState alone;
  actions::drop(alone, {f.video});
  ASSERT_TRUE(alone.video.session.has_value()) << "opened for marking all the same";
  EXPECT_FALSE(alone.video.detect.running());
  ASSERT_TRUE(alone.notices.banner.has_value());
  EXPECT_FALSE(alone.notices.banner->error);
  EXPECT_EQ(alone.notices.banner->title, "Detecting people needs the pose models");
  EXPECT_NE(alone.notices.banner->detail.find("tools/pose_model/fetch_model.sh"), std::string::npos);
  EXPECT_EQ(alone.notices.failures, 0);
  EXPECT_THROW(actions::startDetection(alone), std::invalid_argument);
  EXPECT_NE(alone.video.session->detectError.find("fetch_model.sh"), std::string::npos);

  AppState withKeys;
  actions::drop(withKeys, {f.video, f.keys});
  ASSERT_TRUE(withKeys.video.session.has_value());
  EXPECT_FALSE(withKeys.notices.banner.has_value()) << "a video with its keyframes is not detected";
  EXPECT_TRUE(withKeys.video.session->detectError.empty());

  AppState off;
  actions::setDetectWhenVideoOpens(off, false);
  actions::drop(off, {f.video});
  EXPECT_FALSE(off.notices.banner.has_value());

  if (before) setenv("EIGENWALKER_MODELS", kept.c_str(), 1);
  else unsetenv("EIGENWALKER_MODELS");
}

// The viewer saves a track as `eigenwalker-cli track --out` does (the same files, read back to
// the same joints) with the keyframes it was tracked from; before a track there is nothing to
// save, and it says so.
TEST(VideoActions, TheTrackIsSavedAsTheCommandLineSavesIt) {
  const Filmed f = filmWithKeyframes("video_actions_save", 30, {0, 20});
  AppState s;
  actions::openVideo(s, f.video);
  EXPECT_THROW(actions::saveTrack(s, f.dir / "early"), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(f.dir / "early"));
  openAndTrack(s, f);
  ASSERT_TRUE(s.video.session->tracked);

  const auto out = f.dir / "saved";
  actions::saveTrack(s, out);
  for (const char* file : {"track_2d.csv", "confidence.csv", "walk_keyframes.json"})
    EXPECT_TRUE(std::filesystem::exists(out / file)) << file;
  KeypointOptions o;
  o.fps = 30.0;
  const KeypointTrial back = readKeypointTrial(out / "keypoints", o);
  const JointTrack& t = s.video.session->tracked->track;
  ASSERT_EQ(back.jointsPx.rows(), t.jointsPx.rows());
  // Every joint as tracked, with its confidence (a reader leaves out a point under 0.3, as
  // Pose2Sim does); BODY_25 has a neck, not a sternum, so reading it back puts the sternum
  // between the shoulders (the layout's definition, assets/keypoint-layouts/).
  const auto at = [](const Eigen::MatrixXd& m, Eigen::Index r, Joint j) -> Eigen::Vector2d {
    return m.row(r).segment<2>(2 * index(j)).transpose();
  };
  Eigen::Index compared = 0;
  for (Eigen::Index r = 0; r < t.jointsPx.rows(); ++r) {
    for (int j = 0; j < kJointCount; ++j) {
      const auto joint = static_cast<Joint>(j);
      const Eigen::Vector2d expected =
          joint == Joint::Sternum
              ? Eigen::Vector2d(0.5 * (at(t.jointsPx, r, Joint::RShoulder) + at(t.jointsPx, r, Joint::LShoulder)))
              : at(t.jointsPx, r, joint);
      const bool sure = joint == Joint::Sternum
                            ? std::min(t.confidence(r, index(Joint::RShoulder)), t.confidence(r, index(Joint::LShoulder))) >= o.minConfidence
                            : t.confidence(r, j) >= o.minConfidence;
      if (!sure) continue;
      ++compared;
      EXPECT_LT((at(back.jointsPx, r, joint) - expected).norm(), 0.01) << kJointNames[j] << " frame " << r;
    }
  }
  EXPECT_GT(compared, 8 * t.jointsPx.size() / 20) << "most joint-frames are sure";
  const Keyframes savedKeys = readKeyframes(out / "walk_keyframes.json");
  ASSERT_EQ(savedKeys.keyframes.size(), 2u);
  EXPECT_EQ(savedKeys.keyframes[1].frame, 20);
  EXPECT_EQ(savedKeys.video, "walk.avi");
  // The marks alone, under the same name, into a folder made for them.
  actions::saveKeyframesInto(s, f.dir / "marks" / "only");
  EXPECT_EQ(readKeyframes(f.dir / "marks" / "only" / "walk_keyframes.json").keyframes.size(), 2u);
}

// The least sure frame is the tracked frame, not a keyframe, of lowest mean confidence; a
// keyframe put there moves it elsewhere; without a track there is none.
TEST(VideoActions, TheLeastSureFrameIsTheWeakestFrameNotAKeyframe) {
  const Filmed f = filmWithKeyframes("video_actions_least", 40, {0});
  const Eigen::MatrixXd& truthPx = f.truthPx;
  AppState s;
  actions::openVideo(s, f.video);
  EXPECT_EQ(actions::leastSureTrackedFrame(s), -1);
  openAndTrack(s, f);
  s.video.session->frame = 20;
  EXPECT_EQ(actions::neighbouringKeyframe(s, -1), 0);
  EXPECT_EQ(actions::neighbouringKeyframe(s, 1), -1) << "the only keyframe is frame 0";
  s.video.session->frame = 0;
  EXPECT_EQ(actions::neighbouringKeyframe(s, -1), -1) << "none before the first";
  ASSERT_TRUE(s.video.session->tracked);
  const JointTrack& t = s.video.session->tracked->track;
  const int least = actions::leastSureTrackedFrame(s);
  ASSERT_GT(least, 0) << "frame 0 is the keyframe";
  for (Eigen::Index r = 1; r < t.confidence.rows(); ++r)
    EXPECT_GE(t.confidence.row(r).mean(), t.confidence.row(least - t.firstFrame).mean()) << "frame " << r;
  s.video.session->frame = least;
  const int j = index(Joint::Head);
  actions::markJoint(s, Joint::Head, truthPx(least, 2 * j), truthPx(least, 2 * j + 1));
  EXPECT_NE(actions::leastSureTrackedFrame(s), least) << "now a keyframe";
}

// The frame to mark next is framesToMarkNext's on the track with the keyframes as they are
// now: a frame marked since the track was made is not offered again; without a track there
// is none.
TEST(VideoActions, TheFrameToMarkNextIsNoKeyframeAndMovesOnOnceMarked) {
  const Filmed f = filmWithKeyframes("video_actions_next", 40, {0});
  AppState s;
  actions::openVideo(s, f.video);
  EXPECT_EQ(actions::nextFrameToMark(s), -1);
  openAndTrack(s, f);
  ASSERT_TRUE(s.video.session->tracked);
  const JointTrack& t = s.video.session->tracked->track;
  const int next = actions::nextFrameToMark(s);
  EXPECT_EQ(std::vector<int>{next}, framesToMarkNext(t.jointsPx, t.firstFrame, {0}, 1));
  ASSERT_GT(next, 0) << "frame 0 is the keyframe";
  s.video.session->frame = next;
  const int j = index(Joint::Head);
  actions::markJoint(s, Joint::Head, f.truthPx(next, 2 * j), f.truthPx(next, 2 * j + 1));
  const int after = actions::nextFrameToMark(s);
  EXPECT_NE(after, next) << "now a keyframe";
  EXPECT_EQ(std::vector<int>{after}, framesToMarkNext(t.jointsPx, t.firstFrame, {0, next}, 1));
}

// A joint dragged between two keyframes tracks again only the frames between them, and the
// track that comes out is the one tracking the whole range again gives, frame for frame.
// Settings that reach over the whole range (the flattened background, the model loop) or an
// edit of the first keyframe track it all again.
TEST(VideoActions, AnEditBetweenKeyframesTracksOnlyTheFramesBetweenItsNeighbours) {
  const Filmed f = filmWithKeyframes("video_actions_local", 60, {0, 30});
  AppState s;
  openAndTrack(s, f);
  ASSERT_TRUE(s.video.session->tracked);
  const JointTrack before = s.video.session->tracked->track;

  VideoSession& v = *s.video.session;
  v.frame = 45;
  const int knee = index(Joint::RKnee);
  actions::markJoint(s, Joint::RKnee, f.truthPx(45, 2 * knee), f.truthPx(45, 2 * knee + 1));
  EXPECT_EQ(actions::neighbouringKeyframe(s, -1), 30);
  v.frame = 10;
  EXPECT_EQ(actions::neighbouringKeyframe(s, 1), 30) << "the nearest after, of 30 and 45";
  v.frame = 45;
  const TrackSettings settings = trackSettingsOf(v, 59);
  const auto around = localRetrackRange(*v.tracked, v.keyframes, settings);
  ASSERT_TRUE(around.has_value());
  EXPECT_EQ(*around, std::make_pair(30, 59));
  TrackSettings flattened = settings;
  flattened.flattenBackground = true;
  EXPECT_FALSE(localRetrackRange(*v.tracked, v.keyframes, flattened).has_value());
  TrackSettings looped = settings;
  looped.modelLoopRounds = 1;
  EXPECT_FALSE(localRetrackRange(*v.tracked, v.keyframes, looped).has_value());
  Keyframes outside = v.keyframes;
  outside.keyframes.push_back(outside.keyframes.back());
  outside.keyframes.back().frame = 70;  // past the tracked frames 0-59
  EXPECT_FALSE(localRetrackRange(*v.tracked, outside, settings).has_value());
  Keyframes firstMoved = v.keyframes;
  firstMoved.keyframes.front().jointsPx(1) -= 20.0;  // the head 20 px higher: a taller person
  EXPECT_FALSE(localRetrackRange(*v.tracked, firstMoved, settings).has_value());

  EXPECT_TRUE(actions::letGoOfJoint(s));
  settle(s);
  ASSERT_TRUE(v.tracked);
  ASSERT_EQ(v.tracked->keyframes.keyframes.size(), 3u);
  const JointTrack& local = v.tracked->track;
  const TrackedVideo whole = trackVideo(f.video, v.keyframes, settings, nullptr, {});
  EXPECT_TRUE(same(local.jointsPx, whole.track.jointsPx));
  EXPECT_TRUE(same(local.confidence, whole.track.confidence));
  EXPECT_TRUE(same(local.jointsPx.topRows(30), before.jointsPx.topRows(30))) << "frames 0-29 kept";
  EXPECT_FALSE(same(local.jointsPx.bottomRows(29), before.jointsPx.bottomRows(29)));
}

// With the trunk held (each pass holds it to its own keyframe), the same.
TEST(VideoActions, AnEditBetweenKeyframesWithTheTrunkHeldTracksTheSameAsTheWholeRange) {
  const Filmed f = filmWithKeyframes("video_actions_local_trunk", 45, {0, 20});
  AppState s;
  actions::openVideo(s, f.video);
  actions::setHoldTheTrunk(s, true);
  actions::loadKeyframes(s, f.keys);
  actions::startTracking(s);
  settle(s);
  ASSERT_TRUE(s.video.session->tracked);
  VideoSession& v = *s.video.session;
  v.frame = 32;
  const int wrist = index(Joint::LWrist);
  actions::markJoint(s, Joint::LWrist, f.truthPx(32, 2 * wrist), f.truthPx(32, 2 * wrist + 1));
  const TrackSettings settings = trackSettingsOf(v, 44);
  ASSERT_EQ(localRetrackRange(*v.tracked, v.keyframes, settings), std::make_optional(std::make_pair(20, 44)));
  EXPECT_TRUE(actions::letGoOfJoint(s));
  settle(s);
  const TrackedVideo whole = trackVideo(f.video, v.keyframes, settings, nullptr, {});
  EXPECT_TRUE(same(v.tracked->track.jointsPx, whole.track.jointsPx));
  EXPECT_TRUE(same(v.tracked->track.confidence, whole.track.confidence));
}

// Before a track, playback plays the video's own frames at its rate × the speed, round its end,
// one frame at most per call and none while the frame shown is still decoding.
TEST(VideoActions, PlaybackStepsTheVideosOwnFramesAtItsRate) {
  const auto dir = test::makeTempDir("video_actions_play");
  const auto video = dir / "walk.avi";
  filmWalker(video, 12);
  AppState s;
  actions::openVideo(s, video);
  ASSERT_TRUE(actions::stepsVideoFrames(s));
  VideoSession& v = *s.video.session;
  s.view.playback.playing = true;
  s.view.playback.speed = 0.5f;
  v.shownIndex = 0;
  actions::advancePlayback(s, 1.0 / 30.0);
  EXPECT_EQ(v.frame, 0) << "half a frame at half speed";
  actions::advancePlayback(s, 1.0 / 30.0);
  EXPECT_EQ(v.frame, 1);
  actions::advancePlayback(s, 1.0);
  EXPECT_EQ(v.frame, 1) << "frame 1 is not shown yet: playback holds";
  v.shownIndex = 1;
  actions::advancePlayback(s, 1.0);
  EXPECT_EQ(v.frame, 2) << "one frame at most per drawn frame";
  v.frame = v.shownIndex = v.frameCount() - 1;
  actions::advancePlayback(s, 2.0 / 30.0);
  EXPECT_EQ(v.frame, 0) << "round the end";
  s.view.playback.playing = false;
  v.shownIndex = 0;
  actions::advancePlayback(s, 1.0);
  EXPECT_EQ(v.frame, 0) << "paused";
}

}  // namespace
}  // namespace ew::ui
