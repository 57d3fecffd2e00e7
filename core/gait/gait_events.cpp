#include "core/gait/gait_events.h"
#include "core/gait/gaps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/QR>

#include "core/common/skeleton.h"
#include "core/gait/gait_cycles.h"

namespace ew {
namespace {

int smoothingHalfWidth(double rateHz) {
  return std::max(0, static_cast<int>(std::lround(0.025 * rateHz)));
}

std::vector<double> rowsToSeconds(const Eigen::VectorXd& signal, const std::vector<int>& rows,
                                  double rateHz) {
  std::vector<double> seconds;
  seconds.reserve(rows.size());
  for (int i : rows) seconds.push_back(refinedExtreme(signal, i) / rateHz);
  return seconds;
}

// Near either end the smoothing window is cut short and the signal may still be rising past
// the last frame: an extreme found there is the window's, not the foot's. Dropped.
std::vector<int> awayFromEnds(const std::vector<int>& rows, Eigen::Index n, double rateHz) {
  const int margin = smoothingHalfWidth(rateHz) + 1;
  std::vector<int> kept;
  for (int i : rows)
    if (i >= margin && i + margin < n) kept.push_back(i);
  return kept;
}

void sortedInto(std::vector<double>& times) { std::sort(times.begin(), times.end()); }

// The times of a signal's dominant maxima away from the clip's ends, to a fraction of a frame.
std::vector<double> extremesS(const Eigen::VectorXd& signal, double rateHz) {
  return rowsToSeconds(signal, awayFromEnds(dominantPeaks(signal, rateHz), signal.size(), rateHz), rateHz);
}

}  // namespace

Eigen::VectorXd ankleLeadMm(const Eigen::Ref<const Eigen::MatrixXd>& m, double rateHz, Side side) {
  return smoothedLead(m.col(3 * index(ankleOf(side)) + 1) - m.col(3 * index(Joint::Pelvis) + 1), rateHz);
}

Eigen::VectorXd footPointLeadMm(const Eigen::Ref<const Eigen::MatrixXd>& framesX45,
                                const Eigen::Ref<const Eigen::MatrixXd>& feetX12, double rateHz, FootPoint p) {
  return smoothedLead(feetX12.col(3 * index(p) + 1) - framesX45.col(3 * index(Joint::Pelvis) + 1), rateHz);
}

Eigen::VectorXd smoothedLead(const Eigen::VectorXd& raw, double rateHz) {
  const int half = smoothingHalfWidth(rateHz);
  const auto n = raw.size();
  Eigen::VectorXd smooth(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index a = std::max<Eigen::Index>(0, i - half);
    const Eigen::Index b = std::min<Eigen::Index>(n - 1, i + half);
    smooth[i] = raw.segment(a, b - a + 1).mean();
  }
  return smooth;
}

std::vector<int> dominantPeaks(const Eigen::VectorXd& s, double rateHz) {
  const auto n = s.size();
  if (n < 3) return {};
  const double mean = s.mean();
  const double threshold = mean + 0.3 * (s.maxCoeff() - mean);
  const auto reach = static_cast<Eigen::Index>(std::lround(0.5 / kMaxStrideHz * rateHz));
  std::vector<int> peaks;
  for (Eigen::Index i = 1; i + 1 < n; ++i) {
    if (s[i] < threshold || s[i] < s[i - 1] || s[i] <= s[i + 1]) continue;
    const Eigen::Index a = std::max<Eigen::Index>(0, i - reach);
    const Eigen::Index b = std::min<Eigen::Index>(n - 1, i + reach);
    if (s.segment(a, b - a + 1).maxCoeff() > s[i]) continue;
    peaks.push_back(static_cast<int>(i));
  }
  return peaks;
}

double refinedExtreme(const Eigen::VectorXd& s, int i) {
  if (i <= 0 || i + 1 >= s.size()) return i;
  const double curvature = s[i - 1] - 2.0 * s[i] + s[i + 1];
  if (!(std::abs(curvature) > 1e-12)) return i;
  const double shift = 0.5 * (s[i - 1] - s[i + 1]) / curvature;
  return i + std::clamp(shift, -0.5, 0.5);
}

GaitEventSet gaitEventsFromKinematics(const Eigen::Ref<const Eigen::MatrixXd>& m, double rateHz,
                                      double footOffLag) {
  GaitEventSet events;
  events.method = "kinematics";
  if (m.rows() < 3 || m.cols() != kDims3 || !(rateHz > 0) || !std::isfinite(rateHz)) return events;
  for (Side side : {Side::Right, Side::Left}) {
    const Eigen::VectorXd lead = ankleLeadMm(m, rateHz, side);
    if (!lead.allFinite()) continue;
    FootEvents& foot = side == Side::Right ? events.right : events.left;
    foot.strikesS = extremesS(lead, rateHz);
    foot.offsS = extremesS(-lead, rateHz);
  }
  const double strideS = medianStrideS(events);
  if (!std::isfinite(strideS)) return events;
  const double lastS = static_cast<double>(m.rows() - 1) / rateHz;
  for (FootEvents* foot : {&events.right, &events.left})
    for (double& off : foot->offsS) off = std::min(off + footOffLag * strideS, lastS);
  return events;
}

namespace {

// The phase (0 … 1 of the stride) where a periodic signal, sampled at times t, is largest:
// its harmonics of f fitted by least squares (as many as the samples carry, up to four),
// then evaluated on a fine grid of the cycle.
double phaseOfMaximum(const Eigen::VectorXd& signal, double rateHz, double f) {
  const Eigen::Index n = signal.size();
  const int harmonics = static_cast<int>(std::clamp<Eigen::Index>((n - 1) / 2, 1, 4));
  Eigen::MatrixXd basis(n, 2 * harmonics + 1);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double theta = 2.0 * std::numbers::pi * f * static_cast<double>(i) / rateHz;
    basis(i, 0) = 1.0;
    for (int h = 1; h <= harmonics; ++h) {
      basis(i, 2 * h - 1) = std::sin(h * theta);
      basis(i, 2 * h) = std::cos(h * theta);
    }
  }
  const Eigen::VectorXd c = basis.colPivHouseholderQr().solve(signal);
  constexpr int kGrid = 2000;
  double best = -std::numeric_limits<double>::infinity(), bestPhase = 0.0;
  for (int k = 0; k < kGrid; ++k) {
    const double phase = static_cast<double>(k) / kGrid, theta = 2.0 * std::numbers::pi * phase;
    double v = c(0);
    for (int h = 1; h <= harmonics; ++h) v += c(2 * h - 1) * std::sin(h * theta) + c(2 * h) * std::cos(h * theta);
    if (v > best) best = v, bestPhase = phase;
  }
  return bestPhase;
}

// Every time phase·T + k·T (T = 1/f) within [0, lastS].
std::vector<double> everyStrideAt(double phase, double f, double lastS) {
  std::vector<double> times;
  for (double t = phase / f; t <= lastS; t += 1.0 / f) times.push_back(t);
  return times;
}

}  // namespace

