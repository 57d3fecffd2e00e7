#pragma once
// Error against the view angle for the snippet and skeleton engines, leave-one-subject-out,
// on walkers known only as Fourier vectors (the viewer's population): the analysis window's
// per-engine curves beside the eigenwalker's own (experiments.h, knownViewErrors).
//
// Each held-out walker walks `cycles` cycles overground at `speedMps` (overgroundFrames, 30 Hz)
// and is seen orthographically at each angle (mm, the view known):
//   snippet   the prior learnt from the other subjects' walkers walked the same way
//             (fourierSnippetPrior), given the frames with their progression;
//   skeleton  the walker's own bone lengths (Zou et al. 2009), given the frames in place.
// Scored as experiment "snippet" scores them (clipErrors: MPJPE over every frame and the mean
// squared depth error E_a, after removing the clip's mean translation).

#include <string>
#include <vector>

#include "core/engines/engine.h"
#include "core/experiments/leave_one_out.h"

namespace ew {

struct EngineViewOptions {
  std::vector<double> anglesDeg;
  std::vector<EngineKind> engines{EngineKind::Snippet, EngineKind::Skeleton};
  double cycles = 2.0;
  double speedMps = 1.3;   // the middle of the shared walkers' speeds
  double priorCycles = 4.0;  // each training walker's cycles (fewer: a faster, coarser prior)
  int threads = 1;
};

struct EngineViewRow {
  std::string subject;
  EngineKind engine = EngineKind::Snippet;
  double angleDeg = 0.0;
  double mpjpeMm = 0.0, depthErrorMm2 = 0.0;  // NaN when the engine gave no answer
  std::string error;
};

// progress(done, total, what) after each fold. Error(BadArgument) "engine curves: …" for no
// angle, a non-finite angle, the eigenwalker asked for (its curves are knownViewErrors'), or
// fewer than 3 subjects.
std::vector<EngineViewRow> engineViewErrors(const std::vector<ExperimentWalker>& walkers,
                                            const EngineViewOptions& options,
                                            const std::function<void(int, int, const std::string&)>& progress = {});

// The snippet prior learnt from every walker of a subject other than `without`, each walked
// `cycles` cycles overground at `speedMps`.
SnippetPrior fourierSnippetPrior(const std::vector<ExperimentWalker>& walkers, const std::string& without,
                                 double speedMps, double cycles = 4.0);

}  // namespace ew
