// Eigenwalker engine speed (METHOD §3–6) on synthetic walkers: R = 24, N = 22.
// Goals (docs/ENGINE.md): known-view LSQ/MAP ≤ 20 µs, unknown-view search ≤ 1 ms,
// model build ≤ 5 ms, Fourier fit of a 4-cycle 120 Hz trial ≤ 1 ms.
#include <benchmark/benchmark.h>

#include <numbers>

#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/projection.h"
#include "core/eigenwalker/reconstruction.h"
#include "core/eigenwalker/synthetic_walkers.h"

namespace {

constexpr int kWalkers = 24;
constexpr int kComponents = 22;

struct Fixture {
  Eigen::MatrixXd w = ew::syntheticWalkerSet(kWalkers + 1, 2024);
  std::vector<std::string> ids;
  Eigen::VectorXd omegas = Eigen::VectorXd::Constant(kWalkers, 6.5);
  ew::EigenwalkerModel model;
  ew::ModelGram gram;
  Eigen::VectorXd observed;  // the held-out 25th walker at 30°

  Fixture() {
    for (int i = 0; i < kWalkers; ++i) ids.push_back("S" + std::to_string(i));
    ew::ModelOptions options;
    options.components = kComponents;
    model = ew::buildModel(w.leftCols(kWalkers), ids, ids, omegas, options);
    gram = ew::precomputeModelGram(model);
    observed = ew::projectToView(w.col(kWalkers), 30.0);
  }
};

const Fixture& fixture() {
  static const Fixture f;
  return f;
}

void BM_FourierFit4Cycles120Hz(benchmark::State& state) {
  const double omega = 2.0 * std::numbers::pi * 1.0;
  const Eigen::MatrixXd frames = ew::synthesizeFrames(fixture().w.col(0), omega, 0.5,
                                                      ew::frameTimes(480, 120.0));
  ew::FourierFitOptions options;
  options.omegaHintRadS = omega * 1.02;
  for (auto _ : state) benchmark::DoNotOptimize(ew::fitFourier(frames, 120.0, options));
}
BENCHMARK(BM_FourierFit4Cycles120Hz)->Unit(benchmark::kMicrosecond);

void BM_ModelBuild(benchmark::State& state) {
  const auto& f = fixture();
  ew::ModelOptions options;
  options.components = kComponents;
  for (auto _ : state)
    benchmark::DoNotOptimize(ew::buildModel(f.w.leftCols(kWalkers), f.ids, f.ids, f.omegas, options));
}
BENCHMARK(BM_ModelBuild)->Unit(benchmark::kMicrosecond);

void BM_PrecomputeModelGram(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(ew::precomputeModelGram(fixture().model));
}
BENCHMARK(BM_PrecomputeModelGram)->Unit(benchmark::kMicrosecond);

void BM_KnownViewLsq(benchmark::State& state) {
  const auto& f = fixture();
  for (auto _ : state) benchmark::DoNotOptimize(ew::reconstructLsq(f.gram, f.observed, 30.0));
}
BENCHMARK(BM_KnownViewLsq)->Unit(benchmark::kMicrosecond);

void BM_KnownViewMap(benchmark::State& state) {
  const auto& f = fixture();
  for (auto _ : state) benchmark::DoNotOptimize(ew::reconstructMap(f.gram, f.observed, 30.0, 70.0));
}
BENCHMARK(BM_KnownViewMap)->Unit(benchmark::kMicrosecond);

void BM_UnknownViewLsq(benchmark::State& state) {
  const auto& f = fixture();
  for (auto _ : state) benchmark::DoNotOptimize(ew::searchViewAngle(f.gram, f.observed));
}
BENCHMARK(BM_UnknownViewLsq)->Unit(benchmark::kMicrosecond);

void BM_UnknownViewMap(benchmark::State& state) {
  const auto& f = fixture();
  const ew::EstimatorOptions map{ew::Estimator::Map, 70.0};
  for (auto _ : state) benchmark::DoNotOptimize(ew::searchViewAngle(f.gram, f.observed, map));
}
BENCHMARK(BM_UnknownViewMap)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
