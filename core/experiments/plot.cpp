#include "core/experiments/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <map>
#include <sstream>

#include "core/common/errors.h"
#include "core/eigenwalker/projection.h"

namespace ew {

// [SECTION] Evaluation figures (data → series); independent of the raster back end

namespace {

constexpr Rgb kLsqColor{31, 119, 180};   // blue
constexpr Rgb kMapColor{214, 39, 40};    // red
constexpr Rgb kGrey{90, 90, 90};

Rgb methodColor(const std::string& m) { return m == "map" ? kMapColor : kLsqColor; }
std::string methodLabel(const std::string& m) { return m == "map" ? "MAP (approach II)" : "LSQ (approach I)"; }

struct MeanSd {
  double sum = 0, sumSq = 0;
  int n = 0;
  void add(double v) { sum += v; sumSq += v * v; ++n; }
  double mean() const { return n ? sum / n : 0.0; }
  double sd() const { return n > 1 ? std::sqrt(std::max(0.0, (sumSq - sum * sum / n) / (n - 1))) : 0.0; }
};

// Mean over subjects per (method, angle) of one column of the view-error rows.
template <class Row, class Value>
std::map<std::string, std::map<double, MeanSd>> byMethodAngle(const std::vector<Row>& rows, Value value,
                                                              double Row::*angle) {
  std::map<std::string, std::map<double, MeanSd>> out;
  for (const Row& r : rows) out[r.method][r.*angle].add(value(r));
  return out;
}

PlotSeries seriesOf(const std::string& method, const std::map<double, MeanSd>& cells, bool withSd) {
  PlotSeries s{methodLabel(method), {}, {}, {}, methodColor(method), false, false};
  for (const auto& [x, c] : cells) {
    s.x.push_back(x);
    s.y.push_back(c.mean());
    if (withSd) s.spread.push_back(c.sd());
  }
  return s;
}

std::string fmt(double v, int decimals = 0) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(decimals);
  s << v;
  return s.str();
}

LinePlot varianceFigure(const EvaluationResults& r) {
  LinePlot p{"Fig. 2: cumulative variance of the eigenwalkers (" + std::to_string(r.walkers) + " walkers)",
             "number of eigenwalkers", "cumulative share of variance (%)", {}, false, 0.0, {}, 0.0, 100.0, {}, {}};
  PlotSeries s{"cumulative variance", {}, {}, {}, kLsqColor, false, true};
  s.x.push_back(0);
  s.y.push_back(0);
  for (const auto& v : r.variance) {
    s.x.push_back(v.component);
    s.y.push_back(100.0 * v.cumulativeShare);
  }
  p.xMax = s.x.back();
  p.series.push_back(s);
  p.series.push_back({"95 %", {0, s.x.back()}, {95, 95}, {}, kGrey, true, false});
  p.notes.push_back("95 % reached with " + std::to_string(r.components95) + " eigenwalkers");
  return p;
}

LinePlot sigmaFigure(const EvaluationResults& r) {
  LinePlot p{"Fig. 3: reconstruction error vs sigma^2 (leave-one-subject-out, all angles)",
             "sigma^2 (mm^2, log scale)", "mean E_a of the depth (mm^2)", {}, true, {}, {}, 0.0, {}, {}, {}};
  std::map<std::string, PlotSeries> by;
  for (const auto& row : r.sigmaSweep) {
    auto& s = by.try_emplace(row.method, PlotSeries{methodLabel(row.method), {}, {}, {}, methodColor(row.method),
                                                    row.method == "lsq", row.method == "map"})
                  .first->second;
    s.x.push_back(row.sigma2Mm2);
    s.y.push_back(row.meanAbsErrorMm2);
  }
  for (auto& [m, s] : by) p.series.push_back(s);
  if (r.sigma2OptMm2) {
    p.notes.push_back("optimum sigma^2 = " + fmt(*r.sigma2OptMm2) + " mm^2" +
                      (r.sigma2OptAtGridEdge ? " (at the grid's edge!)" : ""));
  }
  return p;
}

LinePlot knownViewFigure(const EvaluationResults& r, int panel) {
  static const char* titles[] = {"Fig. 5a: absolute depth error E_a vs view angle",
                                 "Fig. 5b: relative depth error E_r vs view angle",
                                 "Fig. 5c: variance of the missing (depth) dimension"};
  static const char* yLabels[] = {"E_a (mm^2)", "E_r (E_a / variance of depth)", "variance of depth (mm^2)"};
  LinePlot p{titles[panel], "view angle (deg; 0 = frontal, +-90 = profile)", yLabels[panel], {}, false,
             {}, {}, 0.0, {}, 30.0, {}};
  const auto cells = byMethodAngle(
      r.knownView,
      [panel](const ViewErrorRow& row) {
        return panel == 0 ? row.absErrorMm2 : panel == 1 ? row.relError : row.varMissingMm2;
      },
      &ViewErrorRow::angleDeg);
  for (const auto& [m, c] : cells) {
    if (panel == 2 && m != cells.begin()->first) continue;  // the same for every method
    PlotSeries s = seriesOf(m, c, false);
    if (panel == 2) {
      s.label = "mean over subjects";
      s.color = kGrey;
    }
    p.series.push_back(s);
  }
  p.notes.push_back("MAP sigma^2 = " + fmt(r.sigma2UsedMm2) + " mm^2; mean over " + std::to_string(r.subjects) +
                    " held-out subjects");
  return p;
}

LinePlot unknownViewFigure(const EvaluationResults& r) {
  LinePlot p{"Fig. 6: estimated vs true view angle (mean +- SD over subjects)", "true view angle (deg)",
             "estimated view angle (deg)", {}, false, {}, {}, {}, {}, 30.0, {}};
  // α̂ unwrapped next to α, so a mean over subjects is meaningful.
  std::map<std::string, std::map<double, MeanSd>> cells;
  double lo = 1e300, hi = -1e300;
  for (const auto& row : r.unknownView) {
    cells[row.method][row.trueAngleDeg].add(row.trueAngleDeg + wrapDeg(row.estAngleDeg - row.trueAngleDeg));
    lo = std::min(lo, row.trueAngleDeg);
    hi = std::max(hi, row.trueAngleDeg);
  }
  p.series.push_back({"ideal", {lo, hi}, {lo, hi}, {}, kGrey, true, false});
  for (const auto& [m, c] : cells) {
    p.series.push_back(seriesOf(m, c, true));
    MeanSd err;
    for (const auto& row : r.unknownView) {
      if (row.method == m) err.add(row.angleErrorDeg);
    }
    p.notes.push_back(m + ": mean |error| " + fmt(err.mean(), 2) + " deg");
  }
  p.yMin = lo - 30;
  p.yMax = hi + 30;
  return p;
}

LinePlot noiseFigure(const EvaluationResults& r) {
  LinePlot p{"2D noise before the Fourier fit: depth error vs noise", "noise SD per image coordinate (mm)",
             "mean E_a (mm^2)", {}, false, {}, {}, 0.0, {}, {}, {}};
  std::map<std::string, std::map<double, MeanSd>> cells;
  for (const auto& row : r.noise) {
    // The condition is the noise level as text; one that is not a number has no x.
    char* end = nullptr;
    const double level = std::strtod(row.condition.c_str(), &end);
    if (row.condition.empty() || end != row.condition.c_str() + row.condition.size()) continue;
    cells[row.method][level].add(row.absErrorMm2);
  }
  for (const auto& [m, c] : cells) {
    PlotSeries s = seriesOf(m, c, false);
    s.markers = true;
    p.series.push_back(s);
  }
  p.notes.push_back("known view, all angles, MAP sigma^2 = " + fmt(r.sigma2UsedMm2) + " mm^2");
  return p;
}

BarPlot missingFigure(const EvaluationResults& r) {
  BarPlot p{"Missing 2D joints (known view, all angles): mean E_a", "mean E_a of the depth (mm^2)", {}, {}, {}, {}, {}};
  std::map<std::string, std::map<std::string, MeanSd>> cells;
  std::vector<std::string> order;
  for (const auto& row : r.missingJoints) {
    if (std::find(order.begin(), order.end(), row.condition) == order.end()) order.push_back(row.condition);
    cells[row.method][row.condition].add(row.absErrorMm2);
  }
  for (const auto& [m, c] : cells) {
    p.seriesLabels.push_back(methodLabel(m));
    p.seriesColors.push_back(methodColor(m));
  }
  for (const auto& cond : order) {
    BarGroup g{cond, {}};
    for (auto& [m, c] : cells) g.values.push_back(c[cond].mean());
    p.groups.push_back(g);
  }
  MeanSd none;
  for (const auto& row : r.knownView) {
    if (row.method == "map") none.add(row.absErrorMm2);
  }
  if (none.n) {
    p.referenceValue = none.mean();
    p.referenceLabel = "MAP, no joint missing";
  }
  return p;
}

// Lower-body input: MPJPE of each estimated joint per method, the mean walker as baseline.
BarPlot lowerBodyFigure(const EvaluationResults& r) {
  BarPlot p{"Lower body measured, upper body from the model: MPJPE of the estimated joints",
            "MPJPE over one cycle (mm)", {}, {}, {}, {}, {}};
  const auto summary = summarizeLowerBody(r.lowerBody);
  std::vector<std::string> methods, joints;
  for (const auto& s : summary) {
    if (std::find(methods.begin(), methods.end(), s.method) == methods.end()) methods.push_back(s.method);
    if (std::find(joints.begin(), joints.end(), s.joint) == joints.end()) joints.push_back(s.joint);
  }
  for (const auto& m : methods) {
    p.seriesLabels.push_back(m == "mean" ? "mean walker (baseline)" : methodLabel(m));
    p.seriesColors.push_back(m == "mean" ? Rgb{150, 150, 150} : methodColor(m));
  }
  for (const auto& j : joints) {
    BarGroup g{j, {}};
    for (const auto& m : methods) {
      double v = 0.0;
      for (const auto& s : summary) {
        if (s.method == m && s.joint == j) v = s.meanMpjpeMm;
      }
      g.values.push_back(v);
    }
    p.groups.push_back(g);
  }
  return p;
}

// The camera experiment: for each noise level, the share of clips reconstructed within a
// given MPJPE (a failure never counts as within), so the whole distribution and the
// failures show in one figure.
LinePlot cameraFigure(const EvaluationResults& r) {
  LinePlot p{"Keypoints through an unknown camera: clips within a given MPJPE", "MPJPE (mm, mean translation removed)",
             "share of clips (%)", {}, false, 0.0, {}, 0.0, 100.0, {}, {}};
  std::map<double, std::vector<double>> byNoise;
  std::map<double, int> clips;
  for (const auto& row : r.camera) {
    ++clips[row.noisePx];
    if (row.error.empty()) byNoise[row.noisePx].push_back(row.mpjpeMm);
  }
  const std::array<Rgb, 4> colors{Rgb{40, 110, 200}, Rgb{220, 120, 30}, Rgb{190, 40, 90}, Rgb{60, 150, 80}};
  std::size_t k = 0;
  for (auto& [noise, values] : byNoise) {
    std::sort(values.begin(), values.end());
    PlotSeries s{fmt(noise) + " px noise", {}, {}, {}, colors[k++ % colors.size()], false, false};
    for (std::size_t i = 0; i < values.size(); ++i) {
      s.x.push_back(values[i]);
      s.y.push_back(100.0 * static_cast<double>(i + 1) / clips[noise]);
    }
    p.series.push_back(s);
  }
  for (const auto& c : summarizeCamera(r.camera))
    p.notes.push_back(fmt(c.noisePx) + " px: mean " + fmt(c.meanMpjpeMm, 1) + " mm, " + std::to_string(c.failures) +
                      " of " + std::to_string(c.clips) + " failed");
  return p;
}

// The engines' colours: one per engine, the same in every figure.
Rgb engineColor(const std::string& engine) {
  if (engine.rfind("eigenwalker", 0) == 0) return Rgb{31, 119, 180};
  if (engine.rfind("snippet", 0) == 0) return Rgb{214, 39, 40};
  return Rgb{44, 160, 44};
}

// Bland-Altman plot of one gait measure: per engine, each walker and view a point (mean of the
// two measurements, reconstruction − motion capture), the bias as a solid line and the 95 %
// limits of agreement as dashed lines.
LinePlot blandAltmanFigure(const std::vector<GaitAgreementRow>& rows, const std::string& measure,
                           const std::string& title, const std::string& unit) {
  LinePlot p{title, "mean of motion capture and reconstruction (" + unit + ")",
             "reconstruction - motion capture (" + unit + ")", {}, false, {}, {}, {}, {}, {}, {}};
  std::map<std::string, PlotSeries> points;
  std::vector<std::string> order;
  double lo = INFINITY, hi = -INFINITY, yLo = 0.0, yHi = 0.0;
  for (const auto& r : rows) {
    if (r.measure != measure || !std::isfinite(r.mocap) || !std::isfinite(r.reconstructed)) continue;
    if (!points.count(r.engine)) {
      order.push_back(r.engine);
      points[r.engine] = PlotSeries{r.engine, {}, {}, {}, engineColor(r.engine), false, true, false};
    }
    const double mean = 0.5 * (r.mocap + r.reconstructed), diff = r.reconstructed - r.mocap;
    points[r.engine].x.push_back(mean);
    points[r.engine].y.push_back(diff);
    lo = std::min(lo, mean), hi = std::max(hi, mean), yLo = std::min(yLo, diff), yHi = std::max(yHi, diff);
  }
  if (order.empty()) return p;
  std::vector<GaitAgreementRow> pooled;
  for (const auto& r : rows) {
    if (r.measure != measure) continue;
    GaitAgreementRow any = r;
    any.angleDeg = 0.0;  // one bias and one pair of limits per engine, over every view
    pooled.push_back(any);
  }
  for (const auto& engine : order) {
    const PlotSeries& pts = points[engine];
    p.series.push_back(pts);
    for (const auto& b : blandAltman(pooled)) {
      if (b.engine != engine || b.pairs == 0) continue;
      for (double y : {b.bias, b.loaLow, b.loaHigh}) {
        p.series.push_back(PlotSeries{"", {lo, hi}, {y, y}, {}, pts.color, y != b.bias, false, true});
        yLo = std::min(yLo, y), yHi = std::max(yHi, y);
      }
      p.notes.push_back(engine + ": bias " + fmt(b.bias, 3) + ", limits " + fmt(b.loaLow, 3) + " to " +
                        fmt(b.loaHigh, 3) + " (" + std::to_string(b.pairs) + " pairs)");
    }
  }
  const double pad = 0.08 * std::max(1e-9, yHi - yLo);
  p.yMin = yLo - pad;
  p.yMax = yHi + pad;
  const double xPad = 0.05 * std::max(1e-9, hi - lo);
  p.xMin = lo - xPad;
  p.xMax = hi + xPad;
  return p;
}

// [SECTION] Experiment "engines"

// Mean MPJPE against the view, one line per engine without noise and one (dashed) at the
// highest noise level (the levels between are in engines_summary.csv).
LinePlot enginesViewFigure(const std::vector<EnginesRow>& rows) {
  LinePlot p{"Three engines, known orthographic view: error against view", "view angle (deg)",
             "mean MPJPE (mm, mean translation removed)", {}, false, {}, {}, 0.0, {}, 30.0, {}};
  double lowest = INFINITY, highest = -INFINITY;
  for (const auto& r : rows)
    if (r.setting == "view") lowest = std::min(lowest, r.noise), highest = std::max(highest, r.noise);
  std::map<std::pair<std::string, double>, std::map<double, std::pair<double, int>>> cells;  // (engine, noise) → angle
  std::vector<std::pair<std::string, double>> order;
  for (const auto& r : rows) {
    if (r.setting != "view" || !std::isfinite(r.mpjpeMm) || (r.noise != lowest && r.noise != highest)) continue;
    const auto key = std::make_pair(r.engine, r.noise);
    if (!cells.count(key)) order.push_back(key);
    auto& c = cells[key][r.angleDeg];
    c.first += r.mpjpeMm;
    ++c.second;
  }
  std::sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
  double top = 0.0;
  for (const auto& key : order) {
    PlotSeries s{key.first + ", " + fmt(key.second) + " mm noise", {}, {}, {}, engineColor(key.first),
                 key.second > lowest, true};
    for (const auto& [angle, c] : cells[key]) {
      s.x.push_back(angle);
      s.y.push_back(c.first / c.second);
      top = std::max(top, s.y.back());
    }
    p.series.push_back(s);
  }
  p.yMax = 1.7 * top;  // the legend above the lines
  p.notes.push_back("each held-out walker's first trial, 30 Hz; the same noise for every engine");
  return p;
}

// The bar group labelled `label`, added (with `values` NaN: no bar) when new.
BarGroup& groupNamed(BarPlot& p, const std::string& label, std::size_t values) {
  for (auto& g : p.groups)
    if (g.label == label) return g;
  p.groups.push_back({label, std::vector<double>(values, NAN)});
  return p.groups.back();
}

// Mean MPJPE of every engine and variant per noise level, through the random cameras.
BarPlot enginesCameraFigure(const std::vector<EnginesSummaryRow>& summary) {
  BarPlot p{"Three engines through random pinhole cameras", "mean MPJPE (mm, mean translation removed)", {}, {}, {},
            {}, ""};
  std::vector<double> levels;
  for (const auto& e : summary)
    if (e.setting == "camera" && std::find(levels.begin(), levels.end(), e.noise) == levels.end())
      levels.push_back(e.noise);
  const std::array<Rgb, 4> shades{Rgb{120, 170, 220}, Rgb{40, 110, 200}, Rgb{20, 50, 120}, Rgb{10, 20, 60}};
  for (std::size_t l = 0; l < levels.size(); ++l) {
    p.seriesLabels.push_back(fmt(levels[l]) + " px noise");
    p.seriesColors.push_back(shades[std::min(l, shades.size() - 1)]);
  }
  for (const auto& e : summary) {
    if (e.setting != "camera") continue;
    groupNamed(p, e.engine + ", " + e.variant, levels.size())
        .values[static_cast<std::size_t>(std::find(levels.begin(), levels.end(), e.noise) - levels.begin())] =
        e.meanMpjpeMm;
  }
  return p;
}

// Time per frame of every engine and variant at the lowest noise level, per setting.
BarPlot enginesTimeFigure(const std::vector<EnginesSummaryRow>& summary) {
  BarPlot p{"Three engines: time per frame (noise-free clips)", "ms per frame (wall, one thread per clip)",
            {"known view", "random camera"}, {Rgb{90, 90, 90}, Rgb{40, 110, 200}}, {}, {}, ""};
  for (const auto& e : summary)
    if (e.noise == 0.0) groupNamed(p, e.engine + ", " + e.variant, 2).values[e.setting == "view" ? 0 : 1] = e.msPerFrame;
  return p;
}

// The gait rows of one setting and noise level, of the engines named (empty: all).
std::vector<GaitAgreementRow> gaitRowsOf(const std::vector<GaitAgreementRow>& rows, const std::string& setting,
                                         double noise, const std::vector<std::string>& engines) {
  std::vector<GaitAgreementRow> out;
  for (const auto& r : rows)
    if (r.setting == setting && r.noise == noise &&
        (engines.empty() || std::find(engines.begin(), engines.end(), r.engine) != engines.end()))
      out.push_back(r);
  return out;
}

}  // namespace

