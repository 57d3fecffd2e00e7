#include "core/skeleton/bone_choice.h"

#include "core/common/errors.h"
#include "core/gait/walking_trial.h"
#include "core/skeleton/bone_sources.h"

namespace ew {

namespace {

void require(bool given, const std::string& option, const std::string& why) {
  if (!given) throw Error(ErrorKind::BadArgument, option, "", why);
}

}  // namespace

BoneSource parseBoneSource(const std::string& name, const std::string& where) {
  if (name == "reference") return BoneSource::Reference;
  if (name == "table2") return BoneSource::Table2;
  if (name == "eigenwalker") return BoneSource::Eigenwalker;
  if (name == "frame") return BoneSource::Frame;
  throw Error(ErrorKind::BadArgument, where, "", "'" + name + "' is no bone source: reference, table2, eigenwalker or frame");
}

Joint jointNamed(const std::string& name, const std::string& where) {
  const auto j = jointFromName(name);
  if (!j) throw Error(ErrorKind::BadArgument, where, "", "'" + name + "' is no joint of docs/METHOD.md §1 (e.g. r_elbow)");
  return *j;
}

std::pair<int, double> referenceBoneOf(const std::string& text, const std::string& where) {
  const auto dash = text.find('-'), equals = text.find('=');
  if (dash == std::string::npos || equals == std::string::npos || equals < dash)
    throw Error(ErrorKind::BadArgument, where, "", "expects JOINT-JOINT=MM, e.g. r_elbow-r_wrist=260");
  const Joint a = jointNamed(text.substr(0, dash), where);
  const Joint b = jointNamed(text.substr(dash + 1, equals - dash - 1), where);
  const int bone = boneBetween(a, b);
  if (bone < 0) throw Error(ErrorKind::BadArgument, where, "", "no bone joins " + text.substr(0, equals));
  double mm = 0.0;
  try {
    mm = std::stod(text.substr(equals + 1));
  } catch (const std::exception&) {
    throw Error(ErrorKind::BadArgument, where, "", "the length after '=' is not a number of mm");
  }
  return {bone, mm};
}

Eigen::RowVectorXd keypointFrame(const KeypointTrial& k, int frame, const std::string& where) {
  if (frame < 0 || frame >= k.jointsPx.rows())
    throw Error(ErrorKind::BadArgument, where, "",
                "frame " + std::to_string(frame) + " is not among the input's 0-" + std::to_string(k.jointsPx.rows() - 1));
  return k.jointsPx.row(frame);
}

ChosenBones chooseBones(const BoneChoice& c, const KeypointTrial& keypoints, const JointTrial* reference,
                        const std::string& referenceName, const std::optional<BoneLengths>& eigenwalker) {
  const BoneChoice::Names& n = c.names;
  if (!c.source && !reference)
    throw Error(ErrorKind::BadArgument, n.source, "",
                "the skeleton engine needs the bone lengths: give " + n.reference +
                    " FILE (a 3D trial of the same person), or " + n.source + " table2|eigenwalker|frame");
  switch (c.source.value_or(BoneSource::Reference)) {
    case BoneSource::Reference:
      require(reference != nullptr, n.reference,
              n.source + " reference needs " + n.reference + " FILE, a 3D trial of the same person");
      return {boneLengthsFromFrames(reference->positionsMm, referenceName), "the reference " + referenceName};
    case BoneSource::Table2:
      require(c.statureMm.has_value(), n.stature,
              n.source + " table2 scales Zou et al.'s Table 2 to the walker's stature: give " + n.stature + " M");
      return {boneLengthsFromZouTable2(*c.statureMm, n.stature),
              "Zou et al.'s Table 2 at a stature of " + std::to_string(*c.statureMm / 1000.0) + " m"};
    case BoneSource::Eigenwalker: {
      require(eigenwalker.has_value(), n.source, "the eigenwalker's fit of the walker is needed");
      const BoneLengths b = c.statureMm ? scaledToStature(*eigenwalker, *c.statureMm, n.stature) : *eigenwalker;
      return {b, c.statureMm ? "the eigenwalker's fit, scaled to the stature" : "the eigenwalker's fit"};
    }
    case BoneSource::Frame: {
      require(c.frame.has_value() && !c.referenceBone.empty(), n.frame,
              n.source + " frame needs " + n.frame + " F (the body parallel to the image plane) and " +
                  n.referenceBone + " JOINT-JOINT=MM");
      const auto [bone, mm] = referenceBoneOf(c.referenceBone, n.referenceBone);
      return {boneLengthsFromReferenceFrame(keypointFrame(keypoints, *c.frame, n.frame), bone, mm, keypoints.file),
              "frame " + std::to_string(*c.frame) + " with " + c.referenceBone};
    }
  }
  throw Error(ErrorKind::BadArgument, n.source, "", "unknown bone source");
}

}  // namespace ew
