#include "core/mapping/joint_mapping.h"

#include <limits>

#include "core/common/errors.h"

namespace ew {

Eigen::Vector3d estimateHead(const Eigen::Vector3d& pelvis, const Eigen::Vector3d& sternum) {
  return sternum + kHeadFractionOfTrunk * (sternum - pelvis);
}

JointTrial jointTrialShell(const RawTrial& raw, std::string source, int frames) {
  JointTrial out;
  out.file = raw.file;
  out.format = raw.format;
  out.source = std::move(source);
  out.rateHz = raw.rateHz;
  out.units = raw.units;
  out.sourceLabels = raw.labels;
  out.positionsMm.setConstant(frames, kDims3, std::numeric_limits<double>::quiet_NaN());
  out.upAxis = raw.upAxis;
  out.events = raw.events;
  out.warnings = raw.warnings;
  return out;
}

JointTrial toJointTrial(const RawTrial& raw) {
  switch (raw.kind) {
    case PointKind::Markers: return mapMarkerSet(raw);
    case PointKind::SkeletonJoints: return mapSkeletonJoints(raw);
    case PointKind::CanonicalJoints: break;
  }
  JointTrial out = jointTrialShell(raw, "15-joint CSV", raw.frameCount());
  if (raw.pointCount() != kJointCount) {
    throw Error(ErrorKind::Malformed, raw.file, "", "expected 15 joints, found " +
                std::to_string(raw.pointCount()));
  }
  out.positionsMm = raw.positionsMm;
  return out;
}

}  // namespace ew
