#include "ui/app/video.h"

#include <algorithm>
#include <cctype>
#include <chrono>

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

TrackSettings trackSettingsOf(const VideoSession& v, int last) {
  return {v.firstFrame,        last,           v.tracker,
          v.flattenBackground, v.holdTheTrunk, v.modelLoopRounds};
}

TrackedVideo trackVideo(const std::filesystem::path& video, const Keyframes& keyframes,
                        const TrackSettings& settings,
                        std::shared_ptr<const EigenwalkerModel> model,
                        const std::function<bool(double)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  VideoSource source(video);
  const bool flow = settings.tracker == TrackerKind::OpticalFlow;
  TrackerOptions o;
  o.kind = settings.tracker;
  o.firstFrame = settings.first;
  o.lastFrame = settings.last;
  o.flattenStaticBackground = settings.flattenBackground;
  o.holdTheTrunk = flow && settings.holdTheTrunk;
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
  t.trial = std::make_shared<const KeypointTrial>(keypointTrialOf(t.track, video.string()));
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
