// The video actions (ui/app/video_actions.h): opening, scrubbing, marking keyframes with undo,
// and tracking on a worker whose track becomes a keypoint clip (picked up in video_poll.cpp).
#include "ui/app/video_actions.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "core/common/errors.h"
#include "core/tracking/track_confidence.h"
#include "ui/app/actions.h"
#include "ui/app/undo.h"
#include "ui/app/video_poll.h"
#include "video/pose_model_files.h"
#include "video/track_files.h"

namespace ew::ui::actions {

namespace {

constexpr std::size_t kUndoDepth = 200;

VideoSession& session(AppState& s) {
  if (!s.video.session) throw std::invalid_argument("no video is open");
  return *s.video.session;
}

// Records the keyframes as they are before an edit.
void pushUndo(VideoSession& v) {
  v.undo.push_back({v.keyframes, nextEditSerial()});
  if (v.undo.size() > kUndoDepth) v.undo.erase(v.undo.begin());
  v.redo.clear();
}

// The first joint of the guided order from `step` on that the frame's keyframe lacks.
int nextUnmarked(const VideoSession& v, int step) {
  const Keyframe* k = v.keyframeAt(v.frame);
  const auto& order = markingOrder();
  for (int i = step; i < static_cast<int>(order.size()); ++i) {
    const int j = index(order[static_cast<std::size_t>(i)]);
    if (!k || !std::isfinite(k->jointsPx(2 * j))) return i;
  }
  return static_cast<int>(order.size());
}

// The keyframe on the frame shown, made when missing: from the track's confident joints
// there (a correction of a tracked frame), else empty.
Keyframe& keyframeHere(VideoSession& v) {
  for (auto& k : v.keyframes.keyframes)
    if (k.frame == v.frame) return k;
  Keyframe k;
  k.frame = v.frame;
  k.jointsPx =
      Eigen::RowVectorXd::Constant(2 * kJointCount, std::numeric_limits<double>::quiet_NaN());
  if (v.tracked && v.frame >= v.tracked->track.firstFrame && v.frame <= v.tracked->lastFrame()) {
    const int row = v.frame - v.tracked->track.firstFrame;
    for (int j = 0; j < kJointCount; ++j) {
      if (v.tracked->track.confidence(row, j) < KeypointOptions{}.minConfidence) continue;
      k.jointsPx.segment<2>(2 * j) = v.tracked->track.jointsPx.row(row).segment<2>(2 * j);
    }
  }
  auto& list = v.keyframes.keyframes;
  const auto at =
      std::find_if(list.begin(), list.end(), [&](const Keyframe& o) { return o.frame > k.frame; });
  return *list.insert(at, std::move(k));
}

// The keyframes edited: on a detected video, its track redone around them and fitted again
// (marks placed while guided marking runs wait for Done).
void keyframesEdited(AppState& s) {
  if (actions::correctsDetections(s) && !s.video.session->marking) actions::fitDetections(s);
}

}  // namespace

void openVideo(AppState& s, const std::filesystem::path& path) {
  std::shared_ptr<FrameCache> frames;
  try {
    frames = std::make_shared<FrameCache>(path);
  } catch (const std::exception& e) {
    throw std::invalid_argument(e.what());
  }
  closeVideo(s);
  if (s.clip.settings) closeClip(s);
  VideoSession v;
  v.path = path;
  v.frames = std::move(frames);
  v.keyframes.video = path.filename().string();
  s.video.session = std::move(v);
  s.doc.mode = Mode::Clip;
  s.view.playback.playing = false;
  const VideoInfo& i = s.video.session->frames->info();
  s.log.info("Opened the video " + path.string() + ": " + std::to_string(i.widthPx) + "×" +
             std::to_string(i.heightPx) + ", " + std::to_string(i.frameCount) + " frames at " +
             std::to_string(i.fps).substr(0, 5) + " fps");
}

void loadKeyframes(AppState& s, const std::filesystem::path& path) {
  VideoSession& v = session(s);
  Keyframes k;
  try {
    k = readKeyframes(path);
  } catch (const std::exception& e) {
    throw std::invalid_argument(e.what());
  }
  try {
    const VideoInfo& info = v.frames->info();
    checkKeyframesWithin(k, v.frameCount(), path.string());
    checkMarksWithin(k, info.widthPx, info.heightPx, path.string());
  } catch (const std::exception& e) {
    throw std::invalid_argument(e.what());
  }
  if (!k.video.empty() && k.video != v.path.filename().string())
    s.log.warning(path.string() + ": marked on " + k.video + ", read into " + v.path.filename().string() +
                  " (the same picture size; renamed?)");
  pushUndo(v);
  k.video = v.path.filename().string();
  v.keyframes = std::move(k);
  if (!v.keyframes.keyframes.empty()) v.frame = v.keyframes.keyframes.front().frame;
  s.log.info("Read " + std::to_string(v.keyframes.keyframes.size()) + " keyframes from " +
             path.string());
  keyframesEdited(s);
}

void saveKeyframes(AppState& s, const std::filesystem::path& path) {
  const VideoSession& v = session(s);
  if (v.keyframes.keyframes.empty()) throw std::invalid_argument("no joints are marked yet");
  try {
    writeKeyframes(path, v.keyframes);
  } catch (const std::exception& e) {
    throw std::invalid_argument(e.what());
  }
  s.log.info("Wrote the keyframes to " + path.string());
}

namespace {

std::filesystem::path keyframeFileIn(const std::filesystem::path& dir, const VideoSession& v) {
  return dir / (v.path.stem().string() + "_keyframes.json");
}

}  // namespace

void saveKeyframesInto(AppState& s, const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw std::invalid_argument(dir.string() + ": cannot create the folder: " + ec.message());
  saveKeyframes(s, keyframeFileIn(dir, session(s)));
}

void saveTrack(AppState& s, const std::filesystem::path& dir) {
  const VideoSession& v = session(s);
  if (!v.tracked) throw std::invalid_argument("no track yet: mark the joints, then Track");
  try {
    writeTrackFiles(dir, v.tracked->track);
    writeKeyframes(keyframeFileIn(dir, v), v.tracked->keyframes);
  } catch (const std::exception& e) {
    throw std::invalid_argument(e.what());
  }
  s.log.info("Wrote the track of frames " + std::to_string(v.tracked->track.firstFrame) + "-" +
             std::to_string(v.tracked->lastFrame()) + " to " + dir.string() +
             " (keypoints/ as OpenPose JSON, track_2d.csv, confidence.csv, " +
             keyframeFileIn(dir, v).filename().string() + ")");
}

int neighbouringKeyframe(const AppState& s, int delta) {
  if (!s.video.session || delta == 0) return -1;
  const int shown = shownVideoFrame(s);
  int best = -1;
  for (const Keyframe& k : s.video.session->keyframes.keyframes) {
    const bool way = delta > 0 ? k.frame > shown : k.frame < shown;
    const bool nearer = best < 0 || (delta > 0 ? k.frame < best : k.frame > best);
    if (way && nearer) best = k.frame;
  }
  return best;
}

namespace {

// The open video's keyframes as they are now (marked since the track was made, too).
std::vector<int> keyframeFrames(const VideoSession& v) {
  std::vector<int> frames;
  for (const Keyframe& k : v.keyframes.keyframes) frames.push_back(k.frame);
  return frames;
}

int firstOr(const std::vector<int>& frames) { return frames.empty() ? -1 : frames.front(); }

}  // namespace

int leastSureTrackedFrame(const AppState& s) {
  if (!s.video.session || !s.video.session->tracked) return -1;
  const TrackedVideo& t = *s.video.session->tracked;
  return firstOr(leastSureFrames(t.meanConfidence, t.track.firstFrame,
                                 keyframeFrames(*s.video.session), 1, 1));
}

int nextFrameToMark(const AppState& s) {
  if (!s.video.session || !s.video.session->tracked) return -1;
  const TrackedVideo& t = *s.video.session->tracked;
  return firstOr(framesToMarkNextAlong(t.cumulativeMotionPx, t.track.firstFrame,
                                       keyframeFrames(*s.video.session), 1));
}

std::filesystem::path defaultTrackFolder(const AppState& s) {
  return s.video.session ? std::filesystem::path(s.video.session->path.stem().string() + "_track")
                         : "track";
}

void setVideoZoom(AppState& s, double zoom, const Eigen::Vector2d& centrePx) {
  VideoSession& v = session(s);
  if (!std::isfinite(zoom) || !centrePx.allFinite())
    throw std::invalid_argument("video zoom: not a number");
  v.zoom = std::clamp(zoom, 1.0, kMaxVideoZoom);
  const VideoInfo& i = v.frames->info();
  v.zoomCentrePx = centrePx.cwiseMax(0.0).cwiseMin(Eigen::Vector2d(i.widthPx, i.heightPx));
}

void setVideoFrame(AppState& s, int frame) {
  VideoSession& v = session(s);
  v.frame = std::clamp(frame, 0, std::max(v.frameCount() - 1, 0));
  v.playedFrames = 0.0;
  if (v.marking) v.markStep = nextUnmarked(v, 0);
  v.followDetection = false;  // the user's frame, not the detection's
  // A tracked or detected clip shows this frame too, when it covers it.
  if (const auto fit = videoFitFrames(s); fit && v.frame >= fit->first && v.frame <= fit->second)
    setClipFrame(s, v.frame - fit->first + 1);
  s.view.playback.playing = false;
}

void startMarking(AppState& s) {
  VideoSession& v = session(s);
  setVideoFrame(s, shownVideoFrame(s));
  v.marking = true;
  v.markStep = nextUnmarked(v, 0);
}

void stopMarking(AppState& s) {
  session(s).marking = false;
  keyframesEdited(s);
}

void skipMarkedJoint(AppState& s) {
  VideoSession& v = session(s);
  if (!v.marking) throw std::invalid_argument("not marking joints");
  v.markStep = nextUnmarked(v, v.markStep + 1);
}

void markJoint(AppState& s, Joint joint, double xPx, double yPx, bool newEdit) {
  VideoSession& v = session(s);
  const VideoInfo& i = v.frames->info();
  if (!(std::isfinite(xPx) && std::isfinite(yPx) && xPx >= 0.0 && yPx >= 0.0 && xPx <= i.widthPx &&
        yPx <= i.heightPx))
    throw std::invalid_argument("a joint must lie in the picture (0-" + std::to_string(i.widthPx) +
                                ", 0-" + std::to_string(i.heightPx) + " px)");
  if (newEdit || v.undo.empty()) pushUndo(v);
  s.view.playback.playing = false;
  Keyframe& k = keyframeHere(v);
  k.jointsPx(2 * index(joint)) = xPx;
  k.jointsPx(2 * index(joint) + 1) = yPx;
  if (v.marking) v.markStep = nextUnmarked(v, 0);
}

bool letGoOfJoint(AppState& s) {
  VideoSession& v = session(s);
  if (v.marking) return false;
  if (correctsDetections(s)) {
    fitDetections(s);
    return true;
  }
  if (!v.tracked) return false;
  if (s.video.track.running()) {
    // The running track is of the keyframes before this edit: stopped, and started again.
    v.trackAgainWhenStopped = true;
    s.video.track.cancel();
    return false;
  }
  startTracking(s);
  return true;
}

void markFromKeypoints(AppState& s, const std::filesystem::path& keypoints) {
  VideoSession& v = session(s);
  Keyframes detected;
  try {
    KeypointOptions o;
    o.fps = v.fps();
    // The video's size: what a MediaPipe CSV's or YOLO labels' fractions are of.
    o.imageSize = KeypointImageSize{v.frames->info().widthPx, v.frames->info().heightPx};
    detected = keyframesFromTrack(readKeypointTrial(keypoints, o).jointsPx, {v.frame},
                                  keypoints.string());
    const VideoInfo& info = v.frames->info();
    checkMarksWithin(detected, info.widthPx, info.heightPx, keypoints.string());
  } catch (const std::exception& e) {
    throw std::invalid_argument(e.what());
  }
  pushUndo(v);
  s.view.playback.playing = false;
  keyframeHere(v).jointsPx = detected.keyframes.front().jointsPx;
  if (v.marking) v.markStep = nextUnmarked(v, 0);
  const auto found = detected.keyframes.front().jointsPx.array().isFinite().count() / 2;
  s.log.info("Marked frame " + std::to_string(v.frame) + " with " + std::to_string(found) +
             " joints from " + keypoints.string());
  keyframesEdited(s);
}

void removeKeyframe(AppState& s, int frame) {
  VideoSession& v = session(s);
  auto& list = v.keyframes.keyframes;
  const auto it =
      std::find_if(list.begin(), list.end(), [&](const Keyframe& k) { return k.frame == frame; });
  if (it == list.end())
    throw std::invalid_argument("frame " + std::to_string(frame) + " is no keyframe");
  pushUndo(v);
  v.keyframes.keyframes.erase(v.keyframes.keyframes.begin() + (it - list.begin()));
  if (v.marking) v.markStep = nextUnmarked(v, 0);
  keyframesEdited(s);
}

void undoKeyframes(AppState& s) {
  VideoSession& v = session(s);
  if (v.undo.empty()) throw std::invalid_argument("nothing to undo");
  v.redo.push_back({std::move(v.keyframes), v.undo.back().serial, latestEditSerial()});
  v.keyframes = std::move(v.undo.back().keyframes);
  v.undo.pop_back();
  if (v.marking) v.markStep = nextUnmarked(v, 0);
  keyframesEdited(s);
}

void redoKeyframes(AppState& s) {
  VideoSession& v = session(s);
  if (v.redo.empty()) throw std::invalid_argument("nothing to redo");
  v.undo.push_back({std::move(v.keyframes), v.redo.back().serial});
  v.keyframes = std::move(v.redo.back().keyframes);
  v.redo.pop_back();
  if (v.marking) v.markStep = nextUnmarked(v, 0);
  keyframesEdited(s);
}

void setTrackRange(AppState& s, int first, int last) {
  VideoSession& v = session(s);
  const int end = v.frameCount() - 1;
  if (last < 0) last = end;
  if (first < 0 || first > end || last < first || last > end)
    throw std::invalid_argument("the frames to track must lie in [0, " + std::to_string(end) +
                                "], first ≤ last");
  v.firstFrame = first;
  v.lastFrame = last;
}

void setTracker(AppState& s, TrackerKind tracker) { session(s).tracker = tracker; }

void setFlattenBackground(AppState& s, bool flatten) { session(s).flattenBackground = flatten; }

void setHoldTheTrunk(AppState& s, bool hold) { session(s).holdTheTrunk = hold; }

void setModelLoopRounds(AppState& s, int rounds) {
  if (rounds < 0 || rounds > 10) throw std::invalid_argument("the model loop runs 0-10 rounds");
  session(s).modelLoopRounds = rounds;
}

namespace {

// A track's progress as the frame it has reached in [first, last]; false once cancelled.
std::function<bool(double)> frameProgress(JobProgress& p, int first, int last) {
  return [&p, first, frames = last - first + 1](double done) {
    try {
      p.set(static_cast<int>(done * frames), frames, "frame " + std::to_string(first + static_cast<int>(done * frames)));
      return true;
    } catch (const JobCancelled&) {
      return false;
    }
  };
}

}  // namespace

void startTracking(AppState& s) {
  VideoSession& v = session(s);
  if (s.video.track.running()) throw std::invalid_argument("a track is running");
  if (s.video.detect.running())
    throw std::invalid_argument("a detection is running: wait for it, or cancel it");
  const int last = v.lastFrame < 0 ? v.frameCount() - 1 : v.lastFrame;
  const bool any = std::any_of(
      v.keyframes.keyframes.begin(), v.keyframes.keyframes.end(), [&](const Keyframe& k) {
        return k.frame >= v.firstFrame && k.frame <= last && k.jointsPx.array().isFinite().any();
      });
  if (!any)
    throw std::invalid_argument("no joints are marked on frames " + std::to_string(v.firstFrame) +
                                "-" + std::to_string(last) + ": mark them on one frame first");
  v.marking = false;
  v.trackError.clear();
  const TrackSettings settings = trackSettingsOf(v, last);
  // An edit between keyframes changes only the frames between its neighbours: those alone
  // are tracked again (a correction in a long clip takes seconds, not the whole clip's time).
  if (v.tracked)
    if (const auto around = localRetrackRange(*v.tracked, v.keyframes, settings)) {
      const std::string title = "Tracking " + v.path.filename().string() + " again, frames " +
                                std::to_string(around->first) + "-" + std::to_string(around->second);
      s.log.info(title + " (the rest of the track is unchanged)");
      s.video.track.start(title, [previous = v.tracked, keys = v.keyframes,
                                  around](JobProgress& p) {
        return std::make_shared<const TrackedVideo>(trackAgainBetween(
            *previous, keys, around->first, around->second, frameProgress(p, around->first, around->second)));
      });
      return;
    }
  const std::string title =
      "Tracking " + v.path.filename().string() + " (" + trackerName(v.tracker) + ")";
  s.log.info(title + ", frames " + std::to_string(v.firstFrame) + "-" + std::to_string(last));
  // The loop fits the model the clip is fitted with (the one walkers are inspected against).
  const auto model = v.modelLoopRounds > 0 && v.tracker == TrackerKind::OpticalFlow
                         ? modelForTracking(s)
                         : nullptr;
  const std::optional<VideoHorizon> horizon = v.horizon() ? std::optional(*v.horizon()) : std::nullopt;
  s.video.track.start(
      title, [path = v.path, keys = v.keyframes, settings, model, horizon](JobProgress& p) {
        return std::make_shared<const TrackedVideo>(trackVideo(
            path, keys, settings, model, frameProgress(p, settings.first, settings.last), horizon));
      });
}

void cancelTracking(AppState& s) { s.video.track.cancel(); }

void startDetection(AppState& s) {
  VideoSession& v = session(s);
  // A detection cancelled (its video closed) stops at its next frame: waited for.
  while (s.video.detect.running() && s.video.detect.cancelled() && !s.video.detect.poll())
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (s.video.detect.running()) throw std::invalid_argument("a detection is running");
  if (s.video.track.running())
    throw std::invalid_argument("a track is running: wait for it, or cancel it");
  if (!findPoseModels(s.video.detectorModel)) {
    v.detectError = missingPoseModelAdvice();
    throw std::invalid_argument(v.detectError);
  }
  v.detectError.clear();
  v.marking = false;
  v.detecting = std::make_shared<LiveDetections>();
  v.followDetection = true;
  s.view.playback.playing = false;
  const std::string title = "Detecting people in " + v.path.filename().string() + " (BlazePose " +
                            std::string(poseModelSizeName(s.video.detectorModel)) + ")";
  s.log.info(title);
  s.video.detect.start(title, [path = v.path, model = s.video.detectorModel,
                               live = v.detecting](JobProgress& p) {
    const auto progress = [&p](int done, int total) {
      try {
        p.set(done, total, "frame " + std::to_string(done) + " of " + std::to_string(total));
        return true;
      } catch (const JobCancelled&) {
        return false;
      }
    };
    return std::make_shared<const DetectedVideo>(detectVideo(path, model, live, progress));
  });
}

void cancelDetection(AppState& s) { s.video.detect.cancel(); }

void setDetectorModel(AppState& s, PoseModelSize model) { s.video.detectorModel = model; }

void setDetectWhenVideoOpens(AppState& s, bool detect) { s.video.detectWhenOpens = detect; }

void fitDetections(AppState& s) {
  VideoSession& v = session(s);
  if (!v.detected || v.detected->people == 0) throw std::invalid_argument("no people detected in this video yet");
  // Fitted as a clip, keeping the camera values the user held for this video.
  ClipSettings c = s.clip.settings && s.clip.settings->path == v.path ? *s.clip.settings : ClipSettings{};
  c.path = v.path;
  c.tracked.reset();
  c.detected = v.detected->frames;
  // The video's keyframes are the corrections; the same ones keep the fit (no refit).
  if (v.keyframes.keyframes.empty())
    c.corrections.reset();
  else if (!c.corrections || !sameKeyframes(*c.corrections, v.keyframes))
    c.corrections = std::make_shared<const Keyframes>(v.keyframes);
  c.video = keypointVideoOf(*v.detected);
  c.horizonRowPx = v.detected->horizon.rowPx();
  c.holdToHorizon = true;
  s.clip.settings = c;
  s.doc.mode = Mode::Clip;
  s.clip.fits.retry();
}

std::vector<KeypointDetection> detectionsOn(const AppState& s, int frame) {
  if (!s.video.session) return {};
  const VideoSession& v = *s.video.session;
  if (v.detecting) return v.detecting->at(frame);
  if (v.detected && frame >= 0 && frame < v.detected->frames->frameCount())
    return v.detected->frames->frames[static_cast<std::size_t>(frame)];
  return {};
}

void closeVideo(AppState& s) {
  if (!s.video.session) return;
  s.video.track.cancel();
  s.video.detect.cancel();
  if (s.clip.settings && (s.clip.settings->tracked || s.clip.settings->detected)) closeClip(s);
  s.video.session.reset();
}

bool showsTrackFit(const AppState& s) {
  return s.video.session && s.clip.fit() && s.video.session->tracked &&
         s.clip.fit()->settings.tracked &&
         s.clip.fit()->settings.tracked == s.video.session->tracked->trial;
}

bool showsDetectionFit(const AppState& s) {
  return s.video.session && s.clip.fit() && s.video.session->detected &&
         s.clip.fit()->settings.detected &&
         s.clip.fit()->settings.detected == s.video.session->detected->frames;
}

bool correctsDetections(const AppState& s) {
  return s.video.session && s.video.session->detected && s.video.session->detected->people > 0 &&
         !s.video.session->tracked;
}

bool showsVideoFit(const AppState& s) { return showsTrackFit(s) || showsDetectionFit(s); }

std::optional<std::pair<int, int>> videoFitFrames(const AppState& s) {
  if (showsTrackFit(s))
    return std::pair{s.video.session->tracked->track.firstFrame,
                     s.video.session->tracked->lastFrame()};
  // The detector's clip numbers its frames as the video does (keypointFramesOf).
  if (showsDetectionFit(s)) return std::pair{0, std::max(s.clip.fit()->rec.trial.frameCount - 1, 0)};
  return std::nullopt;
}

int shownVideoFrame(const AppState& s) {
  if (!s.video.session) return 0;
  const VideoSession& v = *s.video.session;
  if (!v.marking)
    if (const auto fit = videoFitFrames(s)) return fit->first + clipFrameAt(*s.clip.fit(), s.view.playback.cycles);
  return v.frame;
}

bool stepsVideoFrames(const AppState& s) {
  return s.doc.mode == Mode::Clip && s.video.session &&
         (s.video.session->marking || !showsVideoFit(s));
}

namespace {

bool stepsClipFrames(const AppState& s) {
  return s.doc.mode == Mode::Clip && s.clip.fit() && s.clip.fit()->rec.trial.frameCount > 0 &&
         s.clip.fit()->rec.fit.strideHz > 0.0;
}

}  // namespace

void stepFrame(AppState& s, int delta) {
  if (stepsVideoFrames(s)) {
    setVideoFrame(s, shownVideoFrame(s) + delta);
  } else if (stepsClipFrames(s)) {
    const int n = s.clip.fit()->rec.trial.frameCount;
    const int shown = clipFrameAt(*s.clip.fit(), s.view.playback.cycles);
    setClipFrame(s, ((shown + delta) % n + n) % n + 1);
  } else {
    s.view.playback.step(delta, playbackStrideHz(s));
  }
}

void advancePlayback(AppState& s, double seconds) {
  if (!stepsVideoFrames(s)) {
    s.view.playback.advance(seconds, playbackStrideHz(s));
    return;
  }
  VideoSession& v = *s.video.session;
  const auto& p = s.view.playback;
  // One video frame at most per drawn frame, and none while the last is still decoding:
  // every frame is seen (a slow machine plays slower, never skips).
  if (!p.playing || v.fps() <= 0.0 || v.frameCount() < 1 || v.shownIndex != v.frame) return;
  v.playedFrames += seconds * static_cast<double>(p.speed) * v.fps();
  const int whole = static_cast<int>(v.playedFrames);
  if (whole < 1) return;
  v.playedFrames -= whole;
  v.frame = (v.frame + 1) % v.frameCount();
  if (v.marking) v.markStep = nextUnmarked(v, 0);
}

double frameStepS(const AppState& s) {
  if (stepsVideoFrames(s) && s.video.session->fps() > 0.0) return 1.0 / s.video.session->fps();
  if (stepsClipFrames(s) && s.clip.fit()->rec.trial.rateHz > 0.0) return 1.0 / s.clip.fit()->rec.trial.rateHz;
  return 1.0 / 60.0;
}

}  // namespace ew::ui::actions
