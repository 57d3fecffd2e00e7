#include "ui/panels/metric_items.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "ui/app/app_state.h"

namespace ew::ui {
namespace {

std::string formatted(const char* format, double value) {
  char text[96];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// "1.42 ± 0.06 m" when the fit gives the measure an SD (CameraFit::sd), else "".
std::string withSd(double value, double sd, const char* unit) {
  if (!(std::isfinite(sd) && sd > 0.0)) return "";
  char text[96];
  std::snprintf(text, sizeof text, "%.2f ± %.2f %s", value, sd, unit);
  return text;
}

// A keypoint clip: the walk in metres and seconds (the prior knows how big people are) and
// how well the walker drawn back through the camera meets the keypoints.
std::vector<MetricItem> clipItems(const AppState& s) {
  const ClipReconstruction& rec = s.clip.fit()->rec;
  const CameraFit& f = rec.fit;
  return {{"stature  est.", formatted("%.2f m", f.statureMm / 1000.0), formatted("head %.2f m", f.headHeightMm / 1000.0),
           MetricTone::Normal, withSd(f.statureMm / 1000.0, f.sd.statureMm / 1000.0, "m")},
          {f.inPlace ? "belt speed" : "speed", formatted("%.2f m/s", f.speedMps),
           rec.trial.rateAssumed ? "(30 fps?)" : f.inPlace ? "in place" : "", MetricTone::Normal,
           withSd(f.speedMps, f.sd.speedMps, "m/s")},
          {"stride length", formatted("%.2f m", f.strideLengthM), formatted("%.2f Hz", f.strideHz),
           strideIsImplausible(f) ? MetricTone::Bad : MetricTone::Normal,
           withSd(f.strideLengthM, f.sd.strideLengthM, "m")},
          {"cadence  steps", formatted("%.0f /min", f.cadenceStepsPerMin),
           rec.strideSource.starts_with("trunk") ? "trunk's bob" : ""},
          {"reprojection  RMS", formatted("%.1f px", f.reprojectionRmsPx),
           f.outlierSamples > 0 ? formatted("%.0f glitches out", static_cast<double>(f.outlierSamples)) : ""}};
}

// Over the measured joints, as `reconstruct` reports: a model-estimated joint has no truth.
std::vector<MetricItem> reconstructionItems(const AppState& s, const ReconBase& r, const ReconDisplay& d) {
  std::vector<MetricItem> items;
  items.push_back({"E_a  depth error", formatted("%.0f mm²", d.absScoredMm2),
                   formatted("(√ %.1f mm)", std::sqrt(std::max(d.absScoredMm2, 0.0)))});
  items.push_back({"E_r  relative", formatted("%.3f", d.relScored), formatted("σ_m² %.0f mm²", d.errors.sigmaM2Mm2)});
  // Joints estimated from a model are scored apart (their ground truth is the model's).
  std::string note;
  if (d.mpjpeModelEstimatedMm) {
    char text[96];
    std::snprintf(text, sizeof text, "%d measured joints · est. (%.1f)", d.jointsScored, *d.mpjpeModelEstimatedMm);
    note = text;
  }
  items.push_back({"MPJPE  3D", formatted("%.1f mm", d.mpjpeMm), note});
  items.push_back({"2D residual  RMS", formatted("%.1f mm", d.residualRmsMm), d.edited ? "(edited k)" : "",
                   d.edited ? MetricTone::Edited : MetricTone::Normal});
  if (s.doc.recon.unknownAngle)
    items.push_back({"est. α  (true α hidden)", formatted("%.1f°", r.alphaUsedDeg),
                     formatted("error %.1f°", d.angleErrorDeg),
                     d.angleErrorDeg > 10.0 ? MetricTone::Bad : MetricTone::Good});
  else
    items.push_back({"α  known", formatted("%.1f°", r.alphaTrueDeg), ""});
  return items;
}

}  // namespace

std::vector<MetricItem> metricItems(const AppState& s) {
  if (s.doc.mode == Mode::Clip) return s.clip.fit() ? clipItems(s) : std::vector<MetricItem>{};
  const ReconBase* r = s.derived.recon();
  const ReconDisplay* d = s.derived.display();
  if (s.doc.mode != Mode::Reconstruct || !r || !d) return {};
  return reconstructionItems(s, *r, *d);
}

}  // namespace ew::ui
