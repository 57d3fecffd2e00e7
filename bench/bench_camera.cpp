// A 10 s clip (300 frames of OpenPose BODY_25 JSON, one file a frame) read, cleaned and
// reconstructed with everything unknown (issue 13's goal: ≤ 200 ms on the 2-core CI
// machine). The clip: the default model's mean walker crossing 6 m from a 1400 px camera
// 12° above, keypoints placed as a detector would (docs/CAMERA.md).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "core/camera/camera_reconstruction.h"
#include "core/camera/walk_camera.h"
#include "core/engine/default_model.h"
#include "core/engine/fourier.h"
#include "core/keypoints/image_gait.h"
#include "core/keypoints/keypoint_trial.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kFrames = 300;

fs::path writeClip() {
  ew::WalkCamera c;
  c.model = ew::CameraModel::Pinhole;
  c.alphaDeg = 40;
  c.elevationDeg = 12;
  c.focalPx = 1400;
  c.distanceMm = 6000;
  c.cxPx = 960;
  c.cyPx = 540;
  c.lookAtHeightMm = 900;
  c.speedMmS = 1300;
  c.startOffsetMm = -1300 * 5.0;
  const Eigen::VectorXd t = ew::frameTimes(kFrames, 30.0);
  const Eigen::MatrixXd px = ew::projectWalk(
      ew::synthesizeFrames(ew::defaultRealModel().mean, 2 * std::numbers::pi * 0.95, 0.2, t), t, c);
  const fs::path dir = fs::temp_directory_path() / "eigenwalker_bench_camera";
  fs::remove_all(dir);
  fs::create_directories(dir);
  using ew::Joint;
  for (int f = 0; f < kFrames; ++f) {
    const auto p = [&](Joint j, double du = 0, double dv = 0) {
      return std::pair{px(f, 2 * ew::index(j)) + du, px(f, 2 * ew::index(j) + 1) + dv};
    };
    const std::vector<std::pair<double, double>> points = {
        p(Joint::Head, 0, 8), p(Joint::Sternum), p(Joint::RShoulder), p(Joint::RElbow), p(Joint::RWrist),
        p(Joint::LShoulder), p(Joint::LElbow), p(Joint::LWrist), p(Joint::Pelvis), p(Joint::RHip),
        p(Joint::RKnee), p(Joint::RAnkle), p(Joint::LHip), p(Joint::LKnee), p(Joint::LAnkle),
        p(Joint::Head, -3, -4), p(Joint::Head, 3, -4), p(Joint::Head, -6, 0), p(Joint::Head, 6, 0),
        p(Joint::LAnkle, 5, 10), p(Joint::LAnkle, 7, 10), p(Joint::LAnkle, -3, 8), p(Joint::RAnkle, 5, 10),
        p(Joint::RAnkle, 7, 10), p(Joint::RAnkle, -3, 8)};
    json flat = json::array();
    for (const auto& [u, v] : points) flat.insert(flat.end(), {u, v, 0.9});
    char name[64];
    std::snprintf(name, sizeof name, "walk_%06d_keypoints.json", f);
    std::ofstream(dir / name) << json{{"people", {{{"pose_keypoints_2d", flat}}}}}.dump();
  }
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
  ew::CameraFitOptions o;
  o.strideHzHint = ew::imageGaitCycles(t).strideHz;
  for (auto _ : state) benchmark::DoNotOptimize(ew::reconstructUnknownCamera(ew::defaultRealModel(), t.jointsPx, t.rateHz, o));
}
BENCHMARK(BM_UnknownCameraReconstruction300)->Unit(benchmark::kMillisecond);

// The whole user path: files to walker and camera.
void BM_OpenPoseClipToWalkerAndCamera300(benchmark::State& state) {
  for (auto _ : state) {
    const ew::KeypointTrial t = ew::readKeypointTrial(clip(), options());
    ew::CameraFitOptions o;
    o.strideHzHint = ew::imageGaitCycles(t).strideHz;
    benchmark::DoNotOptimize(ew::reconstructUnknownCamera(ew::defaultRealModel(), t.jointsPx, t.rateHz, o));
  }
}
BENCHMARK(BM_OpenPoseClipToWalkerAndCamera300)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
