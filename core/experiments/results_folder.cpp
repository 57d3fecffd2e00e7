#include "core/experiments/results_folder.h"

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <system_error>
#include <unistd.h>

#include "core/common/errors.h"
#include "core/common/json_number.h"
#include "core/io/atomic_write.h"
#include "core/experiments/plot.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

// [SECTION] CSV text

// Enough digits to round-trip a meaningful error (mm², degrees), no trailing noise.
std::string num(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

template <class Row, class Fn>
std::string csv(const char* header, const std::vector<Row>& rows, Fn line) {
  std::ostringstream out;
  out << header << '\n';
  for (const Row& r : rows) out << line(r) << '\n';
  return out.str();
}

std::string join(std::initializer_list<std::string> cells) {
  std::string s;
  for (const auto& c : cells) s += (s.empty() ? "" : ",") + c;
  return s;
}

// A label with commas or quotes as one CSV cell.
std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string viewErrorLine(const ViewErrorRow& r, bool withCondition) {
  std::string s = r.subject + ",";
  if (withCondition) s += r.condition + ",";
  return s + join({num(r.angleDeg), r.method, num(r.absErrorMm2), num(r.relError),
                   num(r.varMissingMm2), num(r.mpjpeMm)});
}

}  // namespace

std::string semanticAxesCsv(const std::vector<SemanticAxisRow>& rows) {
  return csv(kSemanticAxesHeader, rows, [](const SemanticAxisRow& r) {
    return join({r.attribute, quoted(r.label), r.source, r.categorical ? "two-class" : "numeric",
                 std::to_string(r.walkers), num(r.mean), num(r.sd), num(r.looR2), num(r.looRmse),
                 num(r.looAccuracy), num(r.chance), num(r.gain), r.steerable ? "1" : "0",
                 num(r.sliderMeasuredChange), num(r.sliderRatio)});
  });
}

std::string semanticViewsCsv(const std::vector<SemanticViewRow>& rows) {
  return csv(kSemanticViewsHeader, rows, [](const SemanticViewRow& r) {
    return join({r.subject, r.walker, r.attribute, r.view, num(r.angleDeg), num(r.alphaHatDeg), num(r.truth),
                 num(r.from3d), num(r.from2d), r.categorical ? std::to_string(r.class3d) : "",
                 r.categorical ? std::to_string(r.class2d) : ""});
  });
}

std::string semanticViewSummaryCsv(const std::vector<SemanticViewSummaryRow>& rows) {
  return csv(kSemanticViewSummaryHeader, rows, [](const SemanticViewSummaryRow& r) {
    return join({r.attribute, r.categorical ? "two-class" : "numeric", r.view, num(r.angleDeg),
                 std::to_string(r.walkers), num(r.sd), num(r.rmse3d), num(r.rmse2d), num(r.r2From2d),
                 num(r.accuracy3d), num(r.accuracy2d)});
  });
}

std::string harmonicsCsv(const std::vector<HarmonicsRow>& rows) {
  return csv(kHarmonicsHeader, rows, [](const HarmonicsRow& r) {
    return join({r.walker, r.subject, r.source, num(r.strideHz), num(r.h1Share), num(r.h2Share),
                 num(r.residualShare)});
  });
}

std::string varianceCsv(const std::vector<VarianceRow>& rows) {
  return csv(kVarianceHeader, rows, [](const VarianceRow& r) {
    return join({std::to_string(r.component), num(r.eigenvalueMm2), num(r.varianceShare),
                 num(r.cumulativeShare)});
  });
}

std::string sigmaSweepCsv(const std::vector<SigmaSweepRow>& rows) {
  return csv(kSigmaSweepHeader, rows, [](const SigmaSweepRow& r) {
    return join({num(r.sigma2Mm2), r.method, num(r.meanAbsErrorMm2), num(r.meanRelError), num(r.mpjpeMm)});
  });
}

std::string knownViewCsv(const std::vector<ViewErrorRow>& rows) {
  return csv(kKnownViewHeader, rows, [](const ViewErrorRow& r) { return viewErrorLine(r, false); });
}