GaitEventSet gaitEventsOfPeriodicWalk(const Eigen::Ref<const Eigen::MatrixXd>& m, double rateHz, double strideHz,
                                      double footOffLag) {
  GaitEventSet events;
  events.method = "kinematics (periodic walk)";
  if (m.rows() < 3 || m.cols() != kDims3 || !(rateHz > 0) || !std::isfinite(rateHz) ||
      !(strideHz >= kMinStrideHz && strideHz <= kMaxStrideHz))
    return events;
  const double lastS = static_cast<double>(m.rows() - 1) / rateHz;
  for (Side side : {Side::Right, Side::Left}) {
    const Eigen::VectorXd lead = m.col(3 * index(ankleOf(side)) + 1) - m.col(3 * index(Joint::Pelvis) + 1);
    if (!lead.allFinite()) continue;
    FootEvents& foot = side == Side::Right ? events.right : events.left;
    foot.strikesS = everyStrideAt(phaseOfMaximum(lead, rateHz, strideHz), strideHz, lastS);
    const double off = std::fmod(phaseOfMaximum(-lead, rateHz, strideHz) + footOffLag, 1.0);
    foot.offsS = everyStrideAt(off, strideHz, lastS);
  }
  return events;
}

namespace {

// [begin, end) of the longest run of frames where a foot's heel and toe are both finite.
std::pair<int, int> bothPointsSeen(const Eigen::Ref<const Eigen::MatrixXd>& feet, Side side) {
  std::vector<bool> seen(static_cast<std::size_t>(feet.rows()));
  for (Eigen::Index r = 0; r < feet.rows(); ++r)
    seen[static_cast<std::size_t>(r)] = feet.row(r).segment<3>(3 * index(heelOf(side))).allFinite() &&
                                        feet.row(r).segment<3>(3 * index(toeOf(side))).allFinite();
  return longestRun(seen);
}

}  // namespace

