#pragma once
// What `eigenwalker-cli info` and the viewer's data table show for one file. Filled stage
// by stage (read, map to joints, prepare), so a file that fails late still shows what was
// read, and the failure names its stage.

#include <filesystem>
#include <string>
#include <vector>

#include "core/gait/steady_window.h"
#include "core/io/load_trial.h"

namespace ew {

struct TrialSummary {
  std::string file;
  std::string format;
  int frames = 0;              // frames in the file (after dropping a BVH T-pose frame)
  double rateHz = 0.0;
  double durationS = 0.0;
  std::string units;           // as stated in (or assumed for) the file
  int pointsFound = 0;         // markers or skeleton joints in the file
  std::string source;          // marker set / skeleton recognised
  std::vector<std::string> estimatedJoints;
  // Joints the file does not measure at all (JointTrial::missing): a model estimates them
  // (core/eigenwalker/joint_completion.h) when the trial is reconstructed or inspected.
  std::vector<std::string> modelEstimatedJoints;
  int windowFrames = 0;        // frames in the steady walking window
  double cycles = 0.0;
  double strideHz = 0.0;
  std::string cycleMethod;     // "file events" / "foot contacts"
  double speedMps = 0.0;
  std::vector<StraightSegment> segments;  // straight walking segments, frames of the file
  int segment = -1;                       // the one used (-1: the whole trial)
  std::vector<std::string> warnings;
  std::string error;           // empty when the file is usable as a walker
  std::string errorStage;      // "read", "joints" or "walking"

  bool ok() const { return error.empty(); }
};

TrialSummary summarizeTrial(const std::filesystem::path& file, const LoadOptions& options = {});

}  // namespace ew
