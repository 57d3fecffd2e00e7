// The snippet engine (core/snippet; issue 15's goals on the 2-core CI machine): training
// the prior on the shared walkers (≤ 2 s), one 11-frame snippet MAP at a known view
// (≤ 2 ms) and with the view unknown, and a 10 s clip (300 frames at 30 Hz) at a known
// view (≤ 1 s). The clip is a held-out walker's trial (with its progression) repeated
// end to end until it lasts 10 s, seen at 30°.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>

#include "core/eigenwalker/projection.h"
#include "core/experiments/snippet_experiment.h"
#include "core/snippet/snippet_fit.h"
#include "core/snippet/snippet_sequence.h"

namespace {

std::filesystem::path dataDir() {
  if (const char* env = std::getenv("EIGENWALKER_DATA"); env && *env) return env;
  return EW_SHARED_DATA_DIR;
}

struct Fixture {
  ew::Dataset dataset;
  std::string heldOut;
  ew::PreparedSnippetPrior prior;
  Eigen::MatrixXd clip30;  // held-out trial at 30 Hz, T × 45
};

const Fixture* fixture() {
  static const Fixture* f = [] () -> const Fixture* {
    const auto manifest = dataDir() / "walkers.csv";
    if (!std::filesystem::exists(manifest)) return nullptr;
    auto* out = new Fixture;
    out->dataset = ew::loadDataset({manifest});
    out->heldOut = out->dataset.subjects().front();
    out->prior = ew::prepareSnippetPrior(
        ew::trainSnippetPrior(ew::snippetTrainingTrials(out->dataset, out->heldOut), {}));
    const auto& trial = out->dataset.trials.front().trial;
    out->clip30 = ew::resampleFrames(ew::framesWithProgression(trial), trial.joints.rateHz, 30.0);
    return out;
  }();
  return f;
}

void BM_TrainSnippetPrior(benchmark::State& state) {
  const Fixture* f = fixture();
  if (!f) { state.SkipWithError("../shared/data/walkers.csv not found"); return; }
  const auto trials = ew::snippetTrainingTrials(f->dataset, f->heldOut);
  for (auto _ : state) benchmark::DoNotOptimize(ew::trainSnippetPrior(trials, {}));
}
BENCHMARK(BM_TrainSnippetPrior)->Unit(benchmark::kMillisecond);

void snippetMap(benchmark::State& state, bool knownView) {
  const Fixture* f = fixture();
  if (!f) { state.SkipWithError("../shared/data/walkers.csv not found"); return; }
  const Eigen::MatrixXd y = ew::projectFramesToView(f->clip30.topRows(11), 30.0);
  ew::SnippetFitOptions o;
  o.scale = 1.0;
  if (knownView) o.alphaDeg = 30.0;
  for (auto _ : state) benchmark::DoNotOptimize(ew::fitSnippet(f->prior, y, o));
}
void BM_SnippetMapKnownView(benchmark::State& state) { snippetMap(state, true); }
void BM_SnippetMapUnknownView(benchmark::State& state) { snippetMap(state, false); }
BENCHMARK(BM_SnippetMapKnownView)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SnippetMapUnknownView)->Unit(benchmark::kMillisecond);

void BM_SnippetClip10sKnownView(benchmark::State& state) {
  const Fixture* f = fixture();
  if (!f) { state.SkipWithError("../shared/data/walkers.csv not found"); return; }
  // Repeat the trial (each copy moved on by the distance it covers) to 300 frames.
  const Eigen::Index n = f->clip30.rows();
  Eigen::MatrixXd frames(300, 45);
  for (Eigen::Index i = 0; i < 300; ++i) {
    frames.row(i) = f->clip30.row(i % n);
    const double ahead = static_cast<double>(i / n) * (f->clip30(n - 1, 7) - f->clip30(0, 7));
    for (int j = 0; j < 15; ++j) frames(i, 3 * j + 1) += ahead;
  }
  const Eigen::MatrixXd uv = ew::projectFramesToView(frames, 30.0);
  ew::SnippetSequenceOptions o;
  o.fit.alphaDeg = 30.0;
  o.fit.scale = 1.0;
  for (auto _ : state) benchmark::DoNotOptimize(ew::reconstructSnippetSequence(f->prior, uv, 30.0, o));
}
BENCHMARK(BM_SnippetClip10sKnownView)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
