// The embedded default: generating the synthetic population and building its eigenwalker
// model is what the viewer does on a fresh machine with no data. Budget: under 200 ms for
// the default (50 walkers × 4 cycles at 120 Hz) including the model.
#include <benchmark/benchmark.h>

#include "core/eigenwalker/walker_set.h"
#include "core/synth/population.h"

namespace {

// Kinematics only: 50 walkers, hip gain solved, sampled.
void BM_GeneratePopulation(benchmark::State& state) {
  for (auto _ : state) {
    auto walkers = ew::generatePopulation();
    benchmark::DoNotOptimize(walkers);
  }
}
BENCHMARK(BM_GeneratePopulation)->Unit(benchmark::kMillisecond);

// … plus prepareWalkingTrial for each (canonical frame, gait cycles).
void BM_SyntheticDataset(benchmark::State& state) {
  for (auto _ : state) {
    ew::Dataset d = ew::syntheticDataset();
    benchmark::DoNotOptimize(d);
  }
}
BENCHMARK(BM_SyntheticDataset)->Unit(benchmark::kMillisecond);

// The whole default: population, Fourier fits (makeWalkers) and the PCA model.
void BM_DefaultPopulationAndModel(benchmark::State& state) {
  int components = 0;
  for (auto _ : state) {
    const ew::EigenwalkerModel model = ew::buildModel(ew::makeWalkers(ew::syntheticDataset()));
    components = model.componentCount();
    benchmark::DoNotOptimize(model);
  }
  state.counters["components_95"] = components;
}
BENCHMARK(BM_DefaultPopulationAndModel)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