std::string unknownViewCsv(const std::vector<UnknownViewRow>& rows) {
  return csv(kUnknownViewHeader, rows, [](const UnknownViewRow& r) {
    return join({r.subject, num(r.trueAngleDeg), r.method, num(r.estAngleDeg), num(r.angleErrorDeg),
                 num(r.absErrorMm2), num(r.mpjpeMm)});
  });
}

std::string noiseCsv(const std::vector<ViewErrorRow>& rows) {
  return csv(kNoiseHeader, rows, [](const ViewErrorRow& r) { return viewErrorLine(r, true); });
}

std::string missingJointsCsv(const std::vector<ViewErrorRow>& rows) {
  return csv(kMissingJointsHeader, rows, [](const ViewErrorRow& r) { return viewErrorLine(r, true); });
}

std::string lowerBodyCsv(const std::vector<LowerBodyRow>& rows) {
  return csv(kLowerBodyHeader, rows, [](const LowerBodyRow& r) {
    return join({r.subject, r.walker, r.joint, r.method, num(r.mpjpeMm)});
  });
}

namespace {

// A cell that may hold commas (an error text, a label): quoted, inner quotes doubled (RFC 4180).
std::string quotedCell(std::string error) {
  for (std::size_t i = 0; (i = error.find('"', i)) != std::string::npos; i += 2) error.insert(i, "\"");
  return error.empty() ? "" : "\"" + error + "\"";
}

}  // namespace

std::string snippetEnginesCsv(const std::vector<EngineRow>& rows) {
  return csv(kSnippetEnginesHeader, rows, [](const EngineRow& r) {
    return join({r.subject, r.clip, num(r.angleDeg), r.engine, std::to_string(r.frames),
                 r.error.empty() ? num(r.mpjpeMm) : "", r.error.empty() ? num(r.depthErrorMm2) : "",
                 quotedCell(r.error), num(r.seconds)});
  });
}

std::string snippetPhaseCsv(const std::vector<PhaseRow>& rows) {
  return csv(kSnippetPhaseHeader, rows, [](const PhaseRow& r) {
    return join({num(r.angleDeg), r.engine, std::to_string(r.bin), num(r.mpjpeMm), std::to_string(r.frames)});
  });
}

std::string snippetThetaCsv(const std::vector<ThetaRow>& rows) {
  return csv(kSnippetThetaHeader, rows, [](const ThetaRow& r) {
    return join({r.subject, num(r.angleDeg), std::to_string(r.snippet), num(r.trueDeg), num(r.estimatedDeg),
                 num(r.errorDeg), num(r.clipEstimateDeg)});
  });
}

std::string snippetClustersCsv(const std::vector<ClusterChoiceRow>& rows) {
  return csv(kSnippetClustersHeader, rows, [](const ClusterChoiceRow& r) {
    return join({std::to_string(r.clusters), num(r.heldOutLogLikelihood), num(r.emHeldOutLogLikelihood)});
  });
}

std::string gaitAgreementCsv(const std::vector<GaitAgreementRow>& rows) {
  return csv(kGaitAgreementHeader, rows, [](const GaitAgreementRow& r) {
    return join({r.subject, r.engine, num(r.angleDeg), r.measure, num(r.mocap), num(r.reconstructed)});
  });
}

std::string blandAltmanCsv(const std::vector<BlandAltmanRow>& rows) {
  return csv(kBlandAltmanHeader, rows, [](const BlandAltmanRow& r) {
    return join({r.engine, num(r.angleDeg), r.measure, r.unit, std::to_string(r.pairs), std::to_string(r.unmeasured),
                 num(r.mocapMean), num(r.bias), num(r.sd), num(r.loaLow), num(r.loaHigh), num(r.meanAbsDifference),
                 num(r.medianAbsDifference)});
  });
}

// Cells that have no value (an engine's refusal, a camera row's view-only column) are empty.
namespace {
std::string numOrEmpty(double v) { return std::isfinite(v) ? num(v) : ""; }
}  // namespace

