#include "ui/app/gait_report.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "core/common/errors.h"
#include "core/common/json_number.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/walker_set.h"
#include "core/gait/joint_angles.h"
#include "core/io/atomic_write.h"
#include "ui/app/population.h"

namespace ew::ui {
namespace {

double meanOf(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x;
  return v.empty() ? NAN : sum / static_cast<double>(v.size());
}

double sdOf(const std::vector<double>& v) {
  if (v.size() < 2) return v.empty() ? NAN : 0.0;
  const double m = meanOf(v);
  double ss = 0.0;
  for (double x : v) ss += (x - m) * (x - m);
  return std::sqrt(ss / (static_cast<double>(v.size()) - 1.0));
}

const CycleCurve* curveOf(const GaitSummary& s, const std::string& name) {
  for (const auto& c : s.curves)
    if (c.name == name) return &c;
  return nullptr;
}

std::string cell(double v, int decimals = 4) {
  if (!std::isfinite(v)) return "";
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << v;
  return out.str();
}

double curveSample(const CycleCurve* c, Eigen::Index k) { return c ? c->meanDeg[k] : NAN; }
double bandSample(const Eigen::VectorXd* v, Eigen::Index k) { return v ? (*v)[k] : NAN; }
// A row of the band, NaN for a band not measured (no walkers to measure it on).
double rowOf(const std::vector<double>& v, size_t r) { return r < v.size() ? v[r] : NAN; }

}  // namespace

const std::vector<GaitRow>& gaitRows() {
  static const std::vector<GaitRow> rows = {
      {"cadence_spm", "cadence (steps/min)", 1},
      {"stride_time_s", "stride time (s)", 3},
      {"stride_length_m", "stride length (m)", 2},
      {"step_length_r_m", "step length, right (m)", 2},
      {"step_length_l_m", "step length, left (m)", 2},
      {"step_width_m", "step width (m)", 3},
      {"speed_mps", "speed (m/s)", 2},
      {"stance_pct", "stance (%)", 1},
      {"swing_pct", "swing (%)", 1},
      {"double_support_pct", "double support (%)", 1},
      {"hip_flexion_range_deg", "hip flexion range (°)", 1},
      {"knee_flexion_range_deg", "knee flexion range (°)", 1},
  };
  return rows;
}

double gaitRowValue(const GaitSummary& s, const std::string& key) {
  return s.measures ? gaitMeasureByName(*s.measures, s.curves, key) : NAN;
}

const Eigen::VectorXd* GaitBand::curveMeanOf(const std::string& name) const {
  const auto k = std::find(curveNames.begin(), curveNames.end(), name);
  return k == curveNames.end() ? nullptr : &curveMean[static_cast<size_t>(k - curveNames.begin())];
}

const Eigen::VectorXd* GaitBand::curveSdOf(const std::string& name) const {
  const auto k = std::find(curveNames.begin(), curveNames.end(), name);
  return k == curveNames.end() ? nullptr : &curveSd[static_cast<size_t>(k - curveNames.begin())];
}

namespace {

// One reference walker as the band measures it.
struct BandWalker {
  Eigen::VectorXd w;
  double strideHz = 0.0;
  std::optional<double> speedMps;
  std::string id;
};

GaitBand gaitBandOf(const std::vector<BandWalker>& walkers, std::string from) {
  GaitBand band;
  band.from = std::move(from);
  const auto& rows = gaitRows();
  std::vector<std::vector<double>> values(rows.size());
  std::vector<std::vector<Eigen::VectorXd>> curves(flexionCurveNames().size());
  for (const BandWalker& b : walkers) {
    const GaitSummary s = measureFourierWalker(b.w, b.strideHz, b.speedMps, b.id);
    if (!s.measures) {
      ++band.unmeasured;
      continue;
    }
    ++band.walkers;
    for (size_t r = 0; r < rows.size(); ++r) {
      const double v = gaitRowValue(s, rows[r].key);
      if (std::isfinite(v)) values[r].push_back(v);
    }
    for (size_t c = 0; c < curves.size(); ++c)
      if (const CycleCurve* curve = curveOf(s, flexionCurveNames()[c])) curves[c].push_back(curve->meanDeg);
  }
  for (const auto& v : values) {
    band.rowMean.push_back(meanOf(v));
    band.rowSd.push_back(sdOf(v));
  }
  for (size_t c = 0; c < curves.size(); ++c) {
    if (curves[c].empty()) continue;
    const auto n = curves[c].front().size();
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(n), sd = Eigen::VectorXd::Zero(n);
    for (const auto& v : curves[c]) mean += v;
    mean /= static_cast<double>(curves[c].size());
    for (const auto& v : curves[c]) sd += (v - mean).cwiseAbs2();
    if (curves[c].size() > 1) sd = (sd / (static_cast<double>(curves[c].size()) - 1.0)).cwiseSqrt();
    band.curveNames.push_back(flexionCurveNames()[c]);
    band.curveMean.push_back(mean);
    band.curveSd.push_back(sd);
  }
  return band;
}

}  // namespace

GaitBand populationGaitBand(const Population& population) {
  std::vector<BandWalker> walkers;
  for (int i = 0; i < population.walkerCount(); ++i) {
    const Walker& w = population.walkers[static_cast<size_t>(i)];
    const WalkerFacts& f = population.facts[static_cast<size_t>(i)];
    walkers.push_back({w.fit.w, f.strideHz, f.speedMps, w.id});
  }
  return gaitBandOf(walkers, "the " + std::to_string(walkers.size()) + " walkers of the loaded population");
}

GaitBand modelGaitBand(const EigenwalkerModel& model, const std::string& name) {
  std::vector<BandWalker> walkers;
  const std::vector<Walker> stored = storedWalkers(model, name);
  for (int r = 0; r < model.walkerCount(); ++r) {
    const Walker& w = stored[static_cast<size_t>(r)];
    walkers.push_back({w.fit.w, w.fit.omegaRadS / (2.0 * std::numbers::pi), model.speedMpsOf(r), w.id});
  }
  std::string from = "the " + std::to_string(walkers.size()) + " walkers of " + name + ", as its " +
                     std::to_string(model.componentCount()) + " eigenwalkers give them back";
  if (model.speedsMps.empty()) from += " (it records no speeds: their lengths from the stance feet)";
  return gaitBandOf(walkers, from);
}

void writeGaitReportCsv(const std::string& file, const GaitSummary& mocap, const std::vector<GaitColumn>& columns,
                        const GaitBand& band) {
  writeFileAtomically(file, [&](std::ostream& out) {
    out << "measure,motion_capture";
    for (const auto& c : columns) out << ',' << c.name;
    out << ",population_mean,population_sd\n";
    const auto& rows = gaitRows();
    for (size_t r = 0; r < rows.size(); ++r) {
      out << rows[r].key << ',' << cell(gaitRowValue(mocap, rows[r].key));
      for (const auto& c : columns) out << ',' << cell(gaitRowValue(*c.summary, rows[r].key));
      out << ',' << cell(rowOf(band.rowMean, r)) << ',' << cell(rowOf(band.rowSd, r)) << '\n';
    }
    out << "\ncurve,cycle_pct,motion_capture_deg";
    for (const auto& c : columns) out << ',' << c.name << "_deg";
    out << ",population_mean_deg,population_sd_deg\n";
    for (const auto& name : flexionCurveNames()) {
      const CycleCurve* a = curveOf(mocap, name);
      std::vector<const CycleCurve*> cols;
      const CycleCurve* any = a;
      for (const auto& c : columns) {
        cols.push_back(curveOf(*c.summary, name));
        if (!any) any = cols.back();
      }
      const Eigen::VectorXd *m = band.curveMeanOf(name), *sd = band.curveSdOf(name);
      if (!any) continue;
      const auto n = any->meanDeg.size();
      for (Eigen::Index k = 0; k < n; ++k) {
        out << name << ',' << cell(100.0 * static_cast<double>(k) / static_cast<double>(n - 1), 1) << ','
            << cell(curveSample(a, k), 3);
        for (const CycleCurve* c : cols) out << ',' << cell(curveSample(c, k), 3);
        out << ',' << cell(bandSample(m, k), 3) << ',' << cell(bandSample(sd, k), 3) << '\n';
      }
    }
  });
}

void writeGaitReportJson(const std::string& file, const GaitReportText& what, const GaitSummary& mocap,
                         const std::vector<GaitColumn>& columns, const GaitBand& band) {
  using nlohmann::json;
  json measures = json::object();
  const auto& rows = gaitRows();
  for (size_t r = 0; r < rows.size(); ++r) {
    json m = {{"motion_capture", finiteOrNull(gaitRowValue(mocap, rows[r].key))},
              {"population_mean", finiteOrNull(rowOf(band.rowMean, r))},
              {"population_sd", finiteOrNull(rowOf(band.rowSd, r))}};
    for (const auto& c : columns) m[c.name] = finiteOrNull(gaitRowValue(*c.summary, rows[r].key));
    measures[rows[r].key] = m;
  }
  json curves = json::object();
  const auto series = [](const CycleCurve* c) {
    return c ? json(std::vector<double>(c->meanDeg.data(), c->meanDeg.data() + c->meanDeg.size())) : json(nullptr);
  };
  const auto band1 = [](const Eigen::VectorXd* v) {
    return v ? json(std::vector<double>(v->data(), v->data() + v->size())) : json(nullptr);
  };
  for (const auto& name : flexionCurveNames()) {
    json c = {{"motion_capture_deg", series(curveOf(mocap, name))},
              {"population_mean_deg", band1(band.curveMeanOf(name))},
              {"population_sd_deg", band1(band.curveSdOf(name))}};
    for (const auto& col : columns) c[col.name + "_deg"] = series(curveOf(*col.summary, name));
    curves[name] = c;
  }
  const json doc = {{"walker", what.walker},
                    {"engine", what.engine},
                    {"cycle_samples", 101},
                    {"band_walkers", band.walkers},
                    {"band", band.from},
                    {"measures", measures},
                    {"curves", curves}};
  writeFileAtomically(file, [&](std::ostream& out) { out << doc.dump(2) << "\n"; });
}

}  // namespace ew::ui
