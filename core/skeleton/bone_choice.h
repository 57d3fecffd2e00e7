#pragma once
// The skeleton engine's bone-length policy: which of the sources of bone_sources.h a
// reconstruction takes, from what the user gave. Zou et al. (2009) measure their performer (a
// 3D reference of the same person); without one, the paper's Table 2 at a stated stature, one
// frame with the body parallel to the image and one bone of known length (§4.1), or — beyond
// the paper — the eigenwalker's fit of this walker, scaled to a stature when one is given. The
// CLI's `reconstruct --engine skeleton` and anything else that runs the engine through a camera
// choose here, so the rule and its messages live once.

#include <optional>
#include <string>
#include <utility>

#include "core/common/skeleton.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/skeleton/skeleton_tree.h"

namespace ew {

struct JointTrial;

enum class BoneSource { Reference, Table2, Eigenwalker, Frame };

// "reference", "table2", "eigenwalker", "frame"; Error(BadArgument) naming `where` otherwise.
BoneSource parseBoneSource(const std::string& name, const std::string& where);

struct BoneChoice {
  std::optional<BoneSource> source;  // unset: the reference's when there is one
  std::optional<double> statureMm;   // Table 2's stature; the eigenwalker's bones scaled to it
  std::optional<int> frame;          // Frame: a frame (0-based) with the body parallel to the image
  std::string referenceBone;         // Frame: the bone of known length, "a-b=MM" (r_elbow-r_wrist=260)
  // How the program names each given in errors (the CLI's options by default).
  struct Names {
    std::string source = "--bones", reference = "--reference", stature = "--stature", frame = "--bone-frame",
                referenceBone = "--reference-bone";
  } names;
};

struct ChosenBones {
  BoneLengths lengths;
  std::string source;  // said in reports: "the reference walk.trc", "Zou et al.'s Table 2 at …", …
};

// What the choice needs and is not given is an Error(BadArgument) naming the given: a reference
// (`reference`, named `referenceName`), a stature, a frame and a bone, the eigenwalker's bones
// (`eigenwalker`: the caller's fit of this walker). Throws what the sources throw.
ChosenBones chooseBones(const BoneChoice& choice, const KeypointTrial& keypoints, const JointTrial* reference,
                        const std::string& referenceName, const std::optional<BoneLengths>& eigenwalker);

// A joint of METHOD §1 by its name (r_elbow), Error(BadArgument) naming `where` otherwise.
Joint jointNamed(const std::string& name, const std::string& where);
// "a-b=MM": the bone between joints a and b and its length in mm; Error(BadArgument) naming
// `where` for text of another form, joints no bone joins or a length that is not a number.
std::pair<int, double> referenceBoneOf(const std::string& text, const std::string& where);
// The keypoints' frame `frame` (T × 30 row); Error(BadArgument) naming `where` when it is not
// among the trial's frames.
Eigen::RowVectorXd keypointFrame(const KeypointTrial& keypoints, int frame, const std::string& where);

}  // namespace ew