// [SECTION] Experiment "semantic"

// Leave-one-subject-out quality of each axis: R² (numeric) or accuracy beside chance (two classes).
BarPlot semanticAxesFigure(const SemanticExperimentResults& r) {
  BarPlot p{"Semantic axes: each attribute predicted from the walker, leave one subject out",
            "R2 (numeric) or accuracy (two classes)", {"R2 / accuracy", "chance (two classes)"},
            {Rgb{40, 110, 200}, Rgb{190, 190, 190}}, {}, 1.0, "perfect"};
  for (const auto& a : r.axes) {
    const double value = a.categorical ? a.looAccuracy : std::max(a.looR2, -0.2);
    p.groups.push_back({a.attribute, {value, a.categorical ? a.chance : NAN}});
  }
  return p;
}

// RMSE of each numeric attribute predicted from one known view, over its SD, against the view.
LinePlot semanticViewsFigure(const SemanticExperimentResults& r) {
  LinePlot p{"Attributes predicted from one 2D view (known view, MAP)", "view angle (deg)",
             "RMSE / SD of the attribute (1 = guessing the mean)", {}, false, {}, {}, 0.0, {}, 15.0, {}};
  const std::array<Rgb, 8> colors{Rgb{31, 119, 180}, Rgb{255, 127, 14}, Rgb{44, 160, 44}, Rgb{214, 39, 40},
                                  Rgb{148, 103, 189}, Rgb{140, 86, 75}, Rgb{227, 119, 194}, Rgb{127, 127, 127}};
  std::vector<std::string> order;
  for (const auto& s : r.viewSummary)
    if (!s.categorical && s.view == "known" && std::find(order.begin(), order.end(), s.attribute) == order.end())
      order.push_back(s.attribute);
  double top = 1.0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    PlotSeries line{order[i], {}, {}, {}, colors[i % colors.size()], i >= colors.size(), true};
    for (const auto& s : r.viewSummary) {
      if (s.attribute != order[i] || s.view != "known" || !(s.sd > 0)) continue;
      line.x.push_back(s.angleDeg);
      line.y.push_back(s.rmse2d / s.sd);
      top = std::max(top, line.y.back());
    }
    p.series.push_back(line);
  }
  p.yMax = 1.6 * top;  // the legend above the lines
  p.notes.push_back("each held-out walker's own Fourier walker, model refitted without its subject");
  return p;
}

