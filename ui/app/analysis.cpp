#include "ui/app/analysis.h"

#include <chrono>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <thread>

#include "core/eigenwalker/walker_set.h"
#include "core/io/atomic_write.h"

namespace ew::ui {

AnalysisWalkers populationAnalysisWalkers(const Population& population) {
  AnalysisWalkers out{{}, "the loaded population", std::nullopt};
  out.walkers.reserve(population.walkers.size());
  for (const auto& w : population.walkers) out.walkers.push_back({w.id, w.subject, w.source, w.fit, {}, 0.0});
  return out;
}

AnalysisWalkers modelAnalysisWalkers(const EigenwalkerModel& model, const std::string& name) {
  AnalysisWalkers out{{}, name + "'s walkers (their part in its " + std::to_string(model.componentCount()) +
                              " eigenwalkers)",
                      varianceTable(model)};
  for (const Walker& w : storedWalkers(model, name)) out.walkers.push_back({w.id, w.subject, w.source, w.fit, {}, 0.0});
  return out;
}

AnalysisResult computeAnalysis(const AnalysisWalkers& from, const AnalysisKey& key, const ProgressFn& progress) {
  const auto start = std::chrono::steady_clock::now();
  AnalysisResult r;
  r.key = key;
  r.from = from.from;
  const std::vector<ExperimentWalker>& walkers = from.walkers;

  EvaluationOptions options;
  for (int a = -90; a <= 90; a += 5) options.anglesDeg.push_back(a);
  if (key.components > 0) options.model.components = key.components;
  options.threads = std::max(1u, std::thread::hardware_concurrency() / 2);
  int stage = 0;
  options.progress = [&](int done, int total, const std::string& what) {
    if (progress) progress(stage * total + done, 3 * total, what);
  };
  if (progress) progress(0, 1, "building the leave-one-out folds");
  const std::vector<Fold> folds = buildFolds(walkers, options.model, options.threads);
  stage = 1;
  r.knownView = knownViewErrors(walkers, folds, options, key.sigma2Mm2);
  stage = 2;
  r.sigmaSweep = sigmaSweep(walkers, folds, options);
  r.spectrum = from.spectrum ? *from.spectrum : varianceTable(buildFullModel(walkers, options.model));
  if (key.engines) {
    // Every 15° (the eigenwalker's curves every 5°) and a prior from 2 cycles per walker: a
    // prior per fold makes these the slow part (about 0.2 s a fold on one core).
    EngineViewOptions engines;
    for (int a = -90; a <= 90; a += 15) engines.anglesDeg.push_back(a);
    engines.priorCycles = 2.0;
    engines.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));  // opt-in, slow
    r.engines = engineViewErrors(walkers, engines, [&](int done, int total, const std::string&) {
      if (progress) progress(done, total, "snippet and skeleton engines");
    });
  }
  r.anglesDeg = options.anglesDeg;
  r.subjects = walkerSubjects(walkers);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

namespace {

double metricValue(const ViewErrorRow& row, ErrorMetric m) {
  switch (m) {
    case ErrorMetric::AbsMm2: return row.absErrorMm2;
    case ErrorMetric::Relative: return row.relError;
    case ErrorMetric::MpjpeMm: return row.mpjpeMm;
  }
  return 0.0;
}

}  // namespace

