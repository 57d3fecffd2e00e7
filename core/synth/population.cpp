#include "core/synth/population.h"

#include <cmath>
#include <cstdio>

#include "core/common/errors.h"
#include "core/gait/prepare.h"
#include "core/synth/random.h"

namespace ew {
namespace {

std::string walkerId(int i) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, "SYN%03d", i + 1);
  return buffer;
}

void checkOptions(const PopulationOptions& o) {
  auto bad = [](const std::string& what) { throw Error(ErrorKind::BadArgument, "", "", what); };
  if (o.count < 1) bad("population size must be at least 1, got " + std::to_string(o.count));
  if (o.trialsPerWalker < 1) bad("trials per walker must be at least 1");
  const double rate = o.simulation.rateHz, cycles = o.simulation.cycles;
  if (!(rate > 0.0 && rate <= 10000.0)) bad("frame rate must be in (0, 10000] Hz");
  if (!(cycles >= 1.0 && cycles <= 100.0)) bad("cycles must be in [1, 100]");
}

std::map<std::string, double> attributesOf(const SynthParams& p, const SynthTrajectories& t) {
  const AngleSummary angles = summarizeAngles(p);
  const BodyDimensions& b = p.body;
  const double strideM = t.strideLengthMm / 1000.0;
  return {
      {"height_m", b.heightMm / 1000.0},
      {"female", p.female ? 1.0 : 0.0},
      {"leg_length_m", (b.thighMm + b.shankMm + b.ankleHeightMm) / 1000.0},
      {"cadence_spm", 120.0 * t.strideHz},
      {"stride_length_m", strideM},
      {"speed_mps", strideM * t.strideHz},
      {"hip_rom_deg", angles.hipRomDeg},
      {"knee_flexion_deg", angles.kneePeakSwingDeg},
      {"knee_loading_deg", angles.kneeLoadingPeakDeg},
      {"arm_swing_deg", 2.0 * p.armSwingDeg},
      {"elbow_flexion_deg", p.elbowMeanDeg},
      {"pelvis_rotation_deg", 2.0 * p.pelvisRotationDeg},
      {"pelvis_obliquity_deg", 2.0 * p.pelvisObliquityDeg},
      {"lateral_sway_mm", 2.0 * p.lateralSwayMm},
      {"step_width_mm", p.stepWidthMm},
      {"trunk_lean_deg", p.trunkLeanDeg},
      {"asymmetry_arm", p.asymmetry.armSwingRatio - 1.0},
  };
}

}  // namespace

std::vector<std::string> synthAttributeNames() {
  return {"height_m",
          "female",
          "leg_length_m",
          "cadence_spm",
          "stride_length_m",
          "speed_mps",
          "hip_rom_deg",
          "knee_flexion_deg",
          "knee_loading_deg",
          "arm_swing_deg",
          "elbow_flexion_deg",
          "pelvis_rotation_deg",
          "pelvis_obliquity_deg",
          "lateral_sway_mm",
          "step_width_mm",
          "trunk_lean_deg",
          "asymmetry_arm"};
}

std::string formatAttribute(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", value);
  return buffer;
}

SynthWalker synthesizeWalker(const std::string& id, int trialIndex, SynthParams params,
                             const SimulationOptions& simulation, std::uint64_t trialSeed) {
  params.hipGain = solveHipGain(params);
  const SynthTrajectories t = simulateWalker(params, simulation, trialSeed);
  SynthWalker w;
  w.id = id;
  w.trialIndex = trialIndex;
  w.trialId = id + "_T" + std::to_string(trialIndex + 1);
  w.params = params;
  w.attributes = attributesOf(params, t);
  w.toesMm = t.toesMm;
  JointTrial& j = w.trial;
  j.file = w.trialId;
  j.format = "synthetic";
  j.source = "synthetic walker (core/synth, seeded)";
  j.rateHz = t.rateHz;
  j.units = "mm";
  j.sourceLabels.assign(kJointNames.begin(), kJointNames.end());
  j.positionsMm = t.jointsMm;
  j.upAxis = SignedAxis{2, 1};
  return w;
}

std::vector<SynthWalker> generatePopulation(const PopulationOptions& options) {
  checkOptions(options);
  std::vector<SynthWalker> walkers;
  walkers.reserve(static_cast<size_t>(options.count * options.trialsPerWalker));
  for (int i = 0; i < options.count; ++i) {
    // Walker i's stream: subject draw first, then one child stream per trial.
    const std::uint64_t walkerSeed = childSeed(options.seed, static_cast<std::uint64_t>(i));
    Rng subjectRng(walkerSeed);
    const SynthParams subject = drawSubjectParams(subjectRng);
    for (int r = 0; r < options.trialsPerWalker; ++r) {
      const std::uint64_t trialSeed = childSeed(walkerSeed, static_cast<std::uint64_t>(r));
      Rng trialRng(trialSeed);
      // The first trial is the subject's own parameters; later ones vary about them.
      const SynthParams params = r == 0 ? subject : jitterTrialParams(subject, trialRng);
      walkers.push_back(
          synthesizeWalker(walkerId(i), r, params, options.simulation, childSeed(trialSeed, 1)));
    }
  }
  return walkers;
}

Dataset datasetFromWalkers(const std::vector<SynthWalker>& walkers) {
  Dataset d;
  for (const SynthWalker& w : walkers) {
    DatasetTrial t;
    t.info.file = w.trialId;
    t.info.subject = w.id;
    t.info.source = kSynthSource;
    t.info.condition = kSynthCondition;
    for (const auto& [name, value] : w.attributes) t.info.attributes[name] = formatAttribute(value);
    t.trial = prepareWalkingTrial(w.trial);
    d.trials.push_back(std::move(t));
  }
  return d;
}

Dataset syntheticDataset(const PopulationOptions& options) {
  return datasetFromWalkers(generatePopulation(options));
}

}  // namespace ew
