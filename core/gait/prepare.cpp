#include "core/gait/prepare.h"

#include <cmath>
#include <sstream>

#include "core/common/errors.h"
#include "core/gait/canonical_frame.h"
#include "core/gait/gait_cycles.h"
#include "core/gait/gaps.h"

namespace ew {
namespace {

void checkShape(const JointTrial& t) {
  if (t.positionsMm.cols() != kDims3) {
    throw Error(ErrorKind::BadArgument, t.file, "", "expected 45 joint columns");
  }
  if (!(t.rateHz > 0) || !std::isfinite(t.rateHz)) throwBadData(t.file, "", "no valid frame rate");
  if (t.positionsMm.rows() < 2) {
    throwBadData(t.file, "", std::to_string(t.positionsMm.rows()) +
                                 " frame(s): a static trial, not walking");
  }
}

std::string missingJointsMessage(const Eigen::MatrixXd& m) {
  std::string names;
  for (int j = 0; j < kJointCount; ++j) {
    if (!m.middleCols<3>(3 * j).array().isFinite().rowwise().all().any()) {
      names += (names.empty() ? "" : ", ") + std::string(kJointNames[static_cast<size_t>(j)]);
    }
  }
  return names.empty() ? "no frame has all 15 joints" : "missing in every frame: " + names;
}

// Gap-free rows [begin, end) with z up.
Eigen::MatrixXd completeRunZUp(const JointTrial& t, const PrepareOptions& o, WalkingTrial& out) {
  Eigen::MatrixXd m = t.positionsMm;
  const int maxGap = std::max(1, static_cast<int>(std::lround(o.maxGapS * t.rateHz)));
  GapReport gaps = bridgeShortGaps(m, maxGap);
  if (gaps.bridgedGaps > 0) {
    out.joints.warnings.push_back(std::to_string(gaps.bridgedGaps) + " short gap(s) interpolated (" +
                                  gaps.notes.front() + (gaps.bridgedGaps > 1 ? ", …)" : ")"));
  }
  auto [begin, end] = longestRun(completeFrames(m));
  if (end - begin < 2) throwBadData(t.file, "", missingJointsMessage(m));
  if (end - begin < m.rows()) {
    out.joints.warnings.push_back("gaps longer than " + std::to_string(o.maxGapS) +
                                  " s: using frames " + std::to_string(begin) + "-" +
                                  std::to_string(end - 1) + " only");
  }
  out.windowBegin = begin;
  out.windowEnd = end;
  Eigen::MatrixXd run = m.middleRows(begin, end - begin);
  const SignedAxis up = t.upAxis.value_or(detectUpAxis(run));
  rotateFrames(run, rotationToZUp(up));
  return run;
}

std::vector<GaitEvent> shiftEvents(const std::vector<GaitEvent>& events, double offsetS) {
  std::vector<GaitEvent> shifted = events;
  for (auto& e : shifted) e.timeS -= offsetS;
  return shifted;
}

// Canonical frame of a z-up window; returns the progression speed in m/s.
double toCanonical(Eigen::MatrixXd& m, double rateHz, std::vector<std::string>& warnings) {
  rotateFacingToY(m);
  const Eigen::Vector2d velocity = removeProgression(m, rateHz);
  placeOnFloor(m);
  const double speed = velocity.norm() / 1000.0;
  if (speed > 0.15 && velocity.y() < -0.5 * velocity.norm()) {
    warnings.push_back("the walker progresses backwards relative to the direction the hips "
                       "face: left/right labels may be swapped");
  }
  return speed;
}

}  // namespace

WalkingTrial prepareWalkingTrial(const JointTrial& t, const PrepareOptions& o) {
  checkShape(t);
  WalkingTrial out;
  out.joints = t;
  out.loadedFrames = t.frameCount();
  Eigen::MatrixXd run = completeRunZUp(t, o, out);
  const int runBegin = out.windowBegin;
  SteadyWindow window{0, static_cast<int>(run.rows()), 0.0, false, ""};
  if (o.cropToSteadyWindow) window = detectSteadyWindow(run, t.rateHz, o.window);
  Eigen::MatrixXd m = run.middleRows(window.begin, window.end - window.begin);
  std::vector<std::string> warnings;
  double speed = toCanonical(m, t.rateHz, warnings);
  double offsetS = (runBegin + window.begin) / t.rateHz;
  try {
    out.cycles = detectGaitCycles(m, t.rateHz, shiftEvents(t.events, offsetS), t.file);
    if (!window.note.empty()) warnings.push_back(window.note);
  } catch (const Error&) {
    if (window.end - window.begin == run.rows()) throw;
    // The steady part is too short for a cycle: fall back to the whole complete run.
    window = SteadyWindow{0, static_cast<int>(run.rows()), 0.0, false, ""};
    m = run;
    warnings.clear();
    speed = toCanonical(m, t.rateHz, warnings);
    offsetS = runBegin / t.rateHz;
    out.cycles = detectGaitCycles(m, t.rateHz, shiftEvents(t.events, offsetS), t.file);
    warnings.push_back("no steady straight-walking part of one full cycle: using the whole trial");
  }
  out.windowBegin = runBegin + window.begin;
  out.windowEnd = runBegin + window.end;
  out.speedMps = speed;
  out.joints.positionsMm = std::move(m);
  out.joints.upAxis = SignedAxis{2, 1};
  out.joints.events = shiftEvents(t.events, offsetS);
  out.joints.warnings.insert(out.joints.warnings.end(), warnings.begin(), warnings.end());
  return out;
}

}  // namespace ew
