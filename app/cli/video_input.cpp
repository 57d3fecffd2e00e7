#include "app/cli/video_input.h"

#include <algorithm>
#include <cctype>
#include <iomanip>
#include <iostream>

#include "core/common/errors.h"

#ifdef EW_HAVE_VIDEO
#include "video/detection_cache.h"
#endif

namespace ew::cli {

bool isVideoFile(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const char* known : {".mp4", ".mov", ".avi", ".mkv", ".webm", ".m4v", ".mpg", ".mpeg", ".wmv"})
    if (ext == known) return true;
  return false;
}

std::function<bool(int, int)> detectionProgressOnStderr() {
  return [lastTenth = -1](int done, int total) mutable {
    const int tenth = done * 10 / std::max(total, 1);
    if (tenth != lastTenth) std::cerr << "detecting: " << done << " of " << total << " frames\n";
    lastTenth = tenth;
    return true;
  };
}

#ifdef EW_HAVE_VIDEO

KeypointFrames detectKeypointFrames(const std::filesystem::path& video, const VideoDetectionSettings& settings,
                                    KeypointOptions& k) {
  PoseDetectionOptions o;
  o.model = parsePoseModelSize(settings.model);
  o.tiles = settings.tiles;
  if (!settings.quiet) o.progress = detectionProgressOnStderr();
  bool fromCache = false;
  const PoseDetectionRun run = detectPosesCached(video, o, fromCache, settings.useCache);
  if (!settings.quiet) {
    if (fromCache) {
      std::cerr << "detections of " << video.string() << " from the cache (" << detectionCacheFolder().string() << ")\n";
    } else {
      const double frames = static_cast<double>(run.poses.size());
      std::cerr << std::fixed << std::setprecision(1) << "detected " << run.people << " people in " << run.poses.size()
                << " frames (BlazePose " << poseModelSizeName(o.model) << ") in " << run.totalSeconds << " s, "
                << frames / std::max(run.totalSeconds, 1e-9) << " frames/s\n"
                << std::defaultfloat;
    }
  }
  k.video = KeypointVideo{video.string(), {run.video.widthPx, run.video.heightPx}, run.video.fps};
  return keypointFramesOf(run);
}

#else

KeypointFrames detectKeypointFrames(const std::filesystem::path& video, const VideoDetectionSettings&, KeypointOptions&) {
  throw Error(ErrorKind::Unsupported, video.string(), "",
              "this build has no video library (OpenCV was not found): detect the keypoints with another tool");
}

#endif

void sayKeypointWarnings(const std::string& input, const KeypointTrial& trial) {
  for (const auto& w : trial.warnings) std::cerr << "warning: " << input << ": " << w << "\n";
}

KeypointTrial keypointTrialOf(const std::filesystem::path& input, KeypointOptions k,
                              const VideoDetectionSettings& settings) {
  if (!isVideoFile(input)) return readKeypointTrial(input, k);
  KeypointFrames frames = detectKeypointFrames(input, settings, k);
  // The size and rate are the video's: said so (k.video) rather than "the file".
  frames.imageSize.reset();
  frames.rateHz.reset();
  return cleanKeypoints(frames, k);
}

}  // namespace ew::cli
