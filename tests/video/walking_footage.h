#pragma once
// Synthetic walking footage with known truth for the tracker tests: a synthetic walker (3 gait
// cycles at 30 fps, 4.4 m) filmed by a pinhole 6 m away (in view throughout, about 250 px
// tall), 30° off the side view, limbs painted with their own textures and colours
// (video/synthetic_footage.h). Written once per test program.

#include <Eigen/Core>
#include <filesystem>

#include "core/synth/population.h"
#include "tests/common/test_support.h"
#include "video/synthetic_footage.h"

namespace ew::test {

struct WalkingFootage {
  std::filesystem::path file;
  Eigen::MatrixXd truthPx;
  double strideHz = 0.0;
};

inline const WalkingFootage& walkingFootage() {
  static const WalkingFootage footage = [] {
    PopulationOptions o;
    o.count = 1;
    o.simulation.rateHz = 30.0;
    o.simulation.cycles = 3.0;
    const SynthWalker walker = generatePopulation(o).front();
    WalkingFootage out;
    out.file = makeTempDir("walking_footage") / "walker.avi";
    const auto& frames = walker.trial.positionsMm;
    out.truthPx = writeFootage(out.file, frames, cameraBeside(frames, 30.0, 6000.0), 30.0);
    out.strideHz = walker.attributes.at("cadence_spm") / 120.0;
    return out;
  }();
  return footage;
}

}  // namespace ew::test