std::string enginesCsv(const std::vector<EnginesRow>& rows) {
  return csv(kEnginesHeader, rows, [](const EnginesRow& r) {
    return join({r.setting, r.subject, r.engine, quotedCell(r.variant), num(r.angleDeg),
                 r.camera >= 0 ? std::to_string(r.camera) : "", num(r.noise), r.noiseUnit, std::to_string(r.frames),
                 numOrEmpty(r.mpjpeMm), numOrEmpty(r.depthErrorMm2), num(r.seconds), quotedCell(r.error)});
  });
}

std::string enginesSummaryCsv(const std::vector<EnginesSummaryRow>& rows) {
  return csv(kEnginesSummaryHeader, rows, [](const EnginesSummaryRow& r) {
    return join({r.setting, r.engine, quotedCell(r.variant), num(r.noise), r.noiseUnit, std::to_string(r.clips),
                 std::to_string(r.failures), numOrEmpty(r.meanMpjpeMm), numOrEmpty(r.medianMpjpeMm),
                 num(r.meanSeconds), numOrEmpty(r.msPerFrame)});
  });
}

std::string enginesGaitAgreementCsv(const std::vector<GaitAgreementRow>& rows) {
  return csv(kEnginesGaitAgreementHeader, rows, [](const GaitAgreementRow& r) {
    return join({r.setting, r.subject, quotedCell(r.engine), num(r.angleDeg),
                 r.camera >= 0 ? std::to_string(r.camera) : "", num(r.noise), r.measure, numOrEmpty(r.mocap),
                 numOrEmpty(r.reconstructed)});
  });
}

std::string enginesBlandAltmanCsv(const std::vector<BlandAltmanRow>& rows) {
  return csv(kEnginesBlandAltmanHeader, rows, [](const BlandAltmanRow& r) {
    return join({r.setting, quotedCell(r.engine), numOrEmpty(r.angleDeg), r.band, num(r.noise), r.measure, r.unit,
                 std::to_string(r.pairs), std::to_string(r.unmeasured), numOrEmpty(r.mocapMean), numOrEmpty(r.bias),
                 numOrEmpty(r.sd), numOrEmpty(r.loaLow), numOrEmpty(r.loaHigh), numOrEmpty(r.meanAbsDifference),
                 numOrEmpty(r.medianAbsDifference)});
  });
}

namespace {

// An engine's columns: empty when it was not asked for.
std::string scoreMm(const std::optional<EngineClipScore>& s) { return s ? num(s->mpjpeMm) : ""; }
std::string scoreError(const std::optional<EngineClipScore>& s) { return s ? quotedCell(s->error) : ""; }

}  // namespace

std::string cameraCsv(const std::vector<CameraRow>& rows) {
  return csv(kCameraHeader, rows, [](const CameraRow& r) {
    const std::string error = r.error;
    return join({r.subject, r.walker, std::to_string(r.camera), num(r.noisePx), r.bystander ? "1" : "0",
                 std::to_string(r.frames), num(r.trueAlphaDeg), num(r.trueElevationDeg), num(r.trueFocalPx),
                 num(r.trueDistanceM), num(r.alphaDeg), num(r.elevationDeg), num(r.focalPx), num(r.distanceM),
                 num(r.alphaErrorDeg), num(r.elevationErrorDeg), num(r.focalRelError), num(r.heightRelError),
                 num(r.mpjpeMm), num(r.reprojectionRmsPx), quotedCell(error), scoreMm(r.skeleton),
                 r.skeleton ? std::to_string(r.skeleton->clampedBoneFrames) : "", scoreError(r.skeleton),
                 scoreMm(r.skeletonGuided), scoreError(r.skeletonGuided),
                 scoreMm(r.skeletonTable2), scoreError(r.skeletonTable2), scoreMm(r.skeletonEigenwalkerBones),
                 scoreError(r.skeletonEigenwalkerBones), scoreMm(r.snippet), scoreError(r.snippet)});
  });
}

