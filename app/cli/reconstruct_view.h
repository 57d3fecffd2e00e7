#pragma once
// `reconstruct`'s orthographic view (the eigenwalker's and the snippet engine's input): a 2D
// CSV, or a 3D trial viewed at --project-angle whose frames are then the truth; and the
// eigenwalker model it is reconstructed with, its subject held out when the model holds it.
#include <Eigen/Core>
#include <optional>
#include <string>

#include "app/cli/reconstruct_args.h"
#include "core/eigenwalker/model.h"
#include "core/engines/engine.h"
#include "core/experiments/view_csv.h"
#include "core/gait/missing_joints.h"

namespace ew::cli {

// The model the user named, or the default one (--components: applyComponents, the viewer's N).
struct ChosenModel {
  EigenwalkerModel model;
  std::string name;          // the file, or defaultRealModelName()
  std::string sigma2Source;  // where its σ² optimum comes from (defaultSigma2Source)
};
ChosenModel chooseModel(const ReconstructArgs& a);
// --components N: the model's first N eigenwalkers (at most as many as it has).
void applyComponents(ChosenModel& c, const ReconstructArgs& a);

// The 2D input and, for a 3D file, the truth it came from.
struct Input {
  ViewSequence view;
  std::optional<double> omegaHintRadS;
  Eigen::MatrixXd frames3d;            // empty for a 2D file
  Eigen::MatrixXd frames3dOverground;  // frames3d with the trial's progression put back
  // Joints not measured in any frame (a lower-body marker set, a 2D column left empty):
  // dropped from the likelihood (their rows of Ê), estimated by the model, flagged.
  JointMask missing{};
};
Input readInput(const ReconstructArgs& a);

// The engines' view of the input: the walk in place at the input's frames, the joints it
// does not measure unseen, the known view angle (--angle) when given.
ViewInput viewInputOf(const Input& in, const ReconstructArgs& a);

// The model's name for the 3D input's subject when its walker is one of the model's (by its
// subject's name or its data; model_membership.h), else "" (and for a 2D input).
std::string inputSubjectInModel(const EigenwalkerModel& model, const Input& in, const ReconstructArgs& a);
// A 3D input whose walker is one of the model's: the model is rebuilt without that subject,
// as the viewer and the experiments reconstruct a walker (METHOD §4), its component count
// kept; the subject's model name, or "" when none (or --in-sample).
std::string holdOutTheInputsSubject(ChosenModel& chosen, const Input& in, const ReconstructArgs& a);

}  // namespace ew::cli
