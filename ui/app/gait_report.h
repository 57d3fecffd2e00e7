#pragma once
// The gait report (issue 17): the spatiotemporal gait measures and flexion curves over the
// gait cycle (core/gait/gait_measures.h) of the selected walker and of its reconstruction,
// beside the loaded population's mean ± SD. GL-free; the panel draws it
// (ui/panels/gait_panel.h), the export writes it.
//
// Every walker the viewer holds is a Fourier walker (METHOD §3: two harmonics, one cycle), so
// each is measured the same way: walked in place for kReportCycles cycles at kReportRateHz,
// events from its kinematics. The motion capture's side and the population are given their
// measured progression speed; a reconstruction has none, so its speed and footprints come from
// its stance feet (docs/GAIT.md: a two-harmonic stance ankle does not stand still, and
// lengths read about 10 % long that way).

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/eigenwalker/model.h"
#include "core/gait/fourier_walker_gait.h"
#include "core/gait/gait_measures.h"

namespace ew::ui {

struct Population;

inline constexpr double kReportCycles = kWalkerGaitCycles;
inline constexpr double kReportRateHz = kWalkerGaitRateHz;

// One walker measured (measureFourierWalker): its measures and curves, or why it could not be.
using GaitSummary = FourierWalkerGait;

// The rows of the report's table, in order: a label with its unit and the value of a summary.
struct GaitRow {
  const char* key;    // "cadence_spm", … (the export's column)
  const char* label;  // "cadence (steps/min)"
  int decimals;
};
const std::vector<GaitRow>& gaitRows();
double gaitRowValue(const GaitSummary& s, const std::string& key);  // NaN when not measured

// The reference walkers' mean and SD per row and per curve sample, over the walkers measured.
struct GaitBand {
  std::string from;       // which walkers, for the caption and the export
  int walkers = 0;        // measured
  int unmeasured = 0;     // no complete stride
  std::vector<double> rowMean, rowSd;  // gaitRows() order
  std::vector<std::string> curveNames;
  std::vector<Eigen::VectorXd> curveMean, curveSd;
  const Eigen::VectorXd* curveMeanOf(const std::string& name) const;
  const Eigen::VectorXd* curveSdOf(const std::string& name) const;
};
// The loaded population's walkers, at their stride frequencies and measured speeds.
GaitBand populationGaitBand(const Population& population);
// The walkers a model was built from, each as the model gives it back (w̄ + E k_r: its N
// eigenwalkers' part, not the whole walker), at its stride frequency and, where the model
// records it (speeds_mps, docs/MODEL_FORMAT.md), its speed; without one, the walker's speed
// and lengths come from its stance feet as a reconstruction's do. `name` names the model.
GaitBand modelGaitBand(const EigenwalkerModel& model, const std::string& name);

// A reconstruction's column of the report: "reconstruction", or an engine's name in compare mode.
struct GaitColumn {
  std::string name;
  const GaitSummary* summary = nullptr;
};

// Written atomically; errors are ew::Error naming the file.
//  CSV: measure,motion_capture,<column names>,population_mean,population_sd then a blank line and
//       curve,cycle_pct,motion_capture_deg,<column names>_deg,population_mean_deg,population_sd_deg
//  JSON: {"walker", "engine", "measures": {key: {…}}, "curves": {name: {…}}, "band_walkers", "band"}
//  (the population_* columns are the band's, whichever walkers it is of: GaitBand::from)
struct GaitReportText {
  std::string walker, engine;
};
void writeGaitReportCsv(const std::string& file, const GaitSummary& mocap, const std::vector<GaitColumn>& columns,
                        const GaitBand& band);
void writeGaitReportJson(const std::string& file, const GaitReportText& what, const GaitSummary& mocap,
                         const std::vector<GaitColumn>& columns, const GaitBand& band);

}  // namespace ew::ui