std::string cameraWideCsv(const std::vector<CameraWideRow>& rows) {
  return csv(kCameraWideHeader, rows, [](const CameraWideRow& w) {
    const CameraRow& r = w.clip;
    return join({quotedCell(w.factor), quotedCell(w.level), r.subject, r.walker, std::to_string(r.camera),
                 num(r.noisePx), r.bystander ? "1" : "0", std::to_string(r.frames), num(r.strides),
                 num(r.walkerHeightPx), num(r.trueAlphaDeg), num(r.trueElevationDeg), num(r.trueFocalPx),
                 num(r.trueWalkerDistanceM), num(r.alphaDeg), num(r.elevationDeg), num(r.focalPx),
                 num(r.walkerDistanceM), num(r.alphaErrorDeg), num(r.elevationErrorDeg), num(r.distanceRelError),
                 num(r.focalRelError), num(r.heightRelError), num(r.mpjpeMm), num(r.reprojectionRmsPx),
                 num(r.seconds), num(r.trueViewElevationDeg), num(r.viewElevationDeg), num(r.viewElevationErrorDeg),
                 num(r.framingOffsetOfHeight), num(r.trueStatureM), num(r.statureM), num(r.statureSdM),
                 num(r.trueSpeedMps), num(r.speedMps), num(r.speedSdMps), num(r.trueStrideLengthM),
                 num(r.strideLengthM), num(r.strideLengthSdM), num(r.strideGivenStatureM),
                 num(r.strideGivenStatureSdM), num(r.alphaSdDeg), num(r.elevationSdDeg), num(r.focalSdPx),
                 num(r.walkerDistanceSdM), quotedCell(r.error)});
  });
}

std::string cameraWideSummaryCsv(const std::vector<CameraWideSummary>& rows) {
  return csv(kCameraWideSummaryHeader, rows, [](const CameraWideSummary& s) {
    return join({quotedCell(s.factor), quotedCell(s.level), std::to_string(s.clips), std::to_string(s.refusals),
                 num(s.medianStrides), num(s.medianWalkerHeightPx), num(s.meanMpjpeMm), num(s.medianMpjpeMm),
                 num(s.medianAlphaErrorDeg), num(s.medianElevationErrorDeg), num(s.medianViewElevationErrorDeg),
                 num(s.medianDistanceRelError),
                 num(s.elevationOver5Share), num(s.distanceOver20Share), num(s.statureWithin2SdShare),
                 num(s.speedWithin2SdShare), num(s.strideWithin2SdShare), num(s.strideGivenStatureWithin2SdShare),
                 num(s.alphaWithin2SdShare), num(s.elevationWithin2SdShare), num(s.focalWithin2SdShare),
                 num(s.distanceWithin2SdShare)});
  });
}

// [SECTION] summary.json

