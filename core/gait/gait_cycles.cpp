#include "core/gait/gait_cycles.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "core/common/errors.h"
#include "core/gait/gait_events.h"

namespace ew {
namespace {

std::vector<double> strikesFromEvents(const std::vector<GaitEvent>& events, Side side,
                                      double durationS) {
  std::vector<double> t;
  for (const auto& e : events) {
    if (e.side == side && e.type == GaitEventType::FootStrike && e.timeS >= 0 &&
        e.timeS <= durationS) {
      t.push_back(e.timeS);
    }
  }
  std::sort(t.begin(), t.end());
  return t;
}

// Strides per second from same-side strike intervals; from alternating strikes when no
// side has two (a trial of about one cycle).
double strideHzFromStrikes(const std::vector<double>& right, const std::vector<double>& left) {
  double total = 0.0;
  int count = 0;
  for (const auto* side : {&right, &left}) {
    if (side->size() >= 2) {
      total += side->back() - side->front();
      count += static_cast<int>(side->size()) - 1;
    }
  }
  if (count > 0) return count / total;
  if (!right.empty() && !left.empty()) {
    const double step = std::abs(right.front() - left.front());
    return step > 0 ? 1.0 / (2.0 * step) : 0.0;
  }
  return 0.0;
}

void checkWalking(const Eigen::MatrixXd& m, double rateHz, const std::string& file) {
  for (Side side : {Side::Right, Side::Left}) {
    const Eigen::VectorXd lead = ankleLeadMm(m, rateHz, side);
    const double range = lead.maxCoeff() - lead.minCoeff();
    if (range < kMinAnkleExcursionMm) {
      std::ostringstream msg;
      msg << "not walking: the " << (side == Side::Right ? "right" : "left")
          << " ankle moves only " << std::lround(range)
          << " mm fore-aft relative to the pelvis (walking needs > " << kMinAnkleExcursionMm
          << " mm)";
      throwBadData(file, "", msg.str());
    }
  }
}

}  // namespace

std::vector<double> footStrikesFromKinematics(const Eigen::MatrixXd& m, double rateHz, Side side) {
  if (m.rows() < 3 || m.cols() != kDims3 || !(rateHz > 0)) return {};  // no interior peak possible
  // Whole frames, not refined: the models' cycles were built with these.
  std::vector<double> strikes;
  for (int i : dominantPeaks(ankleLeadMm(m, rateHz, side), rateHz)) strikes.push_back(i / rateHz);
  return strikes;
}

GaitCycles detectGaitCycles(const Eigen::MatrixXd& m, double rateHz,
                            const std::vector<GaitEvent>& events, const std::string& file) {
  if (m.rows() < 2 || m.cols() != kDims3 || !std::isfinite(rateHz) || !(rateHz > 0)) {
    throwBadData(file, "",
                 "gait cycles: need at least two frames of 15 joints and a positive rate (" +
                     std::to_string(m.rows()) + " frames)");
  }
  if (!m.allFinite()) throwBadData(file, "", "gait cycles: the joint positions are not all finite");
  checkWalking(m, rateHz, file);
  const double durationS = static_cast<double>(m.rows() - 1) / rateHz;
  GaitCycles cycles;
  cycles.rightStrikesS = strikesFromEvents(events, Side::Right, durationS);
  cycles.leftStrikesS = strikesFromEvents(events, Side::Left, durationS);
  cycles.strideHz = strideHzFromStrikes(cycles.rightStrikesS, cycles.leftStrikesS);
  cycles.method = "file events";
  if (!(cycles.strideHz > 0)) {
    cycles.rightStrikesS = footStrikesFromKinematics(m, rateHz, Side::Right);
    cycles.leftStrikesS = footStrikesFromKinematics(m, rateHz, Side::Left);
    cycles.strideHz = strideHzFromStrikes(cycles.rightStrikesS, cycles.leftStrikesS);
    cycles.method = "foot contacts";
  }
  if (cycles.strideHz < kMinStrideHz || cycles.strideHz > kMaxStrideHz) {
    std::ostringstream msg;
    msg << "not walking: no regular foot strikes (found " << cycles.rightStrikesS.size()
        << " right, " << cycles.leftStrikesS.size() << " left";
    if (cycles.strideHz > 0) msg << ", stride frequency " << cycles.strideHz << " Hz";
    msg << "; walking is " << kMinStrideHz << "-" << kMaxStrideHz << " Hz)";
    throwBadData(file, "", msg.str());
  }
  cycles.cycleCount = (static_cast<double>(m.rows()) / rateHz) * cycles.strideHz;
  if (cycles.cycleCount < 1.0) {
    std::ostringstream msg;
    msg << "shorter than one gait cycle (" << cycles.cycleCount << " cycles of "
        << 1.0 / cycles.strideHz << " s): at least one full cycle is needed";
    throwBadData(file, "", msg.str());
  }
  return cycles;
}

}  // namespace ew
