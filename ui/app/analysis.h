#pragma once
// The analysis panel's data (docs/VIEWER.md "Analysis"): reconstruction error against the
// view angle for every held-out subject (core's leave-one-subject-out evaluation,
// core/experiments/experiments.h), the MAP σ² sweep and the eigenvalue spectrum. Computed
// on a worker thread, cached by AnalysisKey; curves are picked out of the rows here.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/experiments/engine_view_curves.h"
#include "core/eigenwalker/model.h"
#include "core/experiments/experiments.h"
#include "ui/app/population.h"

namespace ew::ui {

enum class ErrorMetric { AbsMm2, Relative, MpjpeMm };  // E_a (mm²), E_r, MPJPE (mm)

// What the curves depend on (the view angle α and the selected subject do not: the curves
// cover every angle and every subject).
struct AnalysisKey {
  std::uint64_t generation = 0;
  int components = 0;   // N; 0 = 95 % per fold
  double sigma2Mm2 = 70.0;
  bool engines = false;  // the snippet and skeleton engines' curves too (engine_view_curves.h)
  // Whose walkers: the loaded population (null), or the held model's (that model).
  const EigenwalkerModel* model = nullptr;
  bool operator==(const AnalysisKey&) const = default;
};

// The walkers the analysis holds out in turn: those of the model walkers are reconstructed
// against (held_model.h), named for the panel's caption.
struct AnalysisWalkers {
  std::vector<ExperimentWalker> walkers;
  std::string from;  // "the loaded population", "the default model's walkers (as it stores them)"
  // A model's own spectrum (every eigenvalue it measured on its whole walkers), where the
  // walkers are its stored ones: theirs would end at its N components.
  std::optional<std::vector<VarianceRow>> spectrum;
};
// The loaded population's walkers (exact).
AnalysisWalkers populationAnalysisWalkers(const Population& population);
// A model's walkers as it stores them (storedWalkerVectors: its eigenwalkers' part of each).
AnalysisWalkers modelAnalysisWalkers(const EigenwalkerModel& model, const std::string& name);

struct AnalysisResult {
  AnalysisKey key;
  std::string from;                        // AnalysisWalkers::from
  std::vector<double> anglesDeg;           // −90 … 90 step 5
  std::vector<std::string> subjects;       // held out, first-seen order
  std::vector<ViewErrorRow> knownView;     // subject × angle × {lsq, map}
  std::vector<SigmaSweepRow> sigmaSweep;   // σ² grid × {lsq, map}, mean over subjects and angles
  std::vector<VarianceRow> spectrum;       // model of every walker
  std::vector<EngineViewRow> engines;      // key.engines: snippet and skeleton × subject × every 15°
  double seconds = 0.0;                    // wall time of the computation
};

// Runs the evaluation; progress(done, total, what). Throws on failure.
AnalysisResult computeAnalysis(const AnalysisWalkers& walkers, const AnalysisKey& key, const ProgressFn& progress);

// The error at each of result.anglesDeg for `method` ("lsq" or "map"), for one subject,
// or (subject empty) the mean over the held-out subjects.
std::vector<double> errorCurve(const AnalysisResult& result, const std::string& subject, const std::string& method,
                               ErrorMetric metric);
// The same for another engine's rows (snippet or skeleton): MPJPE and E_a; E_r is the
// eigenwalker's alone (NaN), as is a curve the result does not hold and an angle between
// the engines' 15° steps.
std::vector<double> engineErrorCurve(const AnalysisResult& result, const std::string& subject, EngineKind engine,
                                     ErrorMetric metric);
const char* metricName(ErrorMetric metric);  // "E_a", "E_r", "MPJPE"
const char* metricUnit(ErrorMetric metric);  // "mm²", "", "mm"

// The curves as CSV (atomic write): angle_deg, then one column per curve (subject and
// mean, LSQ and MAP, every metric; then the snippet and skeleton engines' MPJPE and E_a when
// computed); then the σ² sweep and the spectrum as further blocks
// separated by a blank line. Throws Error(Io) on a write failure.
void writeAnalysisCsv(const AnalysisResult& result, const std::string& subject, const std::filesystem::path& file);

}  // namespace ew::ui