namespace {

using nlohmann::json;

// Per clip kind, engine and angle: mean MPJPE and depth error over the subjects the engine
// answered, and how many it refused; θ per angle: median error, share within 10°, and the
// share of subjects whose median snippet is within 10°.
json snippetSummary(const SnippetExperimentResults& r) {
  json engines = json::array();
  std::map<std::tuple<std::string, std::string, double>, std::tuple<double, double, int, int>> cells;
  std::map<std::tuple<std::string, std::string, double>, double> seconds;  // over every clip, answered or not
  for (const auto& row : r.rows) {
    auto& [mpjpe, depth, n, refused] = cells[{row.clip, row.engine, row.angleDeg}];
    seconds[{row.clip, row.engine, row.angleDeg}] += row.seconds;
    if (!row.error.empty()) { ++refused; continue; }
    mpjpe += row.mpjpeMm;
    depth += row.depthErrorMm2;
    ++n;
  }
  for (const auto& [key, v] : cells) {
    const auto& [mpjpe, depth, n, refused] = v;
    engines.push_back({{"clip", std::get<0>(key)}, {"engine", std::get<1>(key)}, {"angle_deg", std::get<2>(key)},
                       {"mean_mpjpe_mm", n ? json(mpjpe / n) : json(nullptr)},
                       {"mean_depth_error_mm2", n ? json(depth / n) : json(nullptr)},
                       {"clips", n}, {"refused", refused},
                       {"mean_seconds", seconds[key] / std::max(1, n + refused)}});
  }
  json theta = json::array();
  std::map<double, std::map<std::string, std::vector<double>>> byAngle;
  for (const auto& t : r.theta) byAngle[t.angleDeg][t.subject].push_back(t.errorDeg);
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  };
  for (const auto& [angle, subjects] : byAngle) {
    std::vector<double> all;
    int subjectsWithin = 0;
    for (const auto& [subject, errors] : subjects) {
      all.insert(all.end(), errors.begin(), errors.end());
      if (median(errors) <= 10.0) ++subjectsWithin;
    }
    const double within = static_cast<double>(std::count_if(all.begin(), all.end(), [](double e) { return e <= 10.0; }));
    theta.push_back({{"angle_deg", angle}, {"snippets", all.size()}, {"median_error_deg", median(all)},
                     {"snippets_within_10_deg_share", within / static_cast<double>(std::max<size_t>(1, all.size()))},
                     {"subjects_median_within_10_deg_share",
                      static_cast<double>(subjectsWithin) / static_cast<double>(std::max<size_t>(1, subjects.size()))}});
  }
  json gait = json::array();
  for (const auto& b : blandAltman(r.gait)) {
    gait.push_back({{"engine", b.engine}, {"angle_deg", b.angleDeg}, {"measure", b.measure}, {"unit", b.unit},
                    {"pairs", b.pairs}, {"unmeasured", b.unmeasured}, {"mocap_mean", finiteOrNull(b.mocapMean)},
                    {"bias", finiteOrNull(b.bias)}, {"loa_low", finiteOrNull(b.loaLow)}, {"loa_high", finiteOrNull(b.loaHigh)}});
  }
  return {{"engines", engines}, {"theta", theta}, {"train_seconds_mean", r.trainSecondsMean},
          {"training_snippets_mean", r.snippetsMean}, {"gait_bland_altman", gait}};
}

// Per setting, engine, variant and noise level: accuracy and time (engines_summary.csv's rows).
json enginesSummary(const EnginesExperimentResults& r) {
  json out = json::array();
  for (const auto& e : summarizeEngines(r.rows))
    out.push_back({{"setting", e.setting}, {"engine", e.engine}, {"variant", e.variant}, {"noise", e.noise},
                   {"noise_unit", e.noiseUnit}, {"clips", e.clips}, {"failures", e.failures},
                   {"mean_mpjpe_mm", finiteOrNull(e.meanMpjpeMm)}, {"median_mpjpe_mm", finiteOrNull(e.medianMpjpeMm)},
                   {"mean_seconds", e.meanSeconds}, {"ms_per_frame", finiteOrNull(e.msPerFrame)}});
  return out;
}

// Per attribute: the axis's quality and slider check (semantic_axes.csv's rows).
json semanticSummary(const SemanticExperimentResults& r) {
  json axes = json::array();
  for (const auto& a : r.axes)
    axes.push_back({{"attribute", a.attribute}, {"source", a.source}, {"kind", a.categorical ? "two-class" : "numeric"},
                    {"walkers", a.walkers}, {"sd", finiteOrNull(a.sd)}, {"loo_r2", finiteOrNull(a.looR2)},
                    {"loo_rmse", finiteOrNull(a.looRmse)}, {"loo_accuracy", finiteOrNull(a.looAccuracy)},
                    {"chance", finiteOrNull(a.chance)}, {"steerable", a.steerable}, {"slider_ratio", finiteOrNull(a.sliderRatio)}});
  return {{"components", r.components}, {"axes", axes}, {"notes", r.notes}};
}

