#pragma once
// The evaluation's output folder: CSVs with exact header lines, summary.json and the
// plots, written into a temporary sibling folder and renamed into place only when
// everything succeeded, so DIR is never seen half-written (an old DIR is replaced last).

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "core/experiments/experiments.h"
#include "core/experiments/plot.h"

namespace ew {

// Header lines, exactly as written (tests and readers rely on them).
inline constexpr const char* kHarmonicsHeader = "walker,subject,source,stride_hz,h1_share,h2_share,residual_share";
inline constexpr const char* kVarianceHeader = "component,eigenvalue_mm2,variance_share,cumulative_share";
inline constexpr const char* kSigmaSweepHeader = "sigma2_mm2,method,mean_abs_error_mm2,mean_rel_error,mpjpe_mm";
inline constexpr const char* kKnownViewHeader = "subject,angle_deg,method,abs_error_mm2,rel_error,var_missing_mm2,mpjpe_mm";
inline constexpr const char* kUnknownViewHeader = "subject,true_angle_deg,method,est_angle_deg,angle_error_deg,abs_error_mm2,mpjpe_mm";
inline constexpr const char* kNoiseHeader = "subject,noise_mm,angle_deg,method,abs_error_mm2,rel_error,var_missing_mm2,mpjpe_mm";
inline constexpr const char* kMissingJointsHeader = "subject,missing,angle_deg,method,abs_error_mm2,rel_error,var_missing_mm2,mpjpe_mm";
inline constexpr const char* kLowerBodyHeader = "subject,walker,estimated_joint,method,mpjpe_mm";
inline constexpr const char* kCameraHeader =
    "subject,walker,camera,noise_px,bystander,frames,true_alpha_deg,true_elevation_deg,true_focal_px,"
    "true_distance_m,alpha_deg,elevation_deg,focal_px,distance_m,alpha_error_deg,elevation_error_deg,"
    "focal_rel_error,height_rel_error,mpjpe_mm,reprojection_rms_px,error,skeleton_mpjpe_mm,"
    "skeleton_clamped_bone_frames,skeleton_error,skeleton_guided_mpjpe_mm,skeleton_guided_error,skeleton_table2_mpjpe_mm,skeleton_table2_error,"
    "skeleton_eigenwalker_bones_mpjpe_mm,skeleton_eigenwalker_bones_error,snippet_mpjpe_mm,snippet_error";
inline constexpr const char* kCameraWideHeader =
    "factor,level,subject,walker,camera,noise_px,bystander,frames,strides,walker_height_px,true_alpha_deg,"
    "true_elevation_deg,true_focal_px,true_walker_distance_m,alpha_deg,elevation_deg,focal_px,walker_distance_m,"
    "alpha_error_deg,elevation_error_deg,distance_rel_error,focal_rel_error,height_rel_error,mpjpe_mm,"
    "reprojection_rms_px,seconds,true_view_elevation_deg,view_elevation_deg,view_elevation_error_deg,"
    "framing_offset_of_height,true_stature_m,stature_m,stature_sd_m,true_speed_mps,speed_mps,speed_sd_mps,"
    "true_stride_length_m,stride_length_m,stride_length_sd_m,stride_length_given_stature_m,"
    "stride_length_given_stature_sd_m,alpha_sd_deg,elevation_sd_deg,focal_sd_px,walker_distance_sd_m,error";
inline constexpr const char* kCameraWideSummaryHeader =
    "factor,level,clips,refusals,median_strides,median_walker_height_px,mean_mpjpe_mm,median_mpjpe_mm,"
    "median_alpha_error_deg,median_elevation_error_deg,median_view_elevation_error_deg,median_distance_rel_error,"
    "elevation_over_5deg_share,distance_over_20pct_share,stature_within_2sd_share,speed_within_2sd_share,"
    "stride_within_2sd_share,stride_given_stature_within_2sd_share,alpha_within_2sd_share,"
    "elevation_within_2sd_share,focal_within_2sd_share,distance_within_2sd_share";

inline constexpr const char* kSnippetEnginesHeader =
    "subject,clip,angle_deg,engine,frames,mpjpe_mm,depth_error_mm2,error,seconds";
inline constexpr const char* kSnippetPhaseHeader = "angle_deg,engine,phase_bin,mpjpe_mm,frames";
inline constexpr const char* kSnippetThetaHeader =
    "subject,angle_deg,snippet,true_deg,estimated_deg,error_deg,clip_estimate_deg";
inline constexpr const char* kSnippetClustersHeader = "clusters,held_out_log_likelihood,em_held_out_log_likelihood";
inline constexpr const char* kGaitAgreementHeader = "subject,engine,angle_deg,measure,mocap,reconstructed";
inline constexpr const char* kBlandAltmanHeader =
    "engine,angle_deg,measure,unit,pairs,unmeasured,mocap_mean,bias,sd,loa_low,loa_high,mean_abs_difference,"
    "median_abs_difference";

inline constexpr const char* kEnginesHeader =
    "setting,subject,engine,variant,angle_deg,camera,noise,noise_unit,frames,mpjpe_mm,depth_error_mm2,seconds,error";
inline constexpr const char* kEnginesSummaryHeader =
    "setting,engine,variant,noise,noise_unit,clips,failures,mean_mpjpe_mm,median_mpjpe_mm,mean_seconds,ms_per_frame";
inline constexpr const char* kEnginesGaitAgreementHeader =
    "setting,subject,engine,angle_deg,camera,noise,measure,mocap,reconstructed";
inline constexpr const char* kEnginesBlandAltmanHeader =
    "setting,engine,angle_deg,band,noise,measure,unit,pairs,unmeasured,mocap_mean,bias,sd,loa_low,loa_high,"
    "mean_abs_difference,median_abs_difference";

inline constexpr const char* kSemanticAxesHeader =
    "attribute,label,source,kind,walkers,mean,sd,loo_r2,loo_rmse,loo_accuracy,chance,gain,steerable,"
    "slider_measured_change,slider_ratio";
inline constexpr const char* kSemanticViewsHeader =
    "subject,walker,attribute,view,angle_deg,alpha_hat_deg,truth,from_3d,from_2d,class_3d,class_2d";
inline constexpr const char* kSemanticViewSummaryHeader =
    "attribute,kind,view,angle_deg,walkers,sd,rmse_3d,rmse_2d,r2_from_2d,accuracy_3d,accuracy_2d";

std::string semanticAxesCsv(const std::vector<SemanticAxisRow>& rows);
std::string semanticViewsCsv(const std::vector<SemanticViewRow>& rows);
std::string semanticViewSummaryCsv(const std::vector<SemanticViewSummaryRow>& rows);

std::string enginesCsv(const std::vector<EnginesRow>& rows);
std::string enginesSummaryCsv(const std::vector<EnginesSummaryRow>& rows);
std::string enginesGaitAgreementCsv(const std::vector<GaitAgreementRow>& rows);
std::string enginesBlandAltmanCsv(const std::vector<BlandAltmanRow>& rows);

std::string snippetEnginesCsv(const std::vector<EngineRow>& rows);
std::string snippetPhaseCsv(const std::vector<PhaseRow>& rows);
std::string snippetThetaCsv(const std::vector<ThetaRow>& rows);
std::string snippetClustersCsv(const std::vector<ClusterChoiceRow>& rows);
std::string gaitAgreementCsv(const std::vector<GaitAgreementRow>& rows);
std::string blandAltmanCsv(const std::vector<BlandAltmanRow>& rows);

std::string harmonicsCsv(const std::vector<HarmonicsRow>& rows);
std::string varianceCsv(const std::vector<VarianceRow>& rows);
std::string sigmaSweepCsv(const std::vector<SigmaSweepRow>& rows);
std::string knownViewCsv(const std::vector<ViewErrorRow>& rows);
std::string unknownViewCsv(const std::vector<UnknownViewRow>& rows);
std::string noiseCsv(const std::vector<ViewErrorRow>& rows);
std::string missingJointsCsv(const std::vector<ViewErrorRow>& rows);
std::string lowerBodyCsv(const std::vector<LowerBodyRow>& rows);
std::string cameraCsv(const std::vector<CameraRow>& rows);
std::string cameraWideCsv(const std::vector<CameraWideRow>& rows);
std::string cameraWideSummaryCsv(const std::vector<CameraWideSummary>& rows);

// What produced the results (recorded in summary.json).
struct EvaluationProvenance {
  std::string commandLine;
  std::vector<std::string> dataFiles;
};

// summary.json's text (pretty-printed JSON; keys documented in docs/RESULTS.md).
std::string summaryJson(const EvaluationResults& results, const EvaluationProvenance& provenance);

struct ResultsFolderOptions {
  PlotWriter plots;  // the figures' writer (plots/raster_plot.h: PNGs); empty: no figures
  // Called after each file is written into the temporary folder (progress; tests use it
  // to fail a run midway).
  std::function<void(const std::filesystem::path&)> afterFile;
};

// Writes the files of the experiments that ran into `dir` (created or replaced
// atomically; its parent is created if missing) and returns their names. On failure the
// temporary folder is removed, `dir` is left as it was, and the error is rethrown
// (filesystem errors as Error(Io) naming `dir`). Trailing separators are ignored ("a/" is
// the folder "a"); a path that does not end in a folder name ("", ".", "a/..") is
// Error(BadArgument).
std::vector<std::string> writeResultsFolder(const std::filesystem::path& dir,
                                            const EvaluationResults& results,
                                            const EvaluationProvenance& provenance,
                                            const ResultsFolderOptions& options = {});

}  // namespace ew
