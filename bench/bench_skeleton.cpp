// The skeleton engine's speed (issue 16's goal: ≤ 50 µs a frame for the reconstruction with
// the sign search). A synthetic walker with rigid bones (2 cycles at 30 Hz) seen through a
// 1400 px pinhole camera at 35° azimuth, with 2 px of noise; also repeated to a 10 s clip,
// since the branch search runs over the whole clip. Time per frame = 1 / items_per_second.
#include <benchmark/benchmark.h>

#include <random>

#include "core/skeleton/skeleton_camera.h"
#include "core/skeleton/skeleton_solve.h"
#include "tests/skeleton/synthetic_camera.h"

namespace {

// The walk's pixels (T × 30), repeated `copies` times one after the other.
Eigen::MatrixXd noisyPixels(const ew::Camera& camera, int copies) {
  const ew::RigidWalk& w = ew::rigidWalk();
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0.0, 2.0);
  const Eigen::Index T = w.framesMm.rows();
  Eigen::MatrixXd px(T * copies, 2 * ew::kJointCount);
  for (Eigen::Index f = 0; f < px.rows(); ++f) {
    px.row(f) = ew::pixels(camera, ew::inCamera(camera, w.framesMm, f % T));
    for (Eigen::Index k = 0; k < px.cols(); ++k) px(f, k) += noise(rng);
  }
  return px;
}

ew::CalibratedCamera calibrated(const ew::Camera& c) {
  ew::CalibratedCamera k;
  k.name = "synthetic";
  k.fxPx = c.intrinsics.fxPx, k.fyPx = c.intrinsics.fyPx;
  k.cxPx = c.intrinsics.cxPx, k.cyPx = c.intrinsics.cyPx;
  k.widthPx = 1920, k.heightPx = 1080;
  return k;
}

// The sign search alone (rays and pelvis depths given): solveSkeletonSequence.
void BM_SkeletonBranchSearch(benchmark::State& state) {
  const ew::RigidWalk& w = ew::rigidWalk();
  const ew::Camera camera = ew::cameraAt(w.framesMm, 35.0);
  const Eigen::MatrixXd px = noisyPixels(camera, static_cast<int>(state.range(0)));
  std::vector<ew::JointRays> rays;
  for (Eigen::Index f = 0; f < px.rows(); ++f) rays.push_back(ew::pinholeRays(px.row(f), camera.intrinsics));
  const std::vector<double> depth = ew::rootDistancesFromBones(rays, w.bones, 7);
  std::vector<Eigen::Vector3d> roots;
  for (size_t f = 0; f < rays.size(); ++f) roots.push_back(depth[f] * rays[f].direction.col(ew::index(ew::Joint::Pelvis)));
  ew::SkeletonSolveOptions options;
  options.upMm = camera.worldToCamera * Eigen::Vector3d::UnitZ();
  for (auto _ : state) benchmark::DoNotOptimize(ew::solveSkeletonSequence(rays, roots, w.bones, 30.0, options));
  state.SetItemsProcessed(state.iterations() * px.rows());
}
BENCHMARK(BM_SkeletonBranchSearch)->Arg(1)->Arg(5)->Unit(benchmark::kMillisecond);

// The whole path from pixels: undistortion, rays, pelvis depth, sign search, world frame.
void BM_SkeletonThroughCamera(benchmark::State& state) {
  const ew::RigidWalk& w = ew::rigidWalk();
  const ew::Camera camera = ew::cameraAt(w.framesMm, 35.0);
  const Eigen::MatrixXd px = noisyPixels(camera, static_cast<int>(state.range(0)));
  const ew::CalibratedCamera k = calibrated(camera);
  for (auto _ : state) benchmark::DoNotOptimize(ew::reconstructThroughCamera(px, k, w.bones, 30.0, "bench"));
  state.SetItemsProcessed(state.iterations() * px.rows());
}
BENCHMARK(BM_SkeletonThroughCamera)->Arg(1)->Arg(5)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
