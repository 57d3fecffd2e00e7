#include "core/experiments/lower_body.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/common/errors.h"
#include "core/eigenwalker/joint_completion.h"
#include "core/eigenwalker/metrics.h"

namespace ew {
namespace {

[[noreturn]] void lowerBodyError(const std::string& problem) {
  throw Error(ErrorKind::BadArgument, "", "", "lower body: " + problem);
}

JointMask estimatedJoints() {
  JointMask m = lowerBodyMeasured();
  for (bool& b : m) b = !b;
  return m;
}

// The mean walker's coefficients in place of the joints in `missing`.
Eigen::VectorXd meanBaseline(const Eigen::VectorXd& w, const EigenwalkerModel& model,
                             const JointMask& missing) {
  Eigen::VectorXd out = w;
  for (int b = 0; b < kFourierBlocks; ++b) {
    for (int j = 0; j < kJointCount; ++j) {
      if (missing[static_cast<size_t>(j)])
        out.segment<3>(b * kDims3 + 3 * j) = model.mean.segment<3>(b * kDims3 + 3 * j);
    }
  }
  return out;
}

void addRows(std::vector<LowerBodyRow>& rows, const ExperimentWalker& walker,
             const std::string& method, const Eigen::VectorXd& wEstimate) {
  const JointMask estimated = estimatedJoints();
  const Eigen::VectorXd perJoint = mpjpePerJoint(walker.fit.w, wEstimate);
  for (int j = 0; j < kJointCount; ++j) {
    if (!estimated[static_cast<size_t>(j)]) continue;
    rows.push_back({walker.subject, walker.id, std::string(kJointNames[static_cast<size_t>(j)]),
                    method, perJoint(j)});
  }
}

void checkArguments(const std::vector<ExperimentWalker>& walkers, const std::vector<Fold>& folds,
                    bool lsq, bool map, double sigma2Mm2) {
  if (!lsq && !map) lowerBodyError("no method chosen");
  if (!(std::isfinite(sigma2Mm2) && sigma2Mm2 >= 0.0))
    lowerBodyError("σ² must be finite and ≥ 0 mm², got " + std::to_string(sigma2Mm2));
  for (const Fold& f : folds) {
    for (int r : f.testWalkers) {
      if (r < 0 || static_cast<size_t>(r) >= walkers.size())
        lowerBodyError("fold '" + f.subject + "' names walker " + std::to_string(r) + " of " +
                       std::to_string(walkers.size()) + ": folds and walkers do not match");
    }
  }
}

}  // namespace

JointMask lowerBodyMeasured() {
  JointMask m{};
  for (Joint j : {Joint::Pelvis, Joint::RHip, Joint::RKnee, Joint::RAnkle, Joint::LHip,
                  Joint::LKnee, Joint::LAnkle})
    m[static_cast<size_t>(index(j))] = true;
  return m;
}

std::vector<LowerBodyRow> lowerBodyErrors(const std::vector<ExperimentWalker>& walkers,
                                          const std::vector<Fold>& folds, bool lsq, bool map,
                                          double sigma2Mm2, int threads) {
  checkArguments(walkers, folds, lsq, map, sigma2Mm2);
  const JointMask missing = estimatedJoints();
  std::vector<std::vector<LowerBodyRow>> parts(folds.size());
  parallelFor(static_cast<int>(folds.size()), threads, [&](int f) {
    const Fold& fold = folds[static_cast<size_t>(f)];
    auto& rows = parts[static_cast<size_t>(f)];
    for (int r : fold.testWalkers) {
      const ExperimentWalker& walker = walkers[static_cast<size_t>(r)];
      if (lsq) {
        CompletionOptions o;
        o.sigma2Mm2 = 0.0;
        addRows(rows, walker, "lsq", completeJoints(fold.model, walker.fit.w, missing, o).w);
      }
      if (map) {
        CompletionOptions o;
        o.sigma2Mm2 = sigma2Mm2;
        addRows(rows, walker, "map", completeJoints(fold.model, walker.fit.w, missing, o).w);
      }
      addRows(rows, walker, "mean", meanBaseline(walker.fit.w, fold.model, missing));
    }
  });
  std::vector<LowerBodyRow> out;
  for (auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

std::vector<LowerBodySummary> summarizeLowerBody(const std::vector<LowerBodyRow>& rows) {
  // (method, joint index or 15 = all) → sum, count; methods in first-seen order.
  std::vector<std::string> methods;
  std::map<std::pair<std::string, int>, std::pair<double, int>> acc;
  for (const auto& r : rows) {
    if (std::find(methods.begin(), methods.end(), r.method) == methods.end())
      methods.push_back(r.method);
    const auto j = jointFromName(r.joint);
    for (int key : {j ? index(*j) : kJointCount, kJointCount}) {
      auto& a = acc[{r.method, key}];
      a.first += r.mpjpeMm;
      a.second += 1;
    }
  }
  std::vector<LowerBodySummary> out;
  for (const auto& m : methods) {
    for (int j = 0; j <= kJointCount; ++j) {
      const auto it = acc.find({m, j});
      if (it == acc.end()) continue;
      out.push_back({m, j == kJointCount ? "all" : std::string(kJointNames[static_cast<size_t>(j)]),
                     it->second.first / it->second.second});
    }
  }
  return out;
}

}  // namespace ew