namespace {

void writeEnginesPlots(const std::filesystem::path& dir, const EnginesExperimentResults& r, const PlotWriter& writer,
                       std::vector<std::string>& names) {
  const auto bar = [&](const std::string& name, const BarPlot& p) {
    if (p.groups.empty()) return;
    writer.bar(dir / name, p);
    names.push_back(name);
  };
  const std::vector<EnginesSummaryRow> summary = summarizeEngines(r.rows);
  if (std::any_of(r.rows.begin(), r.rows.end(), [](const EnginesRow& e) { return e.setting == "view"; })) {
    writer.line(dir / "engines_views.png", enginesViewFigure(r.rows));
    names.push_back("engines_views.png");
  }
  bar("engines_cameras.png", enginesCameraFigure(summary));
  bar("engines_time.png", enginesTimeFigure(summary));
  // Stride length's agreement: the noise-free views, and the cameras at 2 px (the camera
  // experiment's headline level), for the engines' main variants.
  const auto gait = [&](const std::string& name, const std::vector<GaitAgreementRow>& rows, const std::string& title) {
    if (rows.empty()) return;
    writer.line(dir / name, blandAltmanFigure(rows, "stride_length", title, "m"));
    names.push_back(name);
  };
  gait("engines_gait_stride_length_views.png", gaitRowsOf(r.gait, "view", 0.0, {}),
       "Stride length, known orthographic views (all pooled): Bland-Altman");
  gait("engines_gait_stride_length_cameras.png",
       gaitRowsOf(r.gait, "camera", 2.0, {kCameraEigenwalker, kCameraSkeletonGuided, kCameraSnippet}),
       "Stride length, random cameras, 2 px: Bland-Altman");
}

}  // namespace

