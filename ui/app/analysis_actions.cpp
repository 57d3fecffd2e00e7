// The analysis panel's curves (jobs.analysis).
#include "ui/app/analysis_actions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/eigenwalker/model.h"
#include "ui/app/actions.h"
#include "ui/app/actions_internal.h"
#include "ui/app/held_model.h"

namespace ew::ui::actions {

// [SECTION] Analysis

namespace {

AnalysisWalkers analysisWalkers(const AppState& s) {
  if (const EigenwalkerModel* model = heldModelOtherThanThePopulations(s.doc))
    return modelAnalysisWalkers(*model, heldModelPhrase(s.doc));
  if (!s.doc.population) throw std::invalid_argument("the analysis needs a loaded population or a model");
  return populationAnalysisWalkers(*s.doc.population);
}

}  // namespace

AnalysisKey analysisKey(const AppState& s) {
  return {s.doc.generation, s.doc.recon.components, s.doc.recon.sigma2Mm2,
          s.panels.analysis.showEngines || s.doc.compareEngines, heldModelOtherThanThePopulations(s.doc)};
}

std::string analysisSubject(const AppState& s) {
  const Walker* w = s.doc.selectedWalker();
  if (!w) return "";
  if (const EigenwalkerModel* model = heldModelOtherThanThePopulations(s.doc)) return subjectInModel(*model, *w);
  return s.doc.isInspected(s.doc.walker) ? std::string() : w->subject;
}

void requestAnalysis(AppState& s) {
  if ((!s.doc.population && !heldModelOtherThanThePopulations(s.doc)) || s.loading.population.running() || s.jobs.analysis.running()) return;
  const AnalysisKey key = analysisKey(s);
  s.jobs.analysis.request(
      key, "Analysis (leave-one-subject-out, −90…90°)",
      [walkers = analysisWalkers(s), key](JobProgress& progress) -> std::shared_ptr<const AnalysisResult> {
        return std::make_shared<const AnalysisResult>(computeAnalysis(
            walkers, key, [&progress](int done, int total, const std::string& what) {
              progress.set(done, total, what);
            }));
      });
}

std::shared_ptr<const AnalysisResult> analysisNow(AppState& s) {
  const AnalysisKey key = analysisKey(s);
  if (auto cached = s.jobs.analysis.find(key)) return cached;
  auto result = std::make_shared<const AnalysisResult>(computeAnalysis(analysisWalkers(s), key, {}));
  s.jobs.analysis.put(key, result);
  return result;
}

void exportAnalysisCsv(AppState& s, const std::filesystem::path& path) {
  const auto result = analysisNow(s);
  // A walker that is none of the analysed subjects has no curve of its own: the mean is written.
  const std::string subject = analysisSubject(s);
  writeAnalysisCsv(*result, subject, path);
  s.log.info("Wrote " + path.string() + " (analysis curves, " +
             (subject.empty() ? std::string("the mean") : subject + " and the mean") + ")");
}

void setAnalysisMetric(AppState& s, const std::string& name) {
  if (name == "E_a") {
    s.panels.analysis.metric = ErrorMetric::AbsMm2;
  } else if (name == "E_r") {
    s.panels.analysis.metric = ErrorMetric::Relative;
  } else if (name == "MPJPE") {
    s.panels.analysis.metric = ErrorMetric::MpjpeMm;
  } else {
    throw std::invalid_argument("metric must be \"E_a\", \"E_r\" or \"MPJPE\"");
  }
}

}  // namespace ew::ui::actions
