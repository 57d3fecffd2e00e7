#include "core/experiments/engine_view_curves.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <mutex>
#include <numbers>

#include "core/engines/request.h"
#include "core/common/errors.h"
#include "core/eigenwalker/projection.h"
#include "core/skeleton/skeleton_tree.h"
#include "core/snippet/snippet_prior.h"

namespace ew {
namespace {

constexpr double kRateHz = 30.0;

[[noreturn]] void badCurvesOption(const std::string& what) {
  throw Error(ErrorKind::BadArgument, "", "", "engine curves: " + what);
}

void checkOptions(const std::vector<ExperimentWalker>& walkers, const EngineViewOptions& o) {
  if (o.anglesDeg.empty()) badCurvesOption("no view angle");
  for (double a : o.anglesDeg)
    if (!std::isfinite(a)) badCurvesOption("view angles must be finite");
  if (hasEngine(o.engines, EngineKind::Eigenwalker))
    badCurvesOption("the eigenwalker's curves are the known-view experiment's");
  if (walkerSubjects(walkers).size() < 3) throwBadData("engine curves", "", "leave-one-subject-out needs 3 subjects");
}

// One engine at one view: its row, scored against `truth`, or the reason it gave none.
EngineViewRow scoreView(const std::string& subject, EngineKind kind, double alpha, const Engine& engine,
                        const Eigen::MatrixXd& frames, double strideHz) {
  EngineViewRow row{subject, kind, alpha, NAN, NAN, ""};
  try {
    ViewInput in;
    in.uvMm = projectFramesToView(frames, alpha);
    in.rateHz = kRateHz;
    in.alphaDeg = alpha;
    in.strideHzHint = strideHz;
    in.name = subject;
    const ClipErrors e = clipErrors(reconstruct(engine, {in}).engine.framesMm, frames, alpha);
    row.mpjpeMm = e.mpjpeMm;
    row.depthErrorMm2 = e.depthErrorMm2;
  } catch (const std::exception& e) {
    row.error = e.what();
  }
  return row;
}

}  // namespace

SnippetPrior fourierSnippetPrior(const std::vector<ExperimentWalker>& walkers, const std::string& without,
                                 double speedMps, double cycles) {
  std::vector<FourierWalkerTrial> trials;
  for (const auto& w : walkers)
    if (w.subject != without) trials.push_back({w.subject, w.id, w.fit.w, w.fit.omegaRadS, speedMps});
  return trainSnippetPrior(snippetTrialsFromFourier(trials, cycles), {});
}

std::vector<EngineViewRow> engineViewErrors(const std::vector<ExperimentWalker>& walkers,
                                            const EngineViewOptions& o,
                                            const std::function<void(int, int, const std::string&)>& progress) {
  checkOptions(walkers, o);
  const std::vector<std::string> subjects = walkerSubjects(walkers);
  const int total = static_cast<int>(subjects.size());
  std::vector<std::vector<EngineViewRow>> parts(subjects.size());
  std::mutex progressMutex;
  int done = 0;
  if (progress) progress(0, total, "engine curves");
  parallelFor(total, o.threads, [&](int f) {
    const std::string& subject = subjects[static_cast<size_t>(f)];
    SnippetEngine snippet;
    std::string noPrior;
    if (hasEngine(o.engines, EngineKind::Snippet)) {
      try {
        snippet.prior = std::make_shared<const PreparedSnippetPrior>(
            prepareSnippetPrior(fourierSnippetPrior(walkers, subject, o.speedMps, o.priorCycles)));
      } catch (const std::exception& e) {
        noPrior = std::string("snippet prior: ") + e.what();
      }
    }
    for (const auto& w : walkers) {
      if (w.subject != subject) continue;
      const double strideHz = w.fit.omegaRadS / (2.0 * std::numbers::pi);
      const Eigen::MatrixXd overground = overgroundFrames(w.fit.w, w.fit.omegaRadS, o.speedMps, o.cycles, kRateHz);
      const Eigen::MatrixXd inPlace = overgroundFrames(w.fit.w, w.fit.omegaRadS, 0.0, o.cycles, kRateHz);
      SkeletonEngine skeleton;
      if (hasEngine(o.engines, EngineKind::Skeleton)) skeleton.bones = boneLengthsFromFrames(inPlace, w.id);
      for (double alpha : o.anglesDeg) {
        if (hasEngine(o.engines, EngineKind::Snippet))
          parts[static_cast<size_t>(f)].push_back(
              noPrior.empty() ? scoreView(subject, EngineKind::Snippet, alpha, snippet, overground, strideHz)
                              : EngineViewRow{subject, EngineKind::Snippet, alpha, NAN, NAN, noPrior});
        if (hasEngine(o.engines, EngineKind::Skeleton))
          parts[static_cast<size_t>(f)].push_back(
              scoreView(subject, EngineKind::Skeleton, alpha, skeleton, inPlace, strideHz));
      }
    }
    if (progress) {
      const std::lock_guard<std::mutex> lock(progressMutex);
      progress(++done, total, "engine curves");
    }
  });
  std::vector<EngineViewRow> rows;
  for (auto& p : parts) rows.insert(rows.end(), p.begin(), p.end());
  return rows;
}

}  // namespace ew
