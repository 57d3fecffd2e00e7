#include "core/gait/gait_measures.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/common/statistics.h"
#include "core/gait/gait_cycles.h"
#include "core/gait/gait_events.h"

namespace ew {
namespace {

// A column of the frames at a time in seconds, linear between rows (clamped to the trial).
double sampleAt(const Eigen::Ref<const Eigen::MatrixXd>& m, int column, double timeS, double rateHz) {
  const double row = std::clamp(timeS * rateHz, 0.0, static_cast<double>(m.rows() - 1));
  const auto below = static_cast<Eigen::Index>(std::floor(row));
  const Eigen::Index above = std::min<Eigen::Index>(below + 1, m.rows() - 1);
  const double w = row - static_cast<double>(below);
  return (1.0 - w) * m(below, column) + w * m(above, column);
}

void checkInput(const Eigen::Ref<const Eigen::MatrixXd>& m, double rateHz, const std::string& name) {
  if (m.cols() != kDims3 || m.rows() < 3)
    throw Error(ErrorKind::BadArgument, name, "",
                "gait measures need at least 3 frames of 15 joints (got " + std::to_string(m.rows()) +
                    " × " + std::to_string(m.cols()) + ")");
  if (!(rateHz > 0) || !std::isfinite(rateHz))
    throw Error(ErrorKind::BadArgument, name, "", "gait measures need a positive frame rate");
  for (Joint j : {Joint::Pelvis, Joint::RAnkle, Joint::LAnkle}) {
    if (!m.middleCols(3 * index(j), 3).allFinite())
      throwBadData(name, "", "gait measures: the " + std::string(jointName(j)) +
                                 " is missing in some frames (fill the gaps first)");
  }
}

// The side's complete strides: consecutive strikes a plausible stride apart, with the first
// foot off between them.
std::vector<StrideRecord> stridesOf(const FootEvents& foot, Side side) {
  std::vector<StrideRecord> strides;
  for (size_t k = 0; k + 1 < foot.strikesS.size(); ++k) {
    const double a = foot.strikesS[k], b = foot.strikesS[k + 1];
    if (b - a < 1.0 / kMaxStrideHz || b - a > 1.0 / kMinStrideHz) continue;
    StrideRecord stride{side, a, b, NAN};
    const auto off = std::find_if(foot.offsS.begin(), foot.offsS.end(),
                                  [&](double t) { return t > a && t < b; });
    if (off != foot.offsS.end()) stride.offS = *off;
    strides.push_back(stride);
  }
  return strides;
}

double meanOf(const std::vector<double>& v) {
  if (v.empty()) return NAN;
  double sum = 0.0;
  for (double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

double stancePctOf(const std::vector<StrideRecord>& strides, Side side) {
  std::vector<double> pct;
  for (const auto& s : strides) {
    if (s.side == side && std::isfinite(s.offS))
      pct.push_back(100.0 * (s.offS - s.strikeS) / (s.nextStrikeS - s.strikeS));
  }
  return meanOf(pct);
}

// Foot flat, as a fraction of the stride after the strike: loading response is over by about
// 10 % and the heel rises at about 30 % (Perry & Burnfield, ch. 1). The ankle stands still on
// the floor then, so relative to the pelvis it slides back at the walking speed.
constexpr double kFlatBegin = 0.10, kFlatEnd = 0.30;

// The rows of a foot-flat window, [first, last]; empty (first > last) when it leaves the trial.
std::pair<Eigen::Index, Eigen::Index> flatRows(double strikeS, double strideS, double rateHz, Eigen::Index rows) {
  const auto first = static_cast<Eigen::Index>(std::ceil((strikeS + kFlatBegin * strideS) * rateHz));
  const auto last = static_cast<Eigen::Index>(std::floor((strikeS + kFlatEnd * strideS) * rateHz));
  if (first < 0 || last >= rows || last - first < 2) return {1, 0};
  return {first, last};
}

// Least-squares slope (per second) of a column over rows [first, last].
double slopePerS(const Eigen::Ref<const Eigen::MatrixXd>& m, int column, Eigen::Index first, Eigen::Index last,
                 double rateHz) {
  const Eigen::Index n = last - first + 1;
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(n, 0.0, static_cast<double>(n - 1) / rateHz);
  const Eigen::VectorXd y = m.col(column).segment(first, n);
  const double tMean = t.mean();
  return ((t.array() - tMean) * (y.array() - y.mean())).sum() / (t.array() - tMean).square().sum();
}

// How fast the stance feet slide relative to the walker's frame (mm/s, x and y): a flat foot
// stands still on the floor, so this is minus the walker's progression. The median over
// foot-flat windows of the ankle's slope; NaN when no window is inside the trial.
Eigen::Vector2d stanceFootSlide(const Eigen::Ref<const Eigen::MatrixXd>& m, double rateHz,
                                const GaitEventSet& events, double strideS) {
  std::vector<double> sx, sy;
  for (Side side : {Side::Right, Side::Left}) {
    const int x = 3 * index(ankleOf(side));
    for (double strike : events.of(side).strikesS) {
      const auto [first, last] = flatRows(strike, strideS, rateHz, m.rows());
      if (first > last) continue;
      sx.push_back(slopePerS(m, x, first, last, rateHz));
      sy.push_back(slopePerS(m, x + 1, first, last, rateHz));
    }
  }
  return sx.empty() ? Eigen::Vector2d(NAN, NAN) : Eigen::Vector2d(median(sx), median(sy));
}

// The pelvis's mean horizontal velocity over the whole clip (mm/s, x and y): the least-squares
// line through its track.
Eigen::Vector2d pelvisTrend(const Eigen::Ref<const Eigen::MatrixXd>& m, double rateHz) {
  const int x = 3 * index(Joint::Pelvis);
  return {slopePerS(m, x, 0, m.rows() - 1, rateHz), slopePerS(m, x + 1, 0, m.rows() - 1, rateHz)};
}

// Where a foot stood in one stance: its ankle's mean position over foot flat, forward in the
// ground frame (the frame's y plus the walker's progression since row 0), mm.
struct Footprint {
  Side side;
  double strikeS, forwardMm, lateralMm;
};

// slide: the stance feet's slide (stanceFootSlide), taken out so footprints are on the floor.
std::vector<Footprint> footprints(const Eigen::Ref<const Eigen::MatrixXd>& m, double rateHz,
                                  const GaitEventSet& events, double strideS, const Eigen::Vector2d& slide) {
  std::vector<Footprint> prints;
  for (Side side : {Side::Right, Side::Left}) {
    const int x = 3 * index(ankleOf(side));
    for (double strike : events.of(side).strikesS) {
      const auto [first, last] = flatRows(strike, strideS, rateHz, m.rows());
      if (first > last) continue;
      double forward = 0.0, lateral = 0.0;
      for (Eigen::Index r = first; r <= last; ++r) {
        const double t = static_cast<double>(r) / rateHz;
        forward += m(r, x + 1) - slide.y() * t;
        lateral += m(r, x) - slide.x() * t;
      }
      const auto n = static_cast<double>(last - first + 1);
      prints.push_back({side, strike, forward / n, lateral / n});
    }
  }
  std::sort(prints.begin(), prints.end(), [](const Footprint& a, const Footprint& b) { return a.strikeS < b.strikeS; });
  return prints;
}

void fillSteps(GaitMeasures& g, const Eigen::Ref<const Eigen::MatrixXd>& m, double rateHz,
               const Eigen::Vector2d& slide) {
  const auto prints = footprints(m, rateHz, g.events, g.strideTimeS, slide);
  std::vector<double> right, left, widths;
  for (size_t k = 1; k < prints.size(); ++k) {
    const Footprint &a = prints[k - 1], &b = prints[k];
    // A step: the other foot's stance just before, at most a stride earlier.
    if (a.side == b.side || b.strikeS - a.strikeS > 0.75 * g.strideTimeS) continue;
    (b.side == Side::Right ? right : left).push_back(b.forwardMm - a.forwardMm);
    widths.push_back(std::abs(b.lateralMm - a.lateralMm));
  }
  g.stepLengthRightM = meanOf(right) / 1000.0;
  g.stepLengthLeftM = meanOf(left) / 1000.0;
  g.stepWidthM = meanOf(widths) / 1000.0;
  if (std::isfinite(g.stepLengthRightM) && std::isfinite(g.stepLengthLeftM)) {
    g.strideLengthM = g.stepLengthRightM + g.stepLengthLeftM;
  } else if (std::isfinite(g.stepLengthRightM) || std::isfinite(g.stepLengthLeftM)) {
    g.strideLengthM = 2.0 * (std::isfinite(g.stepLengthRightM) ? g.stepLengthRightM : g.stepLengthLeftM);
    g.notes.push_back("one foot's steps only: stride length is twice its step");
  } else {
    g.strideLengthM = g.speedMps * g.strideTimeS;
    g.notes.push_back("no two stances with their foot flat in the trial: stride length is speed × stride time");
  }
}

void fillStance(GaitMeasures& g) {
  g.stanceRightPct = stancePctOf(g.strides, Side::Right);
  g.stanceLeftPct = stancePctOf(g.strides, Side::Left);
  const bool right = std::isfinite(g.stanceRightPct), left = std::isfinite(g.stanceLeftPct);
  if (right && left) {
    g.stancePct = 0.5 * (g.stanceRightPct + g.stanceLeftPct);
    g.doubleSupportPct = g.stanceRightPct + g.stanceLeftPct - 100.0;
  } else if (right || left) {
    g.stancePct = right ? g.stanceRightPct : g.stanceLeftPct;
    g.doubleSupportPct = 2.0 * g.stancePct - 100.0;
    g.notes.push_back(std::string("stance of the ") + (right ? "left" : "right") +
                      " foot not measured (no foot off inside one of its strides): double support "
                      "assumes a symmetric gait");
  } else {
    g.notes.push_back("no foot off inside a stride: stance, swing and double support not measured");
  }
  g.swingPct = 100.0 - g.stancePct;
}

// Strike-to-strike durations and each foot's off-to-off intervals a plausible stride apart.
std::vector<double> withFootOffIntervals(std::vector<double> durations, const GaitEventSet& events) {
  for (const FootEvents* foot : {&events.right, &events.left}) {
    for (std::size_t i = 0; i + 1 < foot->offsS.size(); ++i) {
      const double d = foot->offsS[i + 1] - foot->offsS[i];
      if (d >= 1.0 / kMaxStrideHz && d <= 1.0 / kMinStrideHz) durations.push_back(d);
    }
  }
  return durations;
}

std::vector<CycleCurve> cycleCurvesOf(const std::vector<std::string>& wantedNames,
                                      const Eigen::Ref<const Eigen::MatrixXd>& angles,
                                      const std::vector<std::string>& names, double rateHz,
                                      const GaitMeasures& measures, int samples) {
  std::vector<CycleCurve> curves;
  if (samples < 2 || !(rateHz > 0) || static_cast<size_t>(angles.cols()) != names.size()) return curves;
  for (const auto& wanted : wantedNames) {
    const auto column = std::find(names.begin(), names.end(), wanted);
    if (column == names.end()) continue;
    const int c = static_cast<int>(column - names.begin());
    const Side side = wanted.back() == 'r' ? Side::Right : Side::Left;
    std::vector<Eigen::VectorXd> strides;
    for (const auto& s : measures.strides) {
      if (s.side != side) continue;
      Eigen::VectorXd curve(samples);
      for (int k = 0; k < samples; ++k) {
        const double t = s.strikeS + (s.nextStrikeS - s.strikeS) * k / (samples - 1.0);
        curve[k] = sampleAt(angles, c, t, rateHz);
      }
      if (curve.allFinite()) strides.push_back(curve);
    }
    if (strides.empty()) continue;
    CycleCurve out{wanted, Eigen::VectorXd::Zero(samples), Eigen::VectorXd::Zero(samples),
                   static_cast<int>(strides.size())};
    for (const auto& s : strides) out.meanDeg += s;
    out.meanDeg /= static_cast<double>(strides.size());
    for (const auto& s : strides) out.sdDeg += (s - out.meanDeg).cwiseAbs2();
    if (strides.size() > 1) out.sdDeg = (out.sdDeg / (static_cast<double>(strides.size()) - 1.0)).cwiseSqrt();
    curves.push_back(std::move(out));
  }
  return curves;
}

}  // namespace

GaitMeasures measureGait(const Eigen::Ref<const Eigen::MatrixXd>& m, double rateHz,
                         const GaitEventSet& events, std::optional<double> progressionSpeedMps,
                         const std::string& name) {
  checkInput(m, rateHz, name);
  GaitMeasures g;
  g.events = events;
  g.strides = stridesOf(events.right, Side::Right);
  const auto left = stridesOf(events.left, Side::Left);
  g.strides.insert(g.strides.end(), left.begin(), left.end());
  std::sort(g.strides.begin(), g.strides.end(),
            [](const StrideRecord& a, const StrideRecord& b) { return a.strikeS < b.strikeS; });
  if (g.strides.empty()) {
    std::ostringstream msg;
    msg << "gait measures (" << events.method << "): no complete stride (found "
        << events.right.strikesS.size() << " right and " << events.left.strikesS.size()
        << " left foot strikes; a stride is two strikes of one foot "
        << 1.0 / kMaxStrideHz << "-" << 1.0 / kMinStrideHz << " s apart)";
    throwBadData(name, "", msg.str());
  }
  std::vector<double> durations;
  for (const auto& s : g.strides) durations.push_back(s.nextStrikeS - s.strikeS);
  g.strideTimeS = meanOf(durations);
  g.strideTimeAllEventsS = meanOf(withFootOffIntervals(durations, events));
  g.cadenceSpm = 120.0 / g.strideTimeS;
  // The frame may carry the walker forward (overground) or not (progression removed): speed
  // is the pelvis's mean velocity relative to the stance feet either way.
  const Eigen::Vector2d slide = stanceFootSlide(m, rateHz, events, g.strideTimeS);
  const Eigen::Vector2d pelvis = pelvisTrend(m, rateHz);
  g.stanceFootSpeedMps = (pelvis.y() - slide.y()) / 1000.0;
  // A progression far below what the feet show is no walk over the floor: a treadmill, or
  // frames whose progression was removed before (a joints CSV or TRC). The feet then tell.
  if (progressionSpeedMps && std::isfinite(g.stanceFootSpeedMps) &&
      *progressionSpeedMps < 0.5 * g.stanceFootSpeedMps) {
    std::ostringstream note;
    note << std::fixed << std::setprecision(2) << "walking in place (progression " << *progressionSpeedMps
         << " m/s, the stance feet " << g.stanceFootSpeedMps << " m/s): speed from the stance feet";
    g.notes.push_back(note.str());
    progressionSpeedMps.reset();
  }
  if (progressionSpeedMps && *progressionSpeedMps > 0) {
    g.speedMps = *progressionSpeedMps;
    g.speedSource = "progression";
  } else if (std::isfinite(g.stanceFootSpeedMps)) {
    g.speedMps = g.stanceFootSpeedMps;
    g.speedSource = "stance feet";
  }
  // The floor under the walker: its known progression, else the stance feet's own slide.
  const Eigen::Vector2d floorSlide = progressionSpeedMps && *progressionSpeedMps > 0
                                         ? Eigen::Vector2d(pelvis.x(), pelvis.y() - *progressionSpeedMps * 1000.0)
                                         : (slide.allFinite() ? slide : Eigen::Vector2d::Zero());
  fillSteps(g, m, rateHz, floorSlide);
  fillStance(g);
  if (!std::isfinite(g.speedMps)) {
    g.speedMps = g.strideLengthM / g.strideTimeS;
    g.speedSource = "stride length × stride frequency";
  }
  return g;
}

const std::vector<std::string>& flexionCurveNames() {
  static const std::vector<std::string> names = {
      "hip_flexion_r", "knee_angle_r", "arm_flex_r", "elbow_flex_r",
      "hip_flexion_l", "knee_angle_l", "arm_flex_l", "elbow_flex_l"};
  return names;
}

double gaitMeasureByName(const GaitMeasures& g, const std::vector<CycleCurve>& curves, const std::string& key) {
  if (key == "cadence_spm") return g.cadenceSpm;
  if (key == "stride_time_s") return g.strideTimeS;
  if (key == "stride_time_all_events_s") return g.strideTimeAllEventsS;
  if (key == "stride_length_m") return g.strideLengthM;
  if (key == "step_length_r_m") return g.stepLengthRightM;
  if (key == "step_length_l_m") return g.stepLengthLeftM;
  if (key == "step_width_m") return g.stepWidthM;
  if (key == "speed_mps") return g.speedMps;
  if (key == "stance_pct") return g.stancePct;
  if (key == "swing_pct") return g.swingPct;
  if (key == "double_support_pct") return g.doubleSupportPct;
  if (key == "hip_flexion_range_deg") return flexionRangeDeg(curves, "hip_flexion");
  if (key == "knee_flexion_range_deg") return flexionRangeDeg(curves, "knee_angle");
  if (key == "ankle_flexion_range_deg") return flexionRangeDeg(curves, "ankle_angle");
  return NAN;
}

double flexionRangeDeg(const std::vector<CycleCurve>& curves, const std::string& base) {
  double sum = 0.0;
  int count = 0;
  for (const auto& c : curves) {
    if (c.name != base + "_r" && c.name != base + "_l") continue;
    sum += c.meanDeg.maxCoeff() - c.meanDeg.minCoeff();
    ++count;
  }
  return count > 0 ? sum / count : NAN;
}

std::vector<CycleCurve> flexionCycleCurves(const Eigen::Ref<const Eigen::MatrixXd>& angles,
                                           const std::vector<std::string>& names, double rateHz,
                                           const GaitMeasures& measures, int samples) {
  return cycleCurvesOf(flexionCurveNames(), angles, names, rateHz, measures, samples);
}

std::vector<CycleCurve> footCycleCurves(const Eigen::Ref<const Eigen::MatrixXd>& angles,
                                        const std::vector<std::string>& names, double rateHz,
                                        const GaitMeasures& measures, int samples) {
  static const std::vector<std::string> ankle = {"ankle_angle_r", "ankle_angle_l"};
  return cycleCurvesOf(ankle, angles, names, rateHz, measures, samples);
}

FootProgression footProgressionDeg(const Eigen::Ref<const Eigen::MatrixXd>& angles,
                                   const std::vector<std::string>& names, double rateHz,
                                   const GaitMeasures& measures) {
  FootProgression out;
  if (!(rateHz > 0) || static_cast<size_t>(angles.cols()) != names.size()) return out;
  for (Side side : {Side::Right, Side::Left}) {
    const auto column = std::find(names.begin(), names.end(),
                                  side == Side::Right ? "foot_progression_r" : "foot_progression_l");
    if (column == names.end()) continue;
    const int c = static_cast<int>(column - names.begin());
    std::vector<double> perStride;
    for (const auto& s : measures.strides) {
      if (s.side != side) continue;
      const auto [first, last] = flatRows(s.strikeS, s.nextStrikeS - s.strikeS, rateHz, angles.rows());
      if (first > last) continue;
      const Eigen::VectorXd flat = angles.col(c).segment(first, last - first + 1);
      if (flat.allFinite()) perStride.push_back(flat.mean());
    }
    (side == Side::Right ? out.rightDeg : out.leftDeg) = meanOf(perStride);
  }
  return out;
}

}  // namespace ew