json knownViewSummary(const std::vector<ViewErrorRow>& rows) {
  std::map<std::string, std::array<double, 4>> sums;  // abs, rel, mpjpe, count
  for (const auto& r : rows) {
    auto& s = sums[r.method];
    s[0] += r.absErrorMm2;
    s[1] += r.relError;
    s[2] += r.mpjpeMm;
    s[3] += 1;
  }
  json out = json::object();
  for (const auto& [method, s] : sums) {
    out[method] = {{"mean_abs_error_mm2", s[0] / s[3]}, {"mean_rel_error", s[1] / s[3]},
                   {"mpjpe_mm", s[2] / s[3]}};
  }
  if (sums.count("lsq") && sums.count("map")) {
    out["map_vs_lsq_reduction"] = 1.0 - (sums["map"][0] / sums["map"][3]) / (sums["lsq"][0] / sums["lsq"][3]);
  }
  return out;
}

json unknownViewSummary(const std::vector<UnknownViewRow>& rows) {
  std::map<std::string, std::array<double, 5>> sums;  // err, count, err(|α|≤60), count, within 10°
  for (const auto& r : rows) {
    auto& s = sums[r.method];
    s[0] += r.angleErrorDeg;
    s[1] += 1;
    if (std::abs(r.trueAngleDeg) <= 60.0) {
      s[2] += r.angleErrorDeg;
      s[3] += 1;
    }
    if (r.angleErrorDeg <= 10.0) s[4] += 1;
  }
  json out = json::object();
  for (const auto& [method, s] : sums) {
    out[method] = {{"mae_deg", s[0] / s[1]},
                   {"mae_deg_abs_le_60", s[3] > 0 ? json(s[2] / s[3]) : json(nullptr)},
                   {"share_within_10_deg", s[4] / s[1]}};
  }
  return out;
}

// Mean E_a per method and condition (noise level, joint set).
json byCondition(const std::vector<ViewErrorRow>& rows) {
  std::map<std::string, std::map<std::string, std::pair<double, int>>> sums;
  for (const auto& r : rows) {
    auto& s = sums[r.method][r.condition];
    s.first += r.absErrorMm2;
    s.second += 1;
  }
  json out = json::object();
  for (const auto& [method, conditions] : sums) {
    for (const auto& [condition, s] : conditions) out[method][condition] = s.first / s.second;
  }
  return out;
}

}  // namespace