GaitEventSet gaitEventsFromFeet(const Eigen::Ref<const Eigen::MatrixXd>& m,
                                const Eigen::Ref<const Eigen::MatrixXd>& feet, double rateHz,
                                double heelStrikeLag) {
  GaitEventSet events = gaitEventsFromKinematics(m, rateHz);
  if (m.rows() < 3 || m.cols() != kDims3 || feet.rows() != m.rows() || feet.cols() != kFootDims3 ||
      !(rateHz > 0) || !std::isfinite(rateHz) || !m.col(3 * index(Joint::Pelvis) + 1).allFinite())
    return events;
  // A foot's two events share one point's lead or the other's: the heel and the toe together,
  // else the ankle for both (its foot-off lag makes its stance unbiased; the toe's accurate foot
  // off after the ankle's early strike would read stance long).
  std::array<bool, 2> fromFeet{};
  for (Side side : {Side::Right, Side::Left}) {
    const auto [begin, end] = bothPointsSeen(feet, side);
    if (end - begin < kMinFeetSeenShare * static_cast<double>(m.rows()) || end - begin < 3) continue;
    const auto n = end - begin;
    const auto run = m.middleRows(begin, n);
    const auto runFeet = feet.middleRows(begin, n);
    const double startS = static_cast<double>(begin) / rateHz;
    const auto shifted = [&](std::vector<double> times) {
      for (double& t : times) t += startS;
      return times;
    };
    FootEvents& foot = side == Side::Right ? events.right : events.left;
    foot.strikesS = shifted(extremesS(footPointLeadMm(run, runFeet, rateHz, heelOf(side)), rateHz));
    foot.offsS = shifted(extremesS(-footPointLeadMm(run, runFeet, rateHz, toeOf(side)), rateHz));
    fromFeet[side == Side::Right ? 0 : 1] = true;
  }
  if (!fromFeet[0] && !fromFeet[1]) return events;
  events.method = fromFeet[0] && fromFeet[1] ? "kinematics (heel and toe)" : "kinematics (heel and toe of one foot, the other's ankle)";
  const double strideS = medianStrideS(events);
  if (!std::isfinite(strideS)) return events;
  const double lastS = static_cast<double>(m.rows() - 1) / rateHz;
  for (Side side : {Side::Right, Side::Left}) {
    if (!fromFeet[side == Side::Right ? 0 : 1]) continue;
    for (double& strike : (side == Side::Right ? events.right : events.left).strikesS)
      strike = std::min(strike + heelStrikeLag * strideS, lastS);
  }
  return events;
}

double medianStrideS(const GaitEventSet& events) {
  std::vector<double> strides;
  for (const FootEvents* foot : {&events.right, &events.left})
    for (size_t i = 0; i + 1 < foot->strikesS.size(); ++i) {
      const double s = foot->strikesS[i + 1] - foot->strikesS[i];
      if (s >= 1.0 / kMaxStrideHz && s <= 1.0 / kMinStrideHz) strides.push_back(s);
    }
  if (strides.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto middle = strides.begin() + static_cast<std::ptrdiff_t>(strides.size() / 2);
  std::nth_element(strides.begin(), middle, strides.end());
  if (strides.size() % 2 == 1) return *middle;
  return 0.5 * (*middle + *std::max_element(strides.begin(), middle));
}

GaitEventSet gaitEventsFromFile(const std::vector<GaitEvent>& events, double durationS) {
  GaitEventSet set;
  set.method = "file events";
  for (const auto& e : events) {
    if (!(e.timeS >= 0 && e.timeS <= durationS)) continue;
    FootEvents& foot = e.side == Side::Right ? set.right : set.left;
    if (e.type == GaitEventType::FootStrike) foot.strikesS.push_back(e.timeS);
    if (e.type == GaitEventType::FootOff) foot.offsS.push_back(e.timeS);
  }
  for (FootEvents* foot : {&set.right, &set.left}) {
    sortedInto(foot->strikesS);
    sortedInto(foot->offsS);
  }
  return set;
}

}  // namespace ew
