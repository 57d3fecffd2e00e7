// `eigenwalker-cli angles FILE --out OUT.mot|OUT.csv`: the joint angles of any 3D trial
// (core/gait/joint_angles.h) over all its frames, in the file's own axes — walking or not,
// so a reconstruction's CSV, a balancing trial's TRC and a mocap walk alike.
#include <iostream>
#include <optional>
#include <limits>
#include <sstream>

#include "core/common/errors.h"

#include "app/cli/commands.h"
#include "core/gait/joint_angles.h"
#include "core/io/load_trial.h"

namespace ew::cli {
namespace {

struct AnglesArgs {
  std::string file, out, units, mapping;
  std::optional<double> rateHz;  // given: checked by the reader (checkedRateOverrideHz)
};

// The file's up axis where its format states one, else METHOD §2's rule: the signed axis
// nearest the body's mean head-above-ankles direction (a person balancing on one leg leans
// 18° off it in the Pose2Sim trial; motion capture's up is an axis).
Eigen::Vector3d upOf(const JointTrial& trial) {
  if (trial.upAxis) return Eigen::Vector3d::Unit(trial.upAxis->axis) * trial.upAxis->sign;
  return bodyUp(trial.positionsMm, 90.0);
}

int runAngles(const AnglesArgs& args) {
  LoadOptions options;
  if (args.rateHz) options.rateHzOverride = *args.rateHz;
  if (!args.units.empty()) options.unitsOverride = args.units;
  if (!args.mapping.empty()) options.mappingFile = args.mapping;
  const JointTrial trial = mapRawTrial(readRawTrial(args.file, options), options);
  const Eigen::Vector3d up = upOf(trial);
  if (!(up.norm() > 0.0))
    throw Error(ErrorKind::BadData, args.file, "", "no frame has the head and both ankles: the up direction is unknown");
  // The ankle and the foot progression where the trial has heel and toe points.
  JointAngles angles = trial.hasFeet() ? jointAnglesWithFeet(trial.positionsMm, trial.feetMm, up, args.file)
                                       : jointAngles(trial.positionsMm, up, args.file);
  // Feet lifted from one view lie in their ankles' sagittal planes: no foot progression.
  if (trial.feetInSagittalPlanes)
    for (std::size_t k = 0; k < angles.names.size(); ++k)
      if (angles.names[k].starts_with("foot_progression"))
        angles.degrees.col(static_cast<Eigen::Index>(k)).setConstant(std::numeric_limits<double>::quiet_NaN());
  std::vector<std::string> empty;
  for (Eigen::Index k = 0; k < angles.degrees.cols(); ++k)
    if (!angles.degrees.col(k).array().isFinite().any()) empty.push_back(angles.names[static_cast<size_t>(k)]);
  std::ostringstream upText;
  upText << up.transpose();
  writeJointAngles(args.out, angles, trial.rateHz,
                   {"source=" + args.file + " (" + trial.format + ")",
                    trial.hasFeet() ? "angles=degrees, joint angles of the 15-joint skeleton and the feet (eigenwalker core/gait/joint_angles.h)"
                                    : "angles=degrees, joint angles of the 15-joint skeleton (eigenwalker core/gait/joint_angles.h)",
                    "up=" + upText.str() + " (file axes)"});
  for (const auto& w : trial.warnings) std::cerr << "warning: " << args.file << ": " << w << "\n";
  if (!empty.empty()) {
    std::cerr << "no frame has the joints for:";
    for (const auto& n : empty) std::cerr << " " << n;
    std::cerr << " (written as nan)\n";
  }
  std::cerr << "wrote " << args.out << ": " << angles.degrees.rows() << " frames at " << trial.rateHz << " Hz, "
            << angles.degrees.cols() << " angles\n";
  return 0;
}

}  // namespace

void addAnglesCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<AnglesArgs>();
  auto* cmd = app.add_subcommand("angles",
                                 "Write a 3D trial's joint angles (hip, knee, shoulder, elbow, pelvis, trunk, neck; the "
                                 "ankle and the foot progression where it has heel and toe points; degrees) as CSV or "
                                 "OpenSim .mot, every frame, any motion");
  cmd->add_option("file", args->file, "3D trial (.c3d .bvh .amc .trc .csv .tsv, e.g. a reconstruction's CSV)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out, "Output .mot (OpenSim) or .csv (written atomically)")->required();
  cmd->add_option("--rate", args->rateHz, "Frame rate in Hz, overriding the file's");
  cmd->add_option("--units", args->units, "Length unit overriding the file's: mm, cm, m, in, cmu");
  cmd->add_option("--mapping", args->mapping, "Joint mapping file (JSON, docs/FORMATS.md) for a marker set the "
                                               "program does not know");
  cmd->callback([args, &exitCode] { exitCode = runAngles(*args); });
}

}  // namespace ew::cli
