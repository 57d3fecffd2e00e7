#include "core/gait/prepare.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "core/common/errors.h"
#include "core/gait/canonical_frame.h"
#include "core/gait/gait_cycles.h"
#include "core/gait/gaps.h"
#include "core/gait/missing_joints.h"
#include "core/io/reader_limits.h"

namespace ew {
namespace {

// [SECTION] Preconditions and the complete run

void checkShape(const JointTrial& t) {
  if (t.positionsMm.cols() != kDims3) {
    throw Error(ErrorKind::BadArgument, t.file, "",
                "walking: expected 45 joint columns, got " + std::to_string(t.positionsMm.cols()));
  }
  if (!std::isfinite(t.rateHz) || t.rateHz < kMinFrameRateHz || t.rateHz > kMaxFrameRateHz) {
    std::ostringstream msg;
    msg << "walking: frame rate " << t.rateHz << " Hz is outside the plausible " << kMinFrameRateHz
        << "-" << kMaxFrameRateHz << " Hz";
    throwBadData(t.file, "", msg.str());
  }
  if (t.positionsMm.rows() < 2) {
    throwBadData(t.file, "",
                 "walking: " + std::to_string(t.positionsMm.rows()) +
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
  return "walking: " + (names.empty() ? std::string("no two consecutive frames have all 15 joints")
                                      : "missing in every frame: " + names);
}

void rejectGlitches(Eigen::MatrixXd& m, double rateHz, std::vector<std::string>& warnings) {
  const OutlierReport outliers = rejectOutlierSamples(m, outlierThresholdMm(rateHz));
  if (outliers.rejectedSamples == 0) return;
  warnings.push_back(std::to_string(outliers.rejectedSamples) +
                     " glitched sample(s) rejected as outliers (" + outliers.notes.front() +
                     (outliers.rejectedSamples > 1 ? ", …)" : ")"));
}

// [SECTION] Joints missing throughout

// Missing joints are not gaps: while the frame is made their columns hold stand-ins, so no
// frame counts as incomplete for their sake — a hip the knee of its side (the heading is
// the horizontal part of right − left), the pelvis the mid-hip (the progression and the
// steady window follow it), every other joint the pelvis (the up axis then points from the
// ankles to the pelvis). useWindow sets them back to NaN. missing_joints.h's minimum
// guarantees every stand-in has a measured source.
void standInForMissing(Eigen::MatrixXd& m, const JointMask& missing) {
  const auto isMissing = [&](Joint j) { return missing[static_cast<size_t>(index(j))]; };
  const auto copy = [&](Joint to, Joint from) {
    m.middleCols<3>(3 * index(to)) = m.middleCols<3>(3 * index(from));
  };
  if (isMissing(Joint::RHip)) copy(Joint::RHip, Joint::RKnee);
  if (isMissing(Joint::LHip)) copy(Joint::LHip, Joint::LKnee);
  if (isMissing(Joint::Pelvis)) {
    m.middleCols<3>(3 * index(Joint::Pelvis)) =
        0.5 * (m.middleCols<3>(3 * index(Joint::RHip)) + m.middleCols<3>(3 * index(Joint::LHip)));
  }
  for (int j = 0; j < kJointCount; ++j) {
    const auto joint = static_cast<Joint>(j);
    if (!isMissing(joint) || joint == Joint::Pelvis || joint == Joint::RHip || joint == Joint::LHip)
      continue;
    copy(joint, Joint::Pelvis);
  }
}

void blankMissing(Eigen::MatrixXd& m, const JointMask& missing) {
  for (int j = 0; j < kJointCount; ++j) {
    if (missing[static_cast<size_t>(j)])
      m.middleCols<3>(3 * j).setConstant(std::numeric_limits<double>::quiet_NaN());
  }
}

// [SECTION] The feet beside the joints

// The feet's points with their glitches and short gaps treated as the joints' are; what is
// left NaN stays NaN (the feet never decide which frames are usable).
Eigen::MatrixXd cleanedFeet(const JointTrial& t, int maxGap, const PrepareOptions& o) {
  Eigen::MatrixXd feet = t.feetMm;
  if (o.rejectOutliers) rejectOutlierSamples(feet, outlierThresholdMm(t.rateHz), kFootPointNames);
  bridgeShortGaps(feet, maxGap, kFootPointNames);
  return feet;
}

// The run's joints with the feet's rows [begin, begin + run rows) after them: the canonical
// frame moves both together (canonical_frame.h), splitFeet parts them again.
Eigen::MatrixXd withFeet(const Eigen::MatrixXd& run, const Eigen::MatrixXd& feet, int begin) {
  Eigen::MatrixXd both(run.rows(), kDims3 + kFootDims3);
  both << run, feet.middleRows(begin, run.rows());
  return both;
}

// The joints of a window; its feet go to `feet` (left empty when the window has none).
Eigen::MatrixXd splitFeet(Eigen::MatrixXd m, Eigen::MatrixXd& feet) {
  if (m.cols() == kDims3) return m;
  feet = m.rightCols(kFootDims3);
  return m.leftCols(kDims3);
}

// Gap-free rows [begin, end) with z up; with the feet after the joints when the trial has them.
Eigen::MatrixXd completeRunZUp(const JointTrial& t, const PrepareOptions& o, WalkingTrial& out) {
  Eigen::MatrixXd m = t.positionsMm;
  standInForMissing(m, out.joints.missing);
  if (o.rejectOutliers) rejectGlitches(m, t.rateHz, out.joints.warnings);
  const int maxGap = std::max(1, static_cast<int>(std::lround(o.maxGapS * t.rateHz)));
  GapReport gaps = bridgeShortGaps(m, maxGap);
  if (gaps.bridgedGaps > 0) {
    out.joints.warnings.push_back(std::to_string(gaps.bridgedGaps) +
                                  " short gap(s) interpolated (" + gaps.notes.front() +
                                  (gaps.bridgedGaps > 1 ? ", …)" : ")"));
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
  if (t.hasFeet()) run = withFeet(run, cleanedFeet(t, maxGap, o), begin);
  rotateFrames(run, rotationToZUp(up));
  return run;
}

std::vector<GaitEvent> shiftEvents(const std::vector<GaitEvent>& events, double offsetS) {
  std::vector<GaitEvent> shifted = events;
  for (auto& e : shifted) e.timeS -= offsetS;
  return shifted;
}

// [SECTION] Which frames to use

std::vector<StraightSegment> inTrialFrames(std::vector<StraightSegment> segments, int runBegin) {
  for (auto& s : segments) {
    s.begin += runBegin;
    s.end += runBegin;
    s.steadyBegin += runBegin;
    s.steadyEnd += runBegin;
  }
  return segments;
}

// A window of the complete run to try, with the warning that says why it was chosen.
struct Candidate {
  int begin = 0;
  int end = 0;
  int segment = -1;
  std::string note;
};

std::string framesText(int begin, int end) {
  return "frames " + std::to_string(begin) + "-" + std::to_string(end - 1);
}

std::string segmentsText(const std::vector<StraightSegment>& segments) {
  std::vector<std::string> parts;
  for (const auto& s : segments) parts.push_back(describeSegment(s));
  return listForMessage(parts, 4, "; ");
}

// The steady part of segment k, then the whole segment (its speed may vary, its heading not).
// Notes count frames in the loaded trial: the run starts at frame `runBegin`.
void addSegment(std::vector<Candidate>& out, const std::vector<StraightSegment>& segments, int k,
                int runFrames, int runBegin) {
  const StraightSegment& s = segments[static_cast<size_t>(k)];
  const bool several = segments.size() > 1;
  std::string steady;
  if (several) {
    steady = "walking in " + std::to_string(segments.size()) + " straight segments (" +
             segmentsText(inTrialFrames(segments, runBegin)) + "): using segment " +
             std::to_string(k + 1) + ", steady " +
             framesText(runBegin + s.steadyBegin, runBegin + s.steadyEnd);
  } else if (s.steadyBegin > 0 || s.steadyEnd < runFrames) {
    steady = "steady straight walking in " +
             framesText(runBegin + s.steadyBegin, runBegin + s.steadyEnd) +
             " (speed or heading off elsewhere)";
  }
  out.push_back({s.steadyBegin, s.steadyEnd, k, steady});
  if (s.begin != s.steadyBegin || s.end != s.steadyEnd) {
    out.push_back({s.begin, s.end, k,
                   "no steady part of straight segment " + std::to_string(k + 1) +
                       " holds a full gait cycle: using the whole segment, " +
                       framesText(runBegin + s.begin, runBegin + s.end)});
  }
}

// Frame ranges of the run to try, best first: the chosen segment's steady part, the whole
// segment, the other segments by length; the whole run only when the trial never turns.
std::vector<Candidate> candidateWindows(const SteadyWindow& w, int runFrames, int runBegin,
                                        const PrepareOptions& o, const std::string& file) {
  const Candidate wholeRun{0, runFrames, -1, ""};
  if (w.segments.empty()) return {wholeRun};
  std::vector<Candidate> out;
  const int count = static_cast<int>(w.segments.size());
  if (o.segment) {
    if (*o.segment < 0 || *o.segment >= count) {
      throw Error(ErrorKind::BadArgument, file, "",
                  "walking: segment " + std::to_string(*o.segment + 1) +
                      " does not exist (the trial has " + std::to_string(count) +
                      " straight segment(s): " + segmentsText(inTrialFrames(w.segments, runBegin)) +
                      ")");
    }
    addSegment(out, w.segments, *o.segment, runFrames, runBegin);
    return out;
  }
  std::vector<int> order;
  for (int k = 0; k < count; ++k) order.push_back(k);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return w.segments[static_cast<size_t>(a)].steadyFrames() >
           w.segments[static_cast<size_t>(b)].steadyFrames();
  });
  for (int k : order) addSegment(out, w.segments, k, runFrames, runBegin);
  if (count == 1 && (w.segments[0].begin > 0 || w.segments[0].end < runFrames)) {
    out.push_back({0, runFrames, -1,
                   "no steady straight-walking part of one full cycle: using the whole trial"});
  }
  return out;
}

// [SECTION] The canonical frame and the cycles of one window

// Canonical frame of a z-up window; returns the progression speed in m/s.
double toCanonical(Eigen::MatrixXd& m, double rateHz, std::vector<std::string>& warnings) {
  rotateFacingToY(m);
  const Eigen::Vector2d velocity = removeProgression(m, rateHz);
  placeOnFloor(m);
  const double speed = velocity.norm() / 1000.0;
  if (speed > 0.15 && velocity.y() < -0.5 * velocity.norm()) {
    warnings.push_back(
        "the walker progresses backwards relative to the direction the hips "
        "face: left/right labels may be swapped");
  }
  return speed;
}

// Fills `out` from frames [c.begin, c.end) of the run, or throws Error(BadData).
void useWindow(const Eigen::MatrixXd& run, int runBegin, const Candidate& c, const JointTrial& t,
               WalkingTrial& out) {
  if (c.end - c.begin < 2) {
    throwBadData(t.file, "",
                 "walking: " + framesText(runBegin + c.begin, runBegin + c.end) +
                     " is too short to hold a gait cycle");
  }
  Eigen::MatrixXd both = run.middleRows(c.begin, c.end - c.begin);
  std::vector<std::string> warnings;
  const double speed = toCanonical(both, t.rateHz, warnings);
  Eigen::MatrixXd feet;
  Eigen::MatrixXd m = splitFeet(std::move(both), feet);
  const double offsetS = (runBegin + c.begin) / t.rateHz;
  out.cycles = detectGaitCycles(m, t.rateHz, shiftEvents(t.events, offsetS), t.file);
  blankMissing(m, out.joints.missing);
  if (!c.note.empty()) warnings.push_back(c.note);
  out.windowBegin = runBegin + c.begin;
  out.windowEnd = runBegin + c.end;
  out.segment = c.segment;
  out.speedMps = speed;
  out.joints.positionsMm = std::move(m);
  out.joints.feetMm = std::move(feet);
  out.joints.upAxis = SignedAxis{2, 1};
  out.joints.events = shiftEvents(t.events, offsetS);
  out.joints.warnings.insert(out.joints.warnings.end(), warnings.begin(), warnings.end());
}

}  // namespace

WalkingTrial prepareWalkingTrial(const JointTrial& t, const PrepareOptions& o) {
  checkShape(t);
  WalkingTrial out;
  out.joints = t;
  out.joints.positionsMm.resize(0, kDims3);  // filled with the window; no second full copy
  out.joints.feetMm.resize(0, 0);
  out.loadedFrames = t.frameCount();
  out.joints.missing = missingJointsOf(t);
  if (anyJoint(out.joints.missing)) requireMinimumMeasured(out.joints.missing, t.file, "walking");
  const Eigen::MatrixXd run = completeRunZUp(t, o, out);
  const int runBegin = out.windowBegin;
  const int runFrames = static_cast<int>(run.rows());
  SteadyWindow window;
  if (o.cropToSteadyWindow) window = detectSteadyWindow(run.leftCols(kDims3), t.rateHz, o.window);
  out.segments = inTrialFrames(window.segments, runBegin);
  const auto candidates = candidateWindows(window, runFrames, runBegin, o, t.file);
  std::optional<Error> firstFailure, lastFailure;
  for (const Candidate& c : candidates) {
    try {
      useWindow(run, runBegin, c, t, out);
      return out;
    } catch (const Error& e) {
      if (!firstFailure) firstFailure = e;
      lastFailure = e;
    }
  }
  // One straight walk: the widest window tried says best why it is not usable.
  if (out.segments.size() < 2) throw *lastFailure;
  std::string why = firstFailure->problem();
  if (why.starts_with("not walking: ")) why.erase(0, std::string_view("not walking: ").size());
  throwBadData(t.file, "",
               "not walking: no straight segment holds a full gait cycle (" +
                   segmentsText(out.segments) + "): " + why);
}

}  // namespace ew
