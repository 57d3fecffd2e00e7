#pragma once
// How good are gait measures from one view? For a held-out walker seen at one angle, the
// gait measures (core/gait/gait_measures.h) of an engine's reconstruction beside those of the
// motion capture it was made from, and their agreement over walkers as clinical validation
// studies report it (Bland & Altman 1986, Lancet 327:307): the bias (mean difference,
// reconstruction − motion capture) and the 95 % limits of agreement (bias ± 1.96 SD of the
// differences).
//
// Both sides are measured the same way — events from the kinematics of their own frames, speed
// and footprints from the walk over the floor where it is known (the motion capture's
// progression; a camera fit's), else from the stance feet (a reconstruction seen in place, a
// two-harmonic walker's calibrated: core/gait/fourier_walker_gait.h) — so a difference is what
// the reconstruction changed, not a difference of methods (those are compared apart: the
// kinematic events against the C3D's, and the stance feet's speed against the progression,
// docs/GAIT.md).

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace ew {

// The measures compared, with their units: cadence (steps/min), stride_length (m), step_width
// (m), speed (m/s), stance (%), double_support (%), knee_flexion_range (deg: the mean over
// both knees of the range of the stride-averaged knee flexion curve), hip_flexion_range (deg).
// Then two curves: knee_flexion_curve and hip_flexion_curve (deg), the RMSE over the cycle
// between the two sides' stride-averaged flexion curves (both sides' joints pooled); their rows
// carry the RMSE as `reconstructed` and 0 as `mocap` (the curve against itself), so the
// Bland-Altman bias of a curve row is its mean RMSE.
struct GaitMeasureName {
  const char* name;
  const char* unit;
  const char* key;  // gaitMeasureByName's (core/gait/gait_measures.h); a curve's base name
  bool curve = false;
};
const std::vector<GaitMeasureName>& agreementMeasures();

struct GaitAgreementRow {
  std::string subject, engine;
  double angleDeg = 0.0;                    // the view (setting "camera": the camera's azimuth)
  std::string measure;
  double mocap = NAN, reconstructed = NAN;  // NaN: that side could not be measured
  // Experiment "engines" (engines_experiment.h) reports more than one condition: "view" is an
  // orthographic view at angleDeg with `noise` mm of 2D noise, "camera" a random pinhole
  // camera (number `camera` of the walker's) with `noise` px.
  std::string setting = "view";
  double noise = 0.0;
  int camera = -1;
};

// What is known of one side's walk besides its frames.
struct GaitSideWalk {
  std::optional<double> progressionMps;  // its speed over the floor (measureGait's progression)
  bool twoHarmonicWalker = false;         // in place, a two-harmonic walker: measureTwoHarmonicGait
  // A periodic walk's stride frequency (a Fourier walker's ω / 2π): its events one per stride
  // (gaitEventsOfPeriodicWalk) rather than the kinematics' peaks.
  std::optional<double> strideHz;
};

// One walker at one view: a row per measure. truthMm and reconstructedMm: T × 45 at rateHz in
// the walker's frame (x right, y forward, z up; progression may be present or removed). A side
// that cannot be measured (no complete stride) gives NaN, never an exception.
std::vector<GaitAgreementRow> gaitAgreementRows(const std::string& subject, const std::string& engine,
                                                double angleDeg, const Eigen::Ref<const Eigen::MatrixXd>& truthMm,
                                                const Eigen::Ref<const Eigen::MatrixXd>& reconstructedMm,
                                                double rateHz, const GaitSideWalk& truthWalk = {},
                                                const GaitSideWalk& reconstructedWalk = {});

// A camera's azimuth band, as clinical reports group views: "front" within 30° of the walker's
// front (|α| < 30°), "back" within 30° of its back (|α| > 150°), "side" between.
std::string azimuthBand(double alphaDeg);

struct BlandAltmanRow {
  std::string engine;
  double angleDeg = 0.0;  // NaN for setting "camera": its rows pool the cameras of one band
  std::string band;       // setting "camera": azimuthBand of its cameras; "" for views
  std::string setting = "view";
  double noise = 0.0;
  std::string measure, unit;
  int pairs = 0;        // walkers where both sides were measured
  int unmeasured = 0;   // where the reconstruction (or the mocap) gave no value
  double mocapMean = NAN;
  double bias = NAN, sd = NAN, loaLow = NAN, loaHigh = NAN;
  double meanAbsDifference = NAN;
  double medianAbsDifference = NAN;
};

// Grouped by setting, engine, angle (views) or azimuth band (cameras), noise and measure, in
// the order first seen.
std::vector<BlandAltmanRow> blandAltman(const std::vector<GaitAgreementRow>& rows);

}  // namespace ew
