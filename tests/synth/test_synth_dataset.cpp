// The synthetic population as a Dataset: every trial passes prepareWalkingTrial with the
// stride frequency and speed it was generated with, and the engine builds a model from it.
#include <gtest/gtest.h>

#include <cmath>

#include "core/eigenwalker/walker_set.h"
#include "core/synth/population.h"

namespace ew {
namespace {

PopulationOptions options(int count) {
  PopulationOptions o;
  o.count = count;
  o.seed = 5;
  return o;
}

TEST(SynthDataset, EveryTrialPreparesWithItsOwnStrideFrequencyAndSpeed) {
  const auto walkers = generatePopulation(options(20));
  const Dataset d = datasetFromWalkers(walkers);
  ASSERT_EQ(d.trials.size(), walkers.size());
  EXPECT_EQ(d.subjects().size(), 20u);
  for (size_t i = 0; i < walkers.size(); ++i) {
    const DatasetTrial& t = d.trials[i];
    const auto& a = walkers[i].attributes;
    EXPECT_EQ(t.info.source, "synthetic");
    EXPECT_EQ(t.info.subject, walkers[i].id);
    EXPECT_EQ(t.info.attributes.at("height_m"), formatAttribute(a.at("height_m")));
    // Stride frequency found from the foot contacts, speed from the pelvis.
    EXPECT_NEAR(t.trial.cycles.strideHz, a.at("cadence_spm") / 120.0,
                0.03 * a.at("cadence_spm") / 120.0)
        << t.info.file << " (" << t.trial.cycles.method << ")";
    EXPECT_NEAR(t.trial.speedMps, a.at("speed_mps"), 0.05 * a.at("speed_mps")) << t.info.file;
    EXPECT_GE(t.trial.cycles.strideHz, 0.65);
    EXPECT_LE(t.trial.cycles.strideHz, 1.25);
    EXPECT_GE(t.trial.speedMps, 0.7);
    EXPECT_LE(t.trial.speedMps, 2.2);
    EXPECT_GE(t.trial.cycles.cycleCount, 3.5) << "the whole trial is steady walking";
  }
}

TEST(SynthDataset, TreadmillWalkersPrepareAsWalkingInPlace) {
  PopulationOptions o = options(4);
  o.simulation.treadmill = true;
  const Dataset d = syntheticDataset(o);
  for (const auto& t : d.trials) {
    EXPECT_LT(t.trial.speedMps, 0.15) << t.info.file;
    EXPECT_GT(t.trial.cycles.strideHz, 0.65) << t.info.file;
  }
}

TEST(SynthDataset, EngineBuildsAModelFromTheDefaultPopulation) {
  const Dataset d = syntheticDataset();  // the embedded default: 50 walkers, 4 cycles, 120 Hz
  std::vector<std::string> warnings;
  const std::vector<Walker> walkers = makeWalkers(d, &warnings);
  EXPECT_EQ(walkers.size(), 50u);
  for (const auto& w : warnings) ADD_FAILURE() << w;
  const EigenwalkerModel model = buildModel(walkers);
  EXPECT_EQ(model.walkerCount(), 50);
  // Many independent parameters, but a few dominate: a real gait space, neither a
  // rank-deficient toy nor white noise.
  EXPECT_GE(model.componentCount(), 5);
  EXPECT_LE(model.componentCount(), 35);
  EXPECT_GE(model.explainedVariance(), 0.95);
  for (const auto& w : walkers) {
    EXPECT_GT(w.fit.h1Share, 0.75) << w.id;
    EXPECT_GT(w.fit.h2Share, 0.02) << w.id;
    EXPECT_LT(w.fit.residualShare, 0.1) << w.id;
  }
}

}  // namespace
}  // namespace ew
