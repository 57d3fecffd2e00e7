#include "core/gait/missing_joints.h"

#include <initializer_list>

#include "core/common/errors.h"

namespace ew {

bool anyJoint(const JointMask& mask) { return jointCount(mask) > 0; }

int jointCount(const JointMask& mask) {
  int n = 0;
  for (bool b : mask) n += b ? 1 : 0;
  return n;
}

std::string jointList(const JointMask& mask) {
  std::string out;
  for (int j = 0; j < kJointCount; ++j) {
    if (!mask[static_cast<size_t>(j)]) continue;
    out += (out.empty() ? "" : ", ") + std::string(kJointNames[static_cast<size_t>(j)]);
  }
  return out;
}

JointMask jointsMissingThroughout(const Eigen::Ref<const Eigen::MatrixXd>& frames) {
  JointMask missing{};
  if (frames.cols() != kDims3 && frames.cols() != kDims2) return missing;
  const auto dims = static_cast<int>(frames.cols()) / kJointCount;
  for (int j = 0; j < kJointCount; ++j)
    missing[static_cast<size_t>(j)] = !frames.middleCols(dims * j, dims).array().isFinite().any();
  return missing;
}

JointMask missingJointsOf(const JointTrial& t) {
  JointMask missing = jointsMissingThroughout(t.positionsMm);
  for (size_t j = 0; j < missing.size(); ++j) missing[j] = missing[j] || t.missing[j];
  return missing;
}

namespace {

bool has(const JointMask& missing, Joint j) { return !missing[static_cast<size_t>(index(j))]; }

void markMissing(JointMask& out, const JointMask& missing, std::initializer_list<Joint> joints) {
  for (Joint j : joints) {
    if (!has(missing, j)) out[static_cast<size_t>(index(j))] = true;
  }
}

}  // namespace

JointMask lackingForMinimum(const JointMask& missing) {
  JointMask lacking{};
  markMissing(lacking, missing, {Joint::RAnkle, Joint::LAnkle});
  const bool hips = has(missing, Joint::RHip) && has(missing, Joint::LHip);
  const bool knees = has(missing, Joint::RKnee) && has(missing, Joint::LKnee);
  if (!hips && !knees)
    markMissing(lacking, missing, {Joint::RHip, Joint::LHip, Joint::RKnee, Joint::LKnee});
  if (!has(missing, Joint::Pelvis) && !hips)
    markMissing(lacking, missing, {Joint::Pelvis, Joint::RHip, Joint::LHip});
  return lacking;
}

void requireMinimumMeasured(const JointMask& missing, const std::string& file,
                            const std::string& stage) {
  const JointMask lacking = lackingForMinimum(missing);
  if (!anyJoint(lacking)) return;
  throwBadData(file, "",
               stage + ": too few joints measured to estimate the rest: " + jointList(lacking) +
                   " missing (needs both ankles, both hips or both knees, and the pelvis or "
                   "both hips; missing in every frame: " +
                   jointList(missing) + ")");
}

}  // namespace ew
