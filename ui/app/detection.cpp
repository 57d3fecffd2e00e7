#include "ui/app/detection.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <utility>

#include "ui/app/background_job.h"
#include "video/detection_cache.h"

namespace ew::ui {

void LiveDetections::add(int frame, std::vector<KeypointDetection> people) {
  if (frame < 0) return;
  std::lock_guard lock(mutex_);
  if (static_cast<std::size_t>(frame) >= frames_.size()) frames_.resize(static_cast<std::size_t>(frame) + 1);
  frames_[static_cast<std::size_t>(frame)] = std::move(people);
  latest_ = frame;
}

std::vector<KeypointDetection> LiveDetections::at(int frame) const {
  std::lock_guard lock(mutex_);
  if (frame < 0 || static_cast<std::size_t>(frame) >= frames_.size()) return {};
  return frames_[static_cast<std::size_t>(frame)];
}

int LiveDetections::latestFrame() const {
  std::lock_guard lock(mutex_);
  return latest_;
}

namespace {

KeypointDetection detectionOf(const FollowedPose& pose) {
  KeypointDetection d;
  d.trackId = pose.personId;
  d.points.resize(kBlazePoseLandmarks, 3);
  for (int i = 0; i < kBlazePoseLandmarks; ++i) {
    const Landmark& lm = pose.landmarks.points[static_cast<std::size_t>(i)];
    d.points.row(i) << lm.x, lm.y, lm.visibility;
  }
  return d;
}

}  // namespace

DetectedVideo detectVideo(const std::filesystem::path& video, PoseModelSize model,
                          const std::shared_ptr<LiveDetections>& live,
                          const std::function<bool(int done, int total)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  PoseDetectionOptions o;
  o.model = model;
  o.progress = progress;
  if (live)
    o.onFrame = [live](int frame, const std::vector<FollowedPose>& poses) {
      std::vector<KeypointDetection> people;
      people.reserve(poses.size());
      for (const FollowedPose& p : poses) people.push_back(detectionOf(p));
      live->add(frame, std::move(people));
    };
  DetectedVideo d;
  d.video = video;
  d.model = model;
  const PoseDetectionRun run = detectPosesCached(video, o, d.fromCache);
  if (run.cancelled) throw JobCancelled();
  d.frames = std::make_shared<const KeypointFrames>(keypointFramesOf(run));
  d.people = run.people;
  d.framesRead = static_cast<int>(run.poses.size());
  d.framesWithPeople = static_cast<int>(
      std::count_if(run.poses.begin(), run.poses.end(), [](const auto& poses) { return !poses.empty(); }));
  d.widthPx = run.video.widthPx;
  d.heightPx = run.video.heightPx;
  d.fps = run.video.fps;
  d.warnings = run.warnings;
  d.horizon = readVideoHorizon(video);
  d.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return d;
}

VideoHorizon readVideoHorizon(const std::filesystem::path& video) {
  VideoHorizon h;
  try {
    h.scene = sceneHorizonOf(video, kSceneHorizonFrames, h.whyNone);
  } catch (const std::exception& e) {
    h.whyNone = e.what();
  }
  return h;
}

KeypointVideo keypointVideoOf(const DetectedVideo& d) {
  return KeypointVideo{d.video.string(), {d.widthPx, d.heightPx}, d.fps};
}

std::string detectionSummary(const DetectedVideo& d) {
  char buf[200];
  std::snprintf(buf, sizeof buf, "BlazePose %s: %d %s on %d of %d frames, ",
                std::string(poseModelSizeName(d.model)).c_str(), d.people, d.people == 1 ? "person" : "people",
                d.framesWithPeople, d.framesRead);
  std::string text = buf;
  if (d.fromCache) return text + "from the cache";
  std::snprintf(buf, sizeof buf, "%.1f s (%.0f frames/s)", d.seconds, d.framesRead / std::max(d.seconds, 1e-9));
  return text + buf;
}

}  // namespace ew::ui