std::string summaryJson(const EvaluationResults& r, const EvaluationProvenance& provenance) {
  double h1 = 0, h2 = 0;
  for (const auto& h : r.harmonics) {
    h1 += h.h1Share;
    h2 += h.h2Share;
  }
  const double n = std::max<double>(1.0, static_cast<double>(r.harmonics.size()));
  json s = {{"walkers", r.walkers}, {"subjects", r.subjects}, {"components", r.components},
            {"components_95", r.components95}, {"h1_share_mean", h1 / n}, {"h2_share_mean", h2 / n}};
  json experiments = json::array();
  for (Experiment e : r.ran) experiments.push_back(experimentName(e));
  s["experiments"] = experiments;
  s["sigma2_opt_mm2"] = r.sigma2OptMm2 ? json(*r.sigma2OptMm2) : json(nullptr);
  s["sigma2_opt_at_grid_edge"] = r.sigma2OptAtGridEdge;
  s["sigma2_used_mm2"] = r.sigma2UsedMm2;
  if (r.ran.count(Experiment::KnownView)) s["known_view"] = knownViewSummary(r.knownView);
  if (r.ran.count(Experiment::UnknownView)) s["unknown_view"] = unknownViewSummary(r.unknownView);
  if (r.ran.count(Experiment::Noise)) s["noise_mean_abs_error_mm2"] = byCondition(r.noise);
  if (r.ran.count(Experiment::MissingJoints)) s["missing_joints_mean_abs_error_mm2"] = byCondition(r.missingJoints);
  if (r.ran.count(Experiment::LowerBody)) {
    json lower = json::object();  // method → joint (and "all") → mean MPJPE of estimated joints, mm
    for (const auto& m : summarizeLowerBody(r.lowerBody)) lower[m.method][m.joint] = m.meanMpjpeMm;
    s["lower_body_estimated_mpjpe_mm"] = lower;
  }
  if (r.ran.count(Experiment::Camera)) {
    json camera = json::array();  // per noise level (px)
    for (const auto& c : summarizeCamera(r.camera)) {
      camera.push_back({{"noise_px", c.noisePx}, {"clips", c.clips}, {"failures", c.failures},
                        {"mean_mpjpe_mm", c.meanMpjpeMm}, {"median_alpha_error_deg", c.medianAlphaErrorDeg},
                        {"median_elevation_error_deg", c.medianElevationErrorDeg},
                        {"median_focal_rel_error", c.medianFocalRelError},
                        {"median_height_rel_error", c.medianHeightRelError},
                        {"height_within_5_percent_share", c.heightWithin5Share}});
      const auto other = [&](const char* key, const CameraSummary::Other& e) {
        if (e.clips)
          camera.back()[key] = {{"clips", e.clips}, {"failures", e.failures}, {"mean_mpjpe_mm", e.meanMpjpeMm}};
      };
      other("skeleton", c.skeleton);
      other("skeleton_guided", c.skeletonGuided);
      other("skeleton_table2_bones", c.skeletonTable2);
      other("skeleton_eigenwalker_bones", c.skeletonEigenwalkerBones);
      other("snippet", c.snippet);
    }
    s["camera"] = camera;
  }
  if (r.ran.count(Experiment::CameraWide)) {
    json wide = json::array();  // per factor and level, at 2 px
    for (const auto& c : summarizeCameraWide(r.cameraWide))
      wide.push_back({{"factor", c.factor}, {"level", c.level}, {"clips", c.clips}, {"refusals", c.refusals},
                      {"mean_mpjpe_mm", c.meanMpjpeMm}, {"median_mpjpe_mm", c.medianMpjpeMm},
                      {"median_alpha_error_deg", c.medianAlphaErrorDeg},
                      {"median_elevation_error_deg", c.medianElevationErrorDeg},
                      {"median_view_elevation_error_deg", c.medianViewElevationErrorDeg},
                      {"median_distance_rel_error", c.medianDistanceRelError}});
    s["camera_wide"] = wide;
  }
  if (r.ran.count(Experiment::Snippet)) s["snippet"] = snippetSummary(r.snippet);
  if (r.ran.count(Experiment::Engines)) s["engines"] = enginesSummary(r.engines);
  if (r.ran.count(Experiment::Semantic)) s["semantic"] = semanticSummary(r.semantic);
  if (r.ran.count(Experiment::SnippetClusters)) {
    json clusters = json::array();
    for (const auto& c : r.snippetClusters)
      clusters.push_back({{"clusters", c.clusters}, {"held_out_log_likelihood", c.heldOutLogLikelihood},
                          {"em_held_out_log_likelihood", c.emHeldOutLogLikelihood}});
    s["snippet_clusters"] = clusters;
  }
  json timings = json::object();
  for (const auto& [name, seconds] : r.timingsS) timings[name] = seconds;
  s["timings_s"] = timings;
  s["warnings"] = r.warnings;
  s["command_line"] = provenance.commandLine;
  s["data_files"] = provenance.dataFiles;
  return s.dump(2) + "\n";
}

// [SECTION] The folder, atomically

namespace {

void writeText(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  out.flush();
  if (!out) throw Error(ErrorKind::Io, file.string(), "", "cannot write");
}

}  // namespace

