// The built-in pose detector's speed and memory (issue 52's goals on this 2-core machine:
// decode + detect + follow ≥ 20 frames/s at 1280×720 with the full model; a 10 s 1080p clip
// from file to 3D walker in ≤ 20 s; peak memory on a long clip bounded). Real footage from
// ../shared/data, re-encoded once per size as MJPG in a temporary folder:
// - the balancing trial's cam01 (one person, 100 frames) at 720×1280 (its portrait 1080×1920 halved
//   to 1280 px tall);
// - the walking video (two people on 122 of its 230 frames: the man on the box and the woman
//   who walks) at 1280×720;
// - the walking video at 1920×1080 made 10 s long (its 230 frames, then a cut to its first 70);
// - a 2-minute clip (the walking video's 230 frames over and over) at 640×360 for the memory.
// frames/s = items_per_second. Without the shared data or the models each benchmark says so.
#include <benchmark/benchmark.h>

#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "core/camera/clip_reconstruction.h"
#include "core/eigenwalker/default_model.h"
#include "core/keypoints/keypoint_trial.h"
#include "video/pose_detector.h"

namespace {

namespace fs = std::filesystem;

fs::path sharedData() { return fs::path(EW_SHARED_DATA_DIR); }

double peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// `source`'s frames `order` re-encoded at `size` (MJPG, 30 fps), once per process.
fs::path clipOf(const fs::path& source, cv::Size size, const std::vector<int>& order, const std::string& name) {
  static std::map<std::string, fs::path> made;
  if (auto it = made.find(name); it != made.end()) return it->second;
  cv::VideoCapture in(source.string());
  std::vector<cv::Mat> frames;
  for (cv::Mat f; in.read(f);) {
    cv::Mat resized;
    cv::resize(f, resized, size, 0, 0, cv::INTER_AREA);
    frames.push_back(resized);
  }
  const fs::path dir = fs::temp_directory_path() / ("ew_bench_detect_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / (name + ".avi");
  cv::VideoWriter out(file.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30.0, size);
  for (int i : order)
    if (i < static_cast<int>(frames.size())) out.write(frames[static_cast<std::size_t>(i)]);
  return made.emplace(name, file).first->second;
}

std::vector<int> firstFrames(int n) {
  std::vector<int> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = i;
  return v;
}

bool ready(benchmark::State& state) {
  if (!fs::exists(sharedData() / "video" / "sports2d-demo" / "demo.mp4")) {
    state.SkipWithError("../shared/data not found beside the checkout");
    return false;
  }
  if (!ew::findPoseModels()) {
    state.SkipWithError(ew::missingPoseModelAdvice().c_str());
    return false;
  }
  return true;
}

void report(benchmark::State& state, const ew::PoseDetectionRun& run) {
  const double frames = static_cast<double>(run.poses.size());
  state.counters["frames"] = frames;
  state.counters["people"] = run.people;
  state.counters["landmarks_ms_per_frame"] = 1000.0 * run.landmarkSeconds / frames;
  state.counters["person_detector_ms_per_frame"] = 1000.0 * run.personSeconds / frames;
  state.counters["decode_ms_per_frame"] = 1000.0 * run.decodeSeconds / frames;
}

// range(0): 0 the balancing trial's cam01 at 720×1280 (one person), 1 the walking video at
// 1280×720 (two people); range(1): the landmark model (0 lite, 1 full, 2 heavy).
void BM_DecodeDetectFollow(benchmark::State& state) {
  if (!ready(state)) return;
  const bool walking = state.range(0) == 1;
  const fs::path clip = walking ? clipOf(sharedData() / "video/sports2d-demo/demo.mp4", {1280, 720}, firstFrames(230), "demo_720p")
                                : clipOf(sharedData() / "pose2sim-balancing/videos/cam01.mp4", {720, 1280}, firstFrames(100), "cam01_720p");
  ew::PoseDetectionOptions o;
  o.model = static_cast<ew::PoseModelSize>(state.range(1));
  ew::PoseDetectionRun run;
  for (auto _ : state) run = ew::detectPoses(clip, o);
  state.SetLabel(std::string(walking ? "walking video 1280x720" : "cam01 720x1280") + ", " +
                 std::string(ew::poseModelSizeName(o.model)));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(run.poses.size()));
  report(state, run);
}
BENCHMARK(BM_DecodeDetectFollow)
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({0, 0})
    ->Args({0, 2})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// A 10 s 1080p clip from the file to the 3D walker: detection, the clip's cleaning, the
// eigenwalker through the unknown camera.
void BM_VideoToWalker1080p10s(benchmark::State& state) {
  if (!ready(state)) return;
  std::vector<int> order = firstFrames(230);
  for (int i = 0; i < 70; ++i) order.push_back(i);
  const fs::path clip = clipOf(sharedData() / "video/sports2d-demo/demo.mp4", {1920, 1080}, order, "demo_1080p_10s");
  double rms = 0.0, stature = 0.0;
  ew::PoseDetectionRun run;
  for (auto _ : state) {
    run = ew::detectPoses(clip);
    ew::KeypointOptions k;
    k.video = ew::KeypointVideo{clip.string(), {1920, 1080}, 30.0};
    const ew::ClipReconstruction c =
        ew::reconstructKeypointTrial(ew::defaultRealModel(), ew::cleanKeypoints(ew::keypointFramesOf(run), k), {});
    rms = c.fit.reprojectionRmsPx;
    stature = c.fit.statureMm / 1000.0;
  }
  report(state, run);
  state.counters["reprojection_rms_px"] = rms;
  state.counters["stature_m"] = stature;
}
BENCHMARK(BM_VideoToWalker1080p10s)->Iterations(1)->Unit(benchmark::kSecond);

// Memory on a long clip: 2 minutes (3600 frames) at 640×360. The detector holds one decoded
// frame and, per frame and person followed, 33 landmarks (a few hundred bytes): peak RSS grows
// by about that per frame, not with the picture.
void BM_DetectTwoMinutes(benchmark::State& state) {
  if (!ready(state)) return;
  std::vector<int> order;
  while (order.size() < 3600) for (int i = 0; i < 230 && order.size() < 3600; ++i) order.push_back(i);
  const fs::path clip = clipOf(sharedData() / "video/sports2d-demo/demo.mp4", {640, 360}, order, "demo_2min");
  const double before = peakRssMb();
  ew::PoseDetectionRun run;
  for (auto _ : state) run = ew::detectPoses(clip);
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(run.poses.size()));
  report(state, run);
  state.counters["peak_rss_MB"] = peakRssMb();
  state.counters["peak_rss_before_MB"] = before;
}
BENCHMARK(BM_DetectTwoMinutes)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace

BENCHMARK_MAIN();
