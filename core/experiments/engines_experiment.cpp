#include "core/experiments/engines_experiment.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <tuple>

#include "core/common/errors.h"
#include "core/common/statistics.h"

namespace ew {
namespace {

[[noreturn]] void badEnginesOption(const std::string& what) { throw Error(ErrorKind::BadArgument, "", "", "engines: " + what); }

void checkOptions(const EnginesExperimentOptions& o) {
  if (o.engines.empty()) badEnginesOption("no engine to compare");
  if (!o.views && !o.cameras) badEnginesOption("neither views nor cameras: nothing to compare on");
  if (o.views && o.anglesDeg.empty()) badEnginesOption("no view angle");
  for (double a : o.anglesDeg)
    if (!std::isfinite(a)) badEnginesOption("view angles must be finite");
  for (const auto* levels : {&o.noiseMm, &o.noisePx}) {
    if (levels->empty()) badEnginesOption("no noise level");
    for (double n : *levels)
      if (!(std::isfinite(n) && n >= 0.0)) badEnginesOption("noise levels must be finite and >= 0");
  }
  if (o.cameras && o.camerasPerWalker < 1) badEnginesOption("at least one camera per walker");
}

// Experiment "snippet"'s engine labels → (engine, variant, the gait table's label).
struct ViewEngineName {
  const char* snippetLabel;
  const char* engine;
  const char* variant;
  const char* gaitLabel;
};
constexpr ViewEngineName kViewEngines[] = {
    {"eigenwalker MAP", "eigenwalker", "MAP, known view", "eigenwalker"},
    {"snippet MAP", "snippet", "MAP, known view", "snippet"},
    {"skeleton", "skeleton", "own bones", "skeleton (own bones)"},
};

const ViewEngineName& viewEngine(const std::string& snippetLabel) {
  for (const auto& e : kViewEngines)
    if (snippetLabel == e.snippetLabel) return e;
  throw Error(ErrorKind::BadData, "engines", "", "unknown engine label '" + snippetLabel + "'");
}

void compareOnViews(const Dataset& dataset, const std::vector<Walker>& walkers, const EnginesExperimentOptions& o,
                    EnginesExperimentResults& out) {
  SnippetExperimentOptions s;
  s.anglesDeg = o.anglesDeg;
  s.noiseMm = o.noiseMm;
  s.beyondTheTrial = false;
  s.engines = o.engines;
  s.sigma2Mm2 = o.sigma2Mm2;
  s.model = o.model;
  s.prior = o.prior;
  s.threads = o.threads;
  SnippetExperimentResults r = snippetComparison(dataset, walkers, s);
  for (const EngineRow& e : r.rows) {
    const ViewEngineName& name = viewEngine(e.engine);
    out.rows.push_back({"view", e.subject, name.engine, name.variant, e.angleDeg, -1, e.noiseMm, "mm", e.frames,
                        e.error.empty() ? e.mpjpeMm : NAN, e.error.empty() ? e.depthErrorMm2 : NAN, e.seconds,
                        e.error});
  }
  for (GaitAgreementRow& g : r.gait) {
    g.engine = viewEngine(g.engine).gaitLabel;
    out.gait.push_back(std::move(g));
  }
  for (auto& w : r.warnings) out.warnings.push_back(std::move(w));
}

// One camera clip's row for an engine's variant (`score` unset: the variant was not asked for).
void addCameraRow(const CameraRow& c, const char* engine, const char* variant, const std::optional<EngineClipScore>& score,
                  EnginesExperimentResults& out) {
  if (!score) return;
  const bool answered = score->error.empty();
  out.rows.push_back({"camera", c.subject, engine, variant, c.trueAlphaDeg, c.camera, c.noisePx, "px", c.frames,
                      answered ? score->mpjpeMm : NAN, NAN, score->seconds, score->error});
}

void compareOnCameras(const std::vector<ExperimentWalker>& walkers, const std::vector<Fold>& folds,
                      const EnginesExperimentOptions& o, EnginesExperimentResults& out) {
  CameraExperimentOptions c;
  c.camerasPerWalker = o.camerasPerWalker;
  c.noisePx = o.noisePx;
  c.sigma2Mm2 = o.sigma2Mm2;
  c.threads = o.threads;
  c.skeleton = hasEngine(o.engines, EngineKind::Skeleton);
  c.snippet = hasEngine(o.engines, EngineKind::Snippet);
  c.gait = true;
  c.keepClipsDir = o.keepClipsDir;
  const bool eigenwalker = hasEngine(o.engines, EngineKind::Eigenwalker);
  for (const CameraRow& row : cameraErrors(walkers, folds, c)) {
    if (eigenwalker)
      addCameraRow(row, "eigenwalker", "everything unknown",
                   EngineClipScore{row.error.empty() ? row.mpjpeMm : NAN, 0, row.error, row.seconds}, out);
    addCameraRow(row, "skeleton", "own bones", row.skeleton, out);
    addCameraRow(row, "skeleton", "own bones, eigenwalker's branches", row.skeletonGuided, out);
    addCameraRow(row, "skeleton", "Table 2 x stature", row.skeletonTable2, out);
    addCameraRow(row, "skeleton", "eigenwalker's bones and branches", row.skeletonEigenwalkerBones, out);
    addCameraRow(row, "snippet", "weak perspective", row.snippet, out);
    // The eigenwalker always runs (the guided skeleton variants need its fit); its gait
    // rows are reported when it was asked for.
    for (const GaitAgreementRow& g : row.gait)
      if (eigenwalker || (g.engine != kCameraEigenwalker && g.engine != kCameraEigenwalkerStatureGiven))
        out.gait.push_back(g);
  }
}

}  // namespace

EnginesExperimentResults compareEngines(const Dataset& dataset, const std::vector<Walker>& datasetWalkers,
                                        const std::vector<ExperimentWalker>& walkers, const std::vector<Fold>& folds,
                                        const EnginesExperimentOptions& options) {
  checkOptions(options);
  EnginesExperimentResults out;
  if (options.views) compareOnViews(dataset, datasetWalkers, options, out);
  if (options.cameras) compareOnCameras(walkers, folds, options, out);
  return out;
}

std::vector<EnginesSummaryRow> summarizeEngines(const std::vector<EnginesRow>& rows) {
  std::vector<EnginesSummaryRow> out;
  std::vector<std::vector<double>> errors;
  std::vector<int> frames;
  std::map<std::tuple<std::string, std::string, std::string, double>, size_t> slot;
  for (const EnginesRow& r : rows) {
    auto [it, added] = slot.emplace(std::make_tuple(r.setting, r.engine, r.variant, r.noise), out.size());
    if (added) {
      out.push_back({r.setting, r.engine, r.variant, r.noise, r.noiseUnit});
      errors.emplace_back();
      frames.push_back(0);
    }
    EnginesSummaryRow& s = out[it->second];
    ++s.clips;
    s.meanSeconds += r.seconds;  // a sum until the end
    frames[it->second] += r.frames;
    if (r.error.empty() && std::isfinite(r.mpjpeMm))
      errors[it->second].push_back(r.mpjpeMm);
    else
      ++s.failures;
  }
  for (size_t k = 0; k < out.size(); ++k) {
    EnginesSummaryRow& s = out[k];
    s.msPerFrame = frames[k] > 0 ? 1000.0 * s.meanSeconds / frames[k] : NAN;
    s.meanSeconds /= s.clips;
    const auto& e = errors[k];
    s.meanMpjpeMm = e.empty() ? NAN : std::accumulate(e.begin(), e.end(), 0.0) / static_cast<double>(e.size());
    s.medianMpjpeMm = e.empty() ? NAN : median(e);
  }
  return out;
}

}  // namespace ew
