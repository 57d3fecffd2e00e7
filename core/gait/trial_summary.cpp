#include "core/gait/trial_summary.h"

#include "core/common/errors.h"
#include "core/gait/missing_joints.h"
#include "core/gait/prepare.h"
#include "core/mapping/joint_mapping.h"

namespace ew {
namespace {

void fillFromRaw(const RawTrial& raw, TrialSummary& s) {
  s.format = raw.format;
  s.frames = raw.frameCount();
  s.rateHz = raw.rateHz;
  s.durationS = raw.rateHz > 0 ? raw.frameCount() / raw.rateHz : 0.0;
  s.units = raw.units;
  s.pointsFound = raw.pointCount();
  s.warnings = raw.warnings;
}

void fillModelEstimated(const JointMask& missing, TrialSummary& s) {
  s.modelEstimatedJoints.clear();
  for (int j = 0; j < kJointCount; ++j) {
    if (missing[static_cast<size_t>(j)])
      s.modelEstimatedJoints.emplace_back(kJointNames[static_cast<size_t>(j)]);
  }
}

void fillFromJoints(const JointTrial& joints, TrialSummary& s) {
  s.source = joints.source;
  for (int j = 0; j < kJointCount; ++j) {
    if (joints.estimated[static_cast<size_t>(j)])
      s.estimatedJoints.emplace_back(kJointNames[static_cast<size_t>(j)]);
  }
  fillModelEstimated(missingJointsOf(joints), s);
  s.warnings = joints.warnings;
}

void fillFromWalking(const WalkingTrial& w, TrialSummary& s) {
  s.windowFrames = w.joints.frameCount();
  s.cycles = w.cycles.cycleCount;
  s.strideHz = w.cycles.strideHz;
  s.cycleMethod = w.cycles.method;
  s.speedMps = w.speedMps;
  s.segments = w.segments;
  s.segment = w.segment;
  fillModelEstimated(w.joints.missing, s);
  s.warnings = w.joints.warnings;
}

}  // namespace

TrialSummary summarizeTrial(const std::filesystem::path& file, const LoadOptions& options) {
  TrialSummary s;
  s.file = file.string();
  s.errorStage = "read";
  try {
    JointTrial joints;
    {  // the raw points are freed before the walking stage copies the joints
      const RawTrial raw = readRawTrial(file, options);
      fillFromRaw(raw, s);
      s.errorStage = "joints";
      joints = mapRawTrial(raw, options);
    }
    fillFromJoints(joints, s);
    s.errorStage = "walking";
    fillFromWalking(prepareWalkingTrial(joints), s);
    s.errorStage.clear();
  } catch (const Error& e) {
    s.error = e.what();
  } catch (const std::exception& e) {
    s.error = std::string("internal error: ") + e.what();
  }
  return s;
}

}  // namespace ew