namespace {

// The mean of value(row) over the rows `take` keeps, at each of the result's angles (NaN
// where none fell).
template <class Rows, class Take, class Value>
std::vector<double> meanAtAngles(const AnalysisResult& result, const Rows& rows, const Take& take, const Value& value) {
  const std::size_t n = result.anglesDeg.size();
  std::vector<double> sum(n, 0.0);
  std::vector<int> count(n, 0);
  for (const auto& row : rows) {
    if (!take(row)) continue;
    for (std::size_t i = 0; i < n; ++i) {
      if (std::abs(result.anglesDeg[i] - row.angleDeg) < 1e-9) {
        sum[i] += value(row);
        ++count[i];
        break;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) sum[i] = count[i] > 0 ? sum[i] / count[i] : std::nan("");
  return sum;
}

}  // namespace

std::vector<double> errorCurve(const AnalysisResult& result, const std::string& subject, const std::string& method,
                               ErrorMetric metric) {
  return meanAtAngles(
      result, result.knownView,
      [&](const ViewErrorRow& row) { return row.method == method && (subject.empty() || row.subject == subject); },
      [&](const ViewErrorRow& row) { return metricValue(row, metric); });
}

std::vector<double> engineErrorCurve(const AnalysisResult& result, const std::string& subject, EngineKind engine,
                                     ErrorMetric metric) {
  return meanAtAngles(
      result, result.engines,
      [&](const EngineViewRow& row) {
        return row.engine == engine && (subject.empty() || row.subject == subject) && row.error.empty();
      },
      [&](const EngineViewRow& row) {
        return metric == ErrorMetric::MpjpeMm ? row.mpjpeMm
               : metric == ErrorMetric::AbsMm2 ? row.depthErrorMm2
                                               : std::nan("");
      });
}

const char* metricName(ErrorMetric metric) {
  switch (metric) {
    case ErrorMetric::AbsMm2: return "E_a";
    case ErrorMetric::Relative: return "E_r";
    case ErrorMetric::MpjpeMm: return "MPJPE";
  }
  return "";
}

const char* metricUnit(ErrorMetric metric) {
  switch (metric) {
    case ErrorMetric::AbsMm2: return "mm²";
    case ErrorMetric::Relative: return "";
    case ErrorMetric::MpjpeMm: return "mm";
  }
  return "";
}

void writeAnalysisCsv(const AnalysisResult& result, const std::string& subject, const std::filesystem::path& file) {
  struct Column {
    std::string name;
    std::vector<double> values;
  };
  std::vector<Column> columns;
  const ErrorMetric metrics[] = {ErrorMetric::AbsMm2, ErrorMetric::Relative, ErrorMetric::MpjpeMm};
  const char* metricKeys[] = {"abs_error_mm2", "rel_error", "mpjpe_mm"};
  for (const std::string method : {"lsq", "map"}) {
    for (int m = 0; m < 3; ++m) {
      if (!subject.empty())
        columns.push_back({subject + "_" + method + "_" + metricKeys[m], errorCurve(result, subject, method, metrics[m])});
      columns.push_back({"mean_" + method + "_" + metricKeys[m], errorCurve(result, "", method, metrics[m])});
    }
  }
  for (EngineKind engine : {EngineKind::Snippet, EngineKind::Skeleton}) {
    if (result.engines.empty()) break;
    const std::string name = engineName(engine);
    for (int m : {0, 2}) {
      if (!subject.empty())
        columns.push_back({subject + "_" + name + "_" + metricKeys[m], engineErrorCurve(result, subject, engine, metrics[m])});
      columns.push_back({"mean_" + name + "_" + metricKeys[m], engineErrorCurve(result, "", engine, metrics[m])});
    }
  }
  writeFileAtomically(file, [&](std::ostream& out) {
    out << std::setprecision(10);
    out << "# eigenwalker analysis: error against view angle (leave-one-subject-out), sigma2_mm2="
        << result.key.sigma2Mm2 << ", components=" << result.key.components << " (0 = 95 %)\n";
    out << "angle_deg";
    for (const auto& c : columns) out << ',' << c.name;
    out << '\n';
    for (std::size_t i = 0; i < result.anglesDeg.size(); ++i) {
      out << result.anglesDeg[i];
      for (const auto& c : columns) out << ',' << c.values[i];
      out << '\n';
    }
    out << "\nsigma2_mm2,method,mean_abs_error_mm2,mean_rel_error,mpjpe_mm\n";
    for (const auto& row : result.sigmaSweep)
      out << row.sigma2Mm2 << ',' << row.method << ',' << row.meanAbsErrorMm2 << ',' << row.meanRelError << ','
          << row.mpjpeMm << '\n';
    out << "\ncomponent,eigenvalue_mm2,variance_share,cumulative_share\n";
    for (const auto& row : result.spectrum)
      out << row.component << ',' << row.eigenvalueMm2 << ',' << row.varianceShare << ',' << row.cumulativeShare << '\n';
  });
}

}  // namespace ew::ui
