// Decoding and tracking speed (issue 14's goal: decode + track ≥ 30 frames/s at 1920×1080 and
// ≥ 60 frames/s at 1280×720 on this 2-core machine). Footage with known truth
// (video/synthetic_footage.h): a synthetic walker, 3 gait cycles at 30 fps, 6 m away, 30° off
// the side view, written once per size as MJPG; tracked from one keyframe on frame 0 (one
// forward pass), so frames/s = items_per_second. Decoding alone is measured beside it.
// Memory: a clip of about two minutes (100 gait cycles of a walker on a treadmill at 1280×720) tracked from a
// keyframe on its first frame (forward: a frame at a time) and on its last (backward: in
// pieces of the tracker's bounded frame buffer, 512 MB); the process's peak RSS is reported.
#include <benchmark/benchmark.h>

#include <sys/resource.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <tuple>

#include "core/synth/population.h"
#include "core/tracking/keyframes.h"
#include "core/tracking/track_confidence.h"
#include "video/joint_tracker.h"
#include "video/synthetic_footage.h"

namespace {

namespace fs = std::filesystem;

struct Footage {
  fs::path file;
  Eigen::MatrixXd truthPx;
};

// The footage at `height` px (16:9), written on first use: `cycles` gait cycles, on a
// treadmill when `inPlace`.
const Footage& footageOf(int height, double cycles = 3.0, bool inPlace = false) {
  static std::map<std::tuple<int, double, bool>, Footage> cache;
  const auto key = std::make_tuple(height, cycles, inPlace);
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  ew::PopulationOptions o;
  o.count = 1;
  o.simulation.rateHz = 30.0;
  o.simulation.cycles = cycles;
  o.simulation.treadmill = inPlace;
  const Eigen::MatrixXd frames = ew::generatePopulation(o).front().trial.positionsMm;
  ew::FootageCamera camera = ew::cameraBeside(frames, 30.0, 6000.0);
  camera.heightPx = height;
  camera.widthPx = height * 16 / 9;
  camera.focalPx = 1000.0 * height / 720.0;  // the same view at every size
  const fs::path dir = fs::temp_directory_path() / ("ew_bench_track_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  Footage f{dir / ("walk_" + std::to_string(height) + "_" + std::to_string(frames.rows()) + ".avi"), {}};
  f.truthPx = ew::writeFootage(f.file, frames, camera, 30.0);
  return cache.emplace(key, std::move(f)).first->second;
}

double peakRssMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // kB on Linux
}

void BM_Decode(benchmark::State& state) {
  const Footage& f = footageOf(static_cast<int>(state.range(0)));
  int frames = 0;
  for (auto _ : state) {
    ew::VideoSource video(f.file);
    frames = video.info().frameCount;
    for (int i = 0; i < frames; ++i) benchmark::DoNotOptimize(video.frame(i));
  }
  state.SetItemsProcessed(state.iterations() * frames);
}
BENCHMARK(BM_Decode)->Arg(720)->Arg(1080)->Unit(benchmark::kMillisecond);

void BM_DecodeAndTrack(benchmark::State& state) {
  const Footage& f = footageOf(static_cast<int>(state.range(0)));
  // range(1): 0 the flow tracker, 1 the appearance tracker, 2 the flow over a flattened
  // background (--flatten-background: the range decoded once more to find it).
  ew::TrackerOptions o;
  o.kind = state.range(1) == 1 ? ew::TrackerKind::Appearance : ew::TrackerKind::OpticalFlow;
  o.flattenStaticBackground = state.range(1) == 2;
  state.SetLabel(std::string(ew::trackerName(o.kind)) + (o.flattenStaticBackground ? ", flattened" : ""));
  const ew::Keyframes keys = ew::keyframesFromTrack(f.truthPx, {0}, f.file.string());
  for (auto _ : state) {
    ew::VideoSource video(f.file);
    benchmark::DoNotOptimize(ew::trackJoints(video, keys, o));
  }
  state.SetItemsProcessed(state.iterations() * f.truthPx.rows());
}
BENCHMARK(BM_DecodeAndTrack)
    ->Args({720, 0})
    ->Args({1080, 0})
    ->Args({720, 1})
    ->Args({1080, 1})
    ->Args({720, 2})
    ->Args({1080, 2})
    ->Unit(benchmark::kMillisecond);

// range(0): 0 keyframe on the first frame, 1 on the last.
void BM_TrackTwoMinutes(benchmark::State& state) {
  const Footage& f = footageOf(720, 100.0, true);  // about 110 s at a normal cadence (the generator's most)
  const int last = static_cast<int>(f.truthPx.rows()) - 1;
  const ew::Keyframes keys = ew::keyframesFromTrack(f.truthPx, {state.range(0) == 0 ? 0 : last}, f.file.string());
  for (auto _ : state) {
    ew::VideoSource video(f.file);
    benchmark::DoNotOptimize(ew::trackJoints(video, keys));
  }
  state.SetLabel(state.range(0) == 0 ? "forward" : "backward");
  state.SetItemsProcessed(state.iterations() * f.truthPx.rows());
  state.counters["frames"] = static_cast<double>(f.truthPx.rows());
  state.counters["peak_rss_MB"] = peakRssMb();
}
BENCHMARK(BM_TrackTwoMinutes)->Arg(0)->Arg(1)->Iterations(1)->Unit(benchmark::kSecond);

// The viewer's *Frame to mark next*, asked on every drawn frame: a 10-minute track at 30 fps
// (18 000 frames) with range(0) keyframes spread over it; the cumulative motion is made once,
// when the track is.
void BM_FrameToMarkNext(benchmark::State& state) {
  const Eigen::Index frames = 18000;
  Eigen::MatrixXd px(frames, ew::kDims2);
  for (Eigen::Index r = 0; r < frames; ++r)
    for (Eigen::Index j = 0; j < ew::kDims2; ++j)
      px(r, j) = 300.0 * std::sin(0.01 * static_cast<double>(r) * static_cast<double>(j % 7 + 1));
  const Eigen::VectorXd motion = ew::cumulativeMotionPx(px);
  std::vector<int> keyframes;
  for (int k = 0; k < state.range(0); ++k) keyframes.push_back(static_cast<int>(k * frames / state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(ew::framesToMarkNextAlong(motion, 0, keyframes, 1));
  state.counters["frames"] = static_cast<double>(frames);
}
BENCHMARK(BM_FrameToMarkNext)->Arg(1)->Arg(20)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
