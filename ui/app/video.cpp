#include "ui/app/video.h"

#include <algorithm>
#include <cctype>
#include <chrono>

#include "core/tracking/track_confidence.h"

namespace ew::ui {

const std::vector<Joint>& markingOrder() {
  static const std::vector<Joint> order{
      Joint::Head,   Joint::Sternum,   Joint::Pelvis, Joint::RShoulder, Joint::RElbow,
      Joint::RWrist, Joint::LShoulder, Joint::LElbow, Joint::LWrist,    Joint::RHip,
      Joint::RKnee,  Joint::RAnkle,    Joint::LHip,   Joint::LKnee,     Joint::LAnkle};
  return order;
}

const Keyframe* VideoSession::keyframeAt(int f) const {
  for (const auto& k : keyframes.keyframes)
    if (k.frame == f) return &k;
  return nullptr;
}

const VideoHorizon* VideoSession::horizon() const {
  if (tracked) return &tracked->horizon;
  if (detected) return &detected->horizon;
  return nullptr;
}

TrackSettings trackSettingsOf(const VideoSession& v, int last) {
  return {v.firstFrame,        last,           v.tracker,
          v.flattenBackground, v.holdTheTrunk, v.modelLoopRounds};
}

namespace {

TrackerOptions trackerOptionsFor(const TrackSettings& settings) {
  TrackerOptions o;
  o.kind = settings.tracker;
  o.firstFrame = settings.first;
  o.lastFrame = settings.last;
  o.flattenStaticBackground = settings.flattenBackground;
  o.holdTheTrunk = settings.tracker == TrackerKind::OpticalFlow && settings.holdTheTrunk;
  return o;
}

// What the viewer reads off a track, made once when it is tracked: the fit's trial, each
// frame's mean confidence and how far the joints have moved by each frame.
void deriveFromTrack(TrackedVideo& t) {
  t.trial = std::make_shared<const KeypointTrial>(keypointTrialOf(t.track, t.video.string()));
  t.meanConfidence = t.track.confidence.rowwise().mean();
  t.cumulativeMotionPx = cumulativeMotionPx(t.track.jointsPx);
}

}  // namespace

TrackedVideo trackVideo(const std::filesystem::path& video, const Keyframes& keyframes,
                        const TrackSettings& settings,
                        std::shared_ptr<const EigenwalkerModel> model,
                        const std::function<bool(double)>& progress,
                        std::optional<VideoHorizon> horizon) {
  const auto start = std::chrono::steady_clock::now();
  VideoSource source(video);
  const bool flow = settings.tracker == TrackerKind::OpticalFlow;
  const TrackerOptions o = trackerOptionsFor(settings);
  TrackedVideo t;
  t.video = video;
  t.keyframes = keyframes;
  t.tracker = settings.tracker;
  t.flattenBackground = settings.flattenBackground;
  t.holdTheTrunk = o.holdTheTrunk;
  t.modelLoopRounds = flow && model ? settings.modelLoopRounds : 0;
  if (t.modelLoopRounds > 0) {
    ModelLoopResult looped =
        trackWithModel(source, keyframes, *model, o, ModelLoopOptions{t.modelLoopRounds}, progress);
    t.track = std::move(looped.track);
    t.loopRounds = std::move(looped.rounds);
    t.loopStopped = std::move(looped.stoppedBecause);
  } else {
    t.track = trackJoints(source, keyframes, o, progress);
  }
  deriveFromTrack(t);
  t.horizon = horizon ? std::move(*horizon) : readVideoHorizon(video);
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  t.ranFirst = t.track.firstFrame;
  t.ranLast = t.lastFrame();
  return t;
}

namespace {

bool sameMarks(const Keyframe& a, const Keyframe& b) {
  // A joint not marked (NaN) on both is unchanged: NaN == NaN is false.
  const auto same = a.jointsPx.array() == b.jointsPx.array() ||
                    (a.jointsPx.array().isNaN() && b.jointsPx.array().isNaN());
  return a.frame == b.frame && same.all();
}

// The frames whose keyframe was added, removed or moved a mark, in order: one walk down both
// lists (Keyframes keep increasing frame numbers), as the panel asks every drawn frame.
std::vector<int> editedFrames(const Keyframes& before, const Keyframes& after) {
  std::vector<int> edited;
  auto a = before.keyframes.begin(), b = after.keyframes.begin();
  while (a != before.keyframes.end() || b != after.keyframes.end()) {
    if (b == after.keyframes.end() || (a != before.keyframes.end() && a->frame < b->frame)) {
      edited.push_back((a++)->frame);
    } else if (a == before.keyframes.end() || b->frame < a->frame) {
      edited.push_back((b++)->frame);
    } else {
      if (!sameMarks(*a, *b)) edited.push_back(a->frame);
      ++a, ++b;
    }
  }
  return edited;
}

}  // namespace

bool sameKeyframes(const Keyframes& a, const Keyframes& b) { return editedFrames(a, b).empty(); }

std::optional<std::pair<int, int>> localRetrackRange(const TrackedVideo& previous,
                                                     const Keyframes& keyframes,
                                                     const TrackSettings& settings) {
  const bool sameSettings =
      settings.tracker == TrackerKind::OpticalFlow && previous.tracker == settings.tracker &&
      !settings.flattenBackground && !previous.flattenBackground && settings.modelLoopRounds == 0 &&
      previous.modelLoopRounds == 0 && previous.holdTheTrunk == settings.holdTheTrunk &&
      previous.track.firstFrame == settings.first && previous.lastFrame() == settings.last;
  if (!sameSettings) return std::nullopt;
  const std::vector<int> edited = editedFrames(previous.keyframes, keyframes);
  if (edited.empty() || edited.front() < settings.first || edited.back() > settings.last) return std::nullopt;
  const int height = std::max(previous.track.imageSize.height, 1);
  if (personHeightPx(previous.keyframes, height) != personHeightPx(keyframes, height)) return std::nullopt;
  int from = settings.first, to = settings.last;
  for (const Keyframe& key : keyframes.keyframes) {
    if (std::binary_search(edited.begin(), edited.end(), key.frame)) continue;
    if (key.frame < edited.front()) from = std::max(from, key.frame);
    if (key.frame > edited.back()) to = std::min(to, key.frame);
  }
  if (from > to) return std::nullopt;
  return std::pair{from, to};
}

TrackedVideo trackAgainBetween(const TrackedVideo& previous, const Keyframes& keyframes, int first,
                               int last, const std::function<bool(double)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  VideoSource source(previous.video);
  const TrackSettings settings{first, last, previous.tracker, previous.flattenBackground, previous.holdTheTrunk, 0};
  const JointTrack part = trackJoints(source, keyframes, trackerOptionsFor(settings), progress);
  TrackedVideo t = previous;
  t.keyframes = keyframes;
  const Eigen::Index row = first - previous.track.firstFrame, rows = last - first + 1;
  t.track.jointsPx.middleRows(row, rows) = part.jointsPx;
  t.track.confidence.middleRows(row, rows) = part.confidence;
  deriveFromTrack(t);
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  t.ranFirst = first;
  t.ranLast = last;
  return t;
}

bool isVideoFile(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* e : {".mp4", ".avi", ".mov", ".mkv", ".webm", ".m4v", ".mpg", ".mpeg"})
    if (ext == e) return true;
  return false;
}

}  // namespace ew::ui