std::vector<std::string> writeResultsFolder(const fs::path& dir, const EvaluationResults& r,
                                            const EvaluationProvenance& provenance,
                                            const ResultsFolderOptions& options) {
  // "results/" names the folder "results" (users type the slash; README's commands do).
  const fs::path target = folderPathWithoutTrailingSeparator(dir);
  // "" or "." or "dir/..": no folder name to write beside and rename into place.
  if (target.empty() || target.filename().empty() || target.filename() == "." ||
      target.filename() == "..")
    throw Error(ErrorKind::BadArgument, dir.string(), "",
                "results folder: the path must end in a folder name");
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string stem = "." + target.filename().string() + "." + std::to_string(::getpid());
  const fs::path partial = parent / (stem + ".partial");
  const fs::path old = parent / (stem + ".old");
  std::vector<std::string> written;
  const auto add = [&](const std::string& name, const std::string& text) {
    writeText(partial / name, text);
    written.push_back(name);
    if (options.afterFile) options.afterFile(partial / name);
  };
  try {
    fs::create_directories(parent);
    fs::remove_all(partial);
    fs::create_directory(partial);
    if (r.ran.count(Experiment::Variance)) {
      add("harmonics.csv", harmonicsCsv(r.harmonics));
      add("variance.csv", varianceCsv(r.variance));
    }
    if (r.ran.count(Experiment::SigmaSweep)) add("sigma_sweep.csv", sigmaSweepCsv(r.sigmaSweep));
    if (r.ran.count(Experiment::KnownView)) add("known_view.csv", knownViewCsv(r.knownView));
    if (r.ran.count(Experiment::UnknownView)) add("unknown_view.csv", unknownViewCsv(r.unknownView));
    if (r.ran.count(Experiment::Noise)) add("noise.csv", noiseCsv(r.noise));
    if (r.ran.count(Experiment::MissingJoints)) add("missing_joints.csv", missingJointsCsv(r.missingJoints));
    if (r.ran.count(Experiment::LowerBody)) add("lower_body.csv", lowerBodyCsv(r.lowerBody));
    if (r.ran.count(Experiment::Camera)) add("camera.csv", cameraCsv(r.camera));
    if (r.ran.count(Experiment::CameraWide)) {
      add("camera_wide.csv", cameraWideCsv(r.cameraWide));
      add("camera_wide_summary.csv", cameraWideSummaryCsv(summarizeCameraWide(r.cameraWide)));
    }
    if (r.ran.count(Experiment::Snippet)) {
      add("snippet_engines.csv", snippetEnginesCsv(r.snippet.rows));
      add("snippet_phase.csv", snippetPhaseCsv(r.snippet.phase));
      add("snippet_theta.csv", snippetThetaCsv(r.snippet.theta));
      add("gait_agreement.csv", gaitAgreementCsv(r.snippet.gait));
      add("gait_bland_altman.csv", blandAltmanCsv(blandAltman(r.snippet.gait)));
    }
    if (r.ran.count(Experiment::SnippetClusters)) add("snippet_clusters.csv", snippetClustersCsv(r.snippetClusters));
    if (r.ran.count(Experiment::Engines)) {
      add("engines.csv", enginesCsv(r.engines.rows));
      add("engines_summary.csv", enginesSummaryCsv(summarizeEngines(r.engines.rows)));
      add("engines_gait_agreement.csv", enginesGaitAgreementCsv(r.engines.gait));
      add("engines_gait_bland_altman.csv", enginesBlandAltmanCsv(blandAltman(r.engines.gait)));
    }
    if (r.ran.count(Experiment::Semantic)) {
      add("semantic_axes.csv", semanticAxesCsv(r.semantic.axes));
      add("semantic_views.csv", semanticViewsCsv(r.semantic.views));
      add("semantic_views_summary.csv", semanticViewSummaryCsv(r.semantic.viewSummary));
    }
    if (options.plots) {
      for (const auto& name : writeEvaluationPlots(partial, r, options.plots)) {
        written.push_back(name);
        if (options.afterFile) options.afterFile(partial / name);
      }
    }
    add("summary.json", summaryJson(r, provenance));
    // Swap: the old folder moves aside, the new one takes its name, the old one goes.
    fs::remove_all(old);
    if (fs::exists(target)) fs::rename(target, old);
    fs::rename(partial, target);
    fs::remove_all(old);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(partial, ec);
    if (!fs::exists(target, ec) && fs::exists(old, ec)) fs::rename(old, target, ec);
    try {
      throw;
    } catch (const fs::filesystem_error& e) {
      throw Error(ErrorKind::Io, target.string(), "", e.code().message());
    }
  }
  return written;
}

}  // namespace ew
