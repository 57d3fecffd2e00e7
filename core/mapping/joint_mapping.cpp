#include "core/mapping/joint_mapping.h"

#include <algorithm>
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

namespace {

// Our own C3D (core/io/c3d_writer.h) writes the feet's points after the 15 joints, by their
// names (kFootPointNames): they become JointTrial::feetMm; other points there are passed over.
void feetAfterTheJoints(const RawTrial& raw, JointTrial& out) {
  for (int k = kJointCount; k < raw.pointCount(); ++k) {
    const auto& label = raw.labels[static_cast<std::size_t>(k)];
    const auto name = std::find(kFootPointNames.begin(), kFootPointNames.end(), label);
    if (name == kFootPointNames.end()) continue;
    if (!out.hasFeet()) out.feetMm.setConstant(raw.frameCount(), kFootDims3, std::numeric_limits<double>::quiet_NaN());
    out.feetMm.middleCols(3 * (name - kFootPointNames.begin()), 3) = raw.positionsMm.middleCols(3 * k, 3);
    const auto kk = static_cast<std::size_t>(k);
    if (kk < raw.descriptions.size() && raw.descriptions[kk] == kSagittalFootDescription) out.feetInSagittalPlanes = true;
  }
}

}  // namespace

JointTrial toJointTrial(const RawTrial& raw) {
  switch (raw.kind) {
    case PointKind::Markers: return mapMarkerSet(raw);
    case PointKind::SkeletonJoints: return mapSkeletonJoints(raw);
    case PointKind::CanonicalJoints: break;
  }
  JointTrial out = jointTrialShell(raw, "15-joint CSV", raw.frameCount());
  if (raw.pointCount() < kJointCount || (raw.pointCount() > kJointCount && raw.format != "C3D")) {
    throw Error(ErrorKind::Malformed, raw.file, "", "expected 15 joints, found " +
                std::to_string(raw.pointCount()));
  }
  out.positionsMm = raw.positionsMm.leftCols(kDims3);
  feetAfterTheJoints(raw, out);
  return out;
}

}  // namespace ew
