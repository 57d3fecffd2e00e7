#include "core/gait/body_size.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/common/errors.h"
#include "core/common/statistics.h"
#include "core/io/load_trial.h"

namespace ew {
namespace {

Eigen::Vector3d at(const Eigen::Ref<const Eigen::MatrixXd>& m, Eigen::Index frame, Joint j) {
  return m.block<1, 3>(frame, 3 * index(j)).transpose();
}

std::string metres(double mm) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g m", mm / 1000.0);
  return text;
}

// The unit among the usual ones that brings the length nearest the typical adult's (in
// log scale) while inside the plausible range; nullopt when none does or `unit` is not
// one the loaders know.
std::optional<std::string> likelyUnit(const BodySize& size, const std::string& unit) {
  double mmPerUnit = 0.0;
  try {
    mmPerUnit = unitToMm(unit, "");
  } catch (const Error&) {
    return std::nullopt;
  }
  const double raw = size.lengthMm / mmPerUnit;  // the length in the file's own numbers
  std::optional<std::string> best;
  double bestDistance = 0.0;
  for (const char* candidate : {"mm", "cm", "m", "in", "cmu"}) {
    const double mm = raw * unitToMm(candidate, "");
    if (mm < size.minMm || mm > size.maxMm) continue;
    const double distance = std::abs(std::log(mm / size.typicalMm));
    if (!best || distance < bestDistance) {
      best = candidate;
      bestDistance = distance;
    }
  }
  return best;
}

}  // namespace

std::optional<BodySize> measureBodySize(const Eigen::Ref<const Eigen::MatrixXd>& m) {
  if (m.cols() != kDims3) return std::nullopt;
  std::vector<double> headToAnkles, hipsToAnkles;
  for (Eigen::Index f = 0; f < m.rows(); ++f) {
    const Eigen::Vector3d ankles = 0.5 * (at(m, f, Joint::RAnkle) + at(m, f, Joint::LAnkle));
    const double head = (at(m, f, Joint::Head) - ankles).norm();
    if (std::isfinite(head)) headToAnkles.push_back(head);
    const double legs = 0.5 * ((at(m, f, Joint::RHip) - at(m, f, Joint::RAnkle)).norm() +
                               (at(m, f, Joint::LHip) - at(m, f, Joint::LAnkle)).norm());
    if (std::isfinite(legs)) hipsToAnkles.push_back(legs);
  }
  if (!headToAnkles.empty())
    return BodySize{"head to ankles", median(headToAnkles), 700.0, 2200.0, 1500.0};
  if (!hipsToAnkles.empty())
    return BodySize{"hips to ankles", median(hipsToAnkles), 350.0, 1200.0, 850.0};
  return std::nullopt;
}

std::optional<std::string> bodySizeWarning(const JointTrial& trial) {
  const auto size = measureBodySize(trial.positionsMm);
  if (!size || (size->lengthMm >= size->minMm && size->lengthMm <= size->maxMm))
    return std::nullopt;
  std::string text = trial.file + ": the walker measures " + metres(size->lengthMm) + " from " +
                     size->what + " (a person's " + metres(size->minMm) + " to " +
                     metres(size->maxMm) + ")";
  const std::string unit = trial.units.empty() ? std::string("mm") : trial.units;
  const auto likely = likelyUnit(*size, unit);
  if (likely && *likely != unit)
    return text + ": the file's unit is probably " + *likely + ", not " + unit + "; use --units " +
           *likely;
  return text + ": check the file's length unit (--units)";
}

}  // namespace ew
