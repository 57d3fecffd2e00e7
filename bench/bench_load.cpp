// Loading + normalising every trial of ../shared/data/walkers.csv: the time a user waits
// when opening the real data set. Reports MB/s over the files' bytes.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <iostream>

#include "core/gait/dataset.h"

namespace {

std::filesystem::path dataDir() {
  if (const char* env = std::getenv("EIGENWALKER_DATA"); env && *env) return env;
  return EW_SHARED_DATA_DIR;
}

void BM_LoadWalkersManifest(benchmark::State& state) {
  const auto manifest = dataDir() / "walkers.csv";
  if (!std::filesystem::exists(manifest)) {
    state.SkipWithError("../shared/data/walkers.csv not found");
    return;
  }
  std::vector<std::string> warnings;
  std::int64_t bytes = 0;
  for (const auto& f : ew::collectTrialFiles({manifest}, warnings)) {
    bytes += static_cast<std::int64_t>(std::filesystem::file_size(f.path));
  }
  size_t trials = 0;
  for (auto _ : state) {
    ew::Dataset d = ew::loadDataset({manifest});
    trials = d.trials.size();
    benchmark::DoNotOptimize(d);
  }
  state.SetBytesProcessed(state.iterations() * bytes);
  state.counters["trials"] = static_cast<double>(trials);
  state.counters["file_MB"] = static_cast<double>(bytes) / 1e6;
}
BENCHMARK(BM_LoadWalkersManifest)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace

BENCHMARK_MAIN();
