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

TrackedVideo trackVideo(const std::filesystem::path& video, const Keyframes& keyframes, int first,
                        int last, TrackerKind tracker, bool flattenBackground, int modelLoopRounds,
                        std::shared_ptr<const EigenwalkerModel> model,
                        const std::function<bool(double)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  VideoSource source(video);
  TrackerOptions o;
  o.kind = tracker;
  o.firstFrame = first;
  o.lastFrame = last;
  o.flattenStaticBackground = flattenBackground;
  TrackedVideo t;
  t.video = video;
  t.keyframes = keyframes;
  t.tracker = tracker;
  t.flattenBackground = flattenBackground;
  t.modelLoopRounds = tracker == TrackerKind::OpticalFlow && model ? modelLoopRounds : 0;
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
