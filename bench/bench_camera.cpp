// A 10 s clip (300 frames of OpenPose BODY_25 JSON, one file a frame) read, cleaned and
// reconstructed with everything unknown (issue 13's goal: ≤ 200 ms on the 2-core CI
// machine). The clip: the default model's mean walker crossing 6 m from a 1400 px camera
// 12° above, keypoints placed as a detector would (docs/CAMERA.md).
#include <benchmark/benchmark.h>

#include <filesystem>

#include "core/camera/camera_knowledge.h"
#include "core/camera/camera_reconstruction.h"
#include "core/eigenwalker/default_model.h"
#include "core/keypoints/image_gait.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/camera/filmed_walk.h"

namespace {

namespace fs = std::filesystem;

constexpr int kFrames = 300;

fs::path writeClip() {
  const fs::path dir = fs::temp_directory_path() / "eigenwalker_bench_camera";
  fs::remove_all(dir);
  ew::test::writeFilmedOpenPose(dir, ew::test::crossingPinhole(1400, kFrames / 30.0), kFrames, 30.0);
  return dir;
}

const fs::path& clip() {
  static const fs::path dir = writeClip();
  return dir;
}

ew::KeypointOptions options() {
  ew::KeypointOptions o;
  o.fps = 30.0;
  return o;
}

void BM_ReadAndCleanOpenPose300(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(ew::readKeypointTrial(clip(), options()));
}
BENCHMARK(BM_ReadAndCleanOpenPose300)->Unit(benchmark::kMillisecond);

void BM_UnknownCameraReconstruction300(benchmark::State& state) {
  const ew::KeypointTrial t = ew::readKeypointTrial(clip(), options());
  ew::CameraFitOptions o = ew::cameraFitOptions(ew::CameraKnowledge{});
  o.strideHzHint = ew::imageGaitCycles(t).strideHz;
  for (auto _ : state) benchmark::DoNotOptimize(ew::reconstructUnknownCamera(ew::defaultRealModel(), t.jointsPx, t.rateHz, o));
}
BENCHMARK(BM_UnknownCameraReconstruction300)->Unit(benchmark::kMillisecond);

// The whole user path: files to walker and camera.
void BM_OpenPoseClipToWalkerAndCamera300(benchmark::State& state) {
  for (auto _ : state) {
    const ew::KeypointTrial t = ew::readKeypointTrial(clip(), options());
    ew::CameraFitOptions o = ew::cameraFitOptions(ew::CameraKnowledge{});
    o.strideHzHint = ew::imageGaitCycles(t).strideHz;
    benchmark::DoNotOptimize(ew::reconstructUnknownCamera(ew::defaultRealModel(), t.jointsPx, t.rateHz, o));
  }
}
BENCHMARK(BM_OpenPoseClipToWalkerAndCamera300)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