std::vector<std::string> writeEvaluationPlots(const std::filesystem::path& dir, const EvaluationResults& r,
                                              const PlotWriter& writer) {
  std::vector<std::string> names;
  if (!writer) return names;
  const auto line = [&](const std::string& name, const LinePlot& p) {
    writer.line(dir / name, p);
    names.push_back(name);
  };
  if (r.ran.count(Experiment::Variance) && !r.variance.empty()) line("fig2_cumulative_variance.png", varianceFigure(r));
  if (r.ran.count(Experiment::SigmaSweep) && !r.sigmaSweep.empty()) line("fig3_sigma_sweep.png", sigmaFigure(r));
  if (r.ran.count(Experiment::KnownView) && !r.knownView.empty()) {
    line("fig5a_abs_error.png", knownViewFigure(r, 0));
    line("fig5b_rel_error.png", knownViewFigure(r, 1));
    line("fig5c_var_missing.png", knownViewFigure(r, 2));
  }
  if (r.ran.count(Experiment::UnknownView) && !r.unknownView.empty()) line("fig6_view_angle.png", unknownViewFigure(r));
  if (r.ran.count(Experiment::Noise) && !r.noise.empty()) line("noise.png", noiseFigure(r));
  if (r.ran.count(Experiment::MissingJoints) && !r.missingJoints.empty()) {
    writer.bar(dir / "missing_joints.png", missingFigure(r));
    names.push_back("missing_joints.png");
  }
  if (r.ran.count(Experiment::Camera) && !r.camera.empty()) line("camera.png", cameraFigure(r));
  if (r.ran.count(Experiment::Snippet) && !r.snippet.gait.empty()) {
    line("gait_bland_altman_stride_length.png",
         blandAltmanFigure(r.snippet.gait, "stride_length", "Stride length from one view: Bland-Altman", "m"));
    line("gait_bland_altman_knee_flexion_range.png",
         blandAltmanFigure(r.snippet.gait, "knee_flexion_range", "Knee flexion range from one view: Bland-Altman", "deg"));
  }
  if (r.ran.count(Experiment::LowerBody) && !r.lowerBody.empty()) {
    writer.bar(dir / "lower_body.png", lowerBodyFigure(r));
    names.push_back("lower_body.png");
  }
  if (r.ran.count(Experiment::Engines) && !r.engines.rows.empty()) writeEnginesPlots(dir, r.engines, writer, names);
  if (r.ran.count(Experiment::Semantic) && !r.semantic.axes.empty()) {
    writer.bar(dir / "semantic_axes.png", semanticAxesFigure(r.semantic));
    names.push_back("semantic_axes.png");
    if (!r.semantic.viewSummary.empty()) line("semantic_views.png", semanticViewsFigure(r.semantic));
  }
  return names;
}

}  // namespace ew
