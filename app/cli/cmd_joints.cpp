// `eigenwalker-cli joints FILE --out OUT.csv [--segment N] [--model MODEL]`: the normalised
// 15-joint trajectories. Joints the file does not measure (a lower-body marker set) are
// estimated from --model, else the default model of real walkers, and named in a comment.
#include <iostream>
#include <optional>
#include <sstream>

#include "app/cli/commands.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/joint_completion.h"
#include "core/eigenwalker/model_file.h"
#include "core/gait/dataset.h"
#include "core/io/joint_csv.h"
#include "core/io/trc_writer.h"

namespace ew::cli {
namespace {

struct JointsArgs {
  std::string file;
  std::string out;
  std::optional<double> rateHz;  // given: checked by the reader (checkedRateOverrideHz)
  std::string units;
  std::string mapping;  // joint mapping file (--mapping)
  int segment = 0;      // 1-based; 0: the longest steady one
  std::string model;    // completes missing joints; empty: the default model of real walkers
};

// Fills the joints the file lacks from the model; the comment line names them and the model.
WalkingTrial completeFromModel(const WalkingTrial& trial, const JointsArgs& args,
                               std::vector<std::string>& comments) {
  if (!anyJoint(trial.joints.missing)) return trial;
  const EigenwalkerModel model = args.model.empty() ? defaultRealModel() : loadModel(args.model);
  const std::string name = args.model.empty() ? defaultRealModelName() : args.model;
  CompletedTrial c = completeWalkingTrial(trial, model);
  std::ostringstream line;
  line << "model_estimated_joints=" << jointList(c.trial.modelEstimated)
       << " (not measured: estimated from the model " << name << ", sigma2 "
       << c.completion.sigma2Mm2 << " mm2)";
  comments.push_back(line.str());
  return std::move(c.trial);
}

int runJoints(const JointsArgs& args) {
  LoadOptions options;
  if (args.rateHz) options.rateHzOverride = *args.rateHz;
  if (!args.units.empty()) options.unitsOverride = args.units;
  if (!args.mapping.empty()) options.mappingFile = args.mapping;
  PrepareOptions prepare;
  if (args.segment != 0) prepare.segment = args.segment - 1;
  const WalkingTrial trial = loadWalkingTrial(args.file, options, prepare);
  std::vector<std::string> comments = {
      "eigenwalker 15-joint trajectories, mm, x right, y forward, z up (docs/METHOD.md §2)",
      "source=" + args.file + " (" + trial.joints.format + ", " + trial.joints.source + ")",
      "window_frames=" + std::to_string(trial.windowBegin) + "-" +
          std::to_string(trial.windowEnd - 1),
      "straight_segment=" + std::to_string(trial.segment + 1) + " of " +
          std::to_string(trial.segments.size()),
      "stride_hz=" + std::to_string(trial.cycles.strideHz) + " (" + trial.cycles.method + ")"};
  std::string estimated;
  for (int j = 0; j < kJointCount; ++j) {
    if (trial.joints.estimated[static_cast<size_t>(j)])
      estimated += std::string(estimated.empty() ? "" : ",") +
                   std::string(kJointNames[static_cast<size_t>(j)]);
  }
  if (!estimated.empty()) comments.push_back("estimated_joints=" + estimated);
  const WalkingTrial out = completeFromModel(trial, args, comments);
  for (const auto& w : out.joints.warnings)
    std::cerr << "warning: " << args.file << ": " << w << "\n";
  writeJointTrajectories(args.out, out.joints.positionsMm, out.joints.rateHz, comments, out.joints.feetMm,
                         out.joints.feetInSagittalPlanes);
  std::cerr << "wrote " << args.out << ": " << out.joints.frameCount() << " frames at "
            << out.joints.rateHz << " Hz\n";
  return 0;
}

}  // namespace

void addJointsCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<JointsArgs>();
  auto* cmd = app.add_subcommand("joints",
                                 "Write one trial's normalised 15-joint trajectories "
                                 "(steady window, canonical frame, mm) as CSV");
  cmd->add_option("file", args->file, "Motion-capture file (.c3d .bvh .amc .trc .csv .tsv)")->required();
  cmd->add_option("--out", args->out, "Output: the 15-joint CSV; a TRC (OpenSim's axes) when it ends in .trc; a C3D when it "
                  "ends in .c3d (the 15 joints and the gait events of their kinematics in the EVENT "
                  "group, docs/CLI.md); written atomically")->required();
  cmd->add_option("--rate", args->rateHz, "Frame rate in Hz, overriding the file's");
  cmd->add_option("--units", args->units, "Length unit overriding the file's: mm, cm, m, in, cmu");
  cmd->add_option("--mapping", args->mapping,
                  "Joint mapping file (JSON, docs/FORMATS.md): which markers make each joint, "
                  "for marker sets the program does not know");
  cmd->add_option("--segment", args->segment,
                  "Straight walking segment to use (1-based, as `info --json` lists them); "
                  "default: the one with the longest steady part");
  cmd->add_option("--model", args->model,
                  "Model (.ewm) that estimates the joints the file lacks (a lower-body marker "
                  "set); default: the model of real walkers shipped with the program")
      ->check(CLI::ExistingFile);
  cmd->callback([args, &exitCode] { exitCode = runJoints(*args); });
}

}  // namespace ew::cli
