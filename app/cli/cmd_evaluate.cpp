// `eigenwalker-cli evaluate --data PATH… --out DIR [--experiment …] …`: the Zhang & Troje
// (2007) evaluation, leave-one-subject-out (METHOD §7–8), as CSVs, PNG plots and summary.json.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>
#include <thread>

#include "app/cli/checks.h"
#include "app/cli/commands.h"
#include "core/common/errors.h"
#include "core/eigenwalker/walker_set.h"
#include "core/engines/engine.h"
#include "core/experiments/experiments.h"
#include "core/experiments/results_folder.h"
#include "core/gait/dataset.h"
#include "core/io/atomic_write.h"
#ifdef EW_HAVE_PLOTS
#include "plots/raster_plot.h"
#endif

namespace ew::cli {
namespace {

namespace fs = std::filesystem;

struct EvaluateArgs {
  std::vector<std::string> data;
  std::string out;
  std::vector<std::string> experiments{"all"};
  std::string angles;      // empty: each experiment's default views
  int cameras = 0;         // experiments "engines", "camera-wide": random cameras per walker (0 = default)
  std::string keepClips;             // experiments "camera", "engines": each clip's keypoints kept here
  std::vector<std::string> factors;  // experiment "camera-wide": the factors to run (empty: all)
  std::optional<double> detectorHipOffsetMm;  // experiment "camera": the simulated detector's hips
  bool noDetectorOffsets = false;              // experiment "camera": the reader ignores the offsets
  std::string method = "both";
  double sigma2Mm2 = 0.0;  // 0 = the sweep's optimum
  int components = 0;      // 0 = 95 % of the variance
  int clusters = 0;        // snippet prior m (0 = its default)
  int clusterComponents = 0;  // snippet prior q per cluster (0 = its default)
  int threads = 0;         // 0 = hardware concurrency
  bool noPlots = false;
  std::vector<std::string> engines;  // --engine: empty = every engine
};

// Progress on stderr: a bar with ETA on a terminal, a few plain lines otherwise.
class ProgressPrinter {
 public:
  ProgressPrinter() : tty_(::isatty(STDERR_FILENO) == 1) {}
  void operator()(int done, int total, const std::string& what) {
    using Clock = std::chrono::steady_clock;
    if (done == 0) start_ = Clock::now();
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    if (tty_) {
      const int width = 30, filled = total > 0 ? width * done / total : width;
      std::cerr << "\r" << std::left << std::setw(15) << what << " [" << std::string(static_cast<size_t>(filled), '#')
                << std::string(static_cast<size_t>(width - filled), '.') << "] " << done << "/" << total;
      if (done > 0 && done < total) std::cerr << "  ETA " << std::fixed << std::setprecision(1) << elapsed * (total - done) / done << " s   ";
      else std::cerr << "  " << std::fixed << std::setprecision(2) << elapsed << " s        ";
      if (done == total) std::cerr << "\n";
      std::cerr.flush();
      return;
    }
    // Plain: start, each quarter, end.
    if (done == 0 || done == total || (total >= 4 && done % (total / 4) == 0)) {
      std::cerr << what << ": " << done << "/" << total << (done == total ? " done" : "") << " ("
                << std::fixed << std::setprecision(2) << elapsed << " s)\n";
    }
  }

 private:
  bool tty_;
  std::chrono::steady_clock::time_point start_;
};

std::string commandLine() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string all, arg;
  while (std::getline(in, arg, '\0')) {
    const bool quote = arg.find_first_of(" \t'\"") != std::string::npos || arg.empty();
    all += (all.empty() ? "" : " ") + (quote ? "'" + arg + "'" : arg);
  }
  return all.empty() ? "eigenwalker-cli evaluate" : all;
}

std::set<Experiment> chosenExperiments(const std::vector<std::string>& names) {
  std::set<Experiment> out;
  for (const auto& n : names) {
    if (n == "all") {
      for (Experiment e : allExperiments()) out.insert(e);
    } else if (auto e = experimentFromName(n)) {
      out.insert(*e);
    } else {
      throw Error(ErrorKind::BadArgument, "--experiment", "", "unknown experiment '" + n + "'");
    }
  }
  return out;
}

bool asksFor(const EvaluateArgs& a, EngineKind kind) {
  if (a.engines.empty()) return true;
  for (const auto& e : a.engines)
    if (parseEngineKind(e, "--engine") == kind) return true;
  return false;
}

// --engine narrows the experiments: the paper's (Zhang & Troje's figures, the camera study)
// are the eigenwalker's own; "snippet" compares the engines asked for; "snippet-clusters"
// is the snippet prior's. Without --experiment, --engine snippet means "snippet".
std::vector<std::string> experimentsForEngines(const EvaluateArgs& a) {
  if (asksFor(a, EngineKind::Eigenwalker)) {
    if (!asksFor(a, EngineKind::Snippet))
      for (const auto& n : a.experiments)
        if (n == experimentName(Experiment::SnippetClusters))
          throw Error(ErrorKind::BadArgument, "--engine", "", "experiment 'snippet-clusters' is the snippet prior's");
    return a.experiments;
  }
  if (a.experiments == std::vector<std::string>{"all"}) return {experimentName(Experiment::Snippet)};
  for (const auto& n : a.experiments) {
    const auto e = experimentFromName(n);
    if (e && *e != Experiment::Snippet && *e != Experiment::SnippetClusters && *e != Experiment::Engines)
      throw Error(ErrorKind::BadArgument, "--engine", "",
                  "experiment '" + n + "' is the eigenwalker's (Zhang & Troje 2007); the other engines' are "
                  "'snippet' and 'engines' (every engine) and 'snippet-clusters' (the snippet prior)");
    if (e && *e == Experiment::SnippetClusters && !asksFor(a, EngineKind::Snippet))
      throw Error(ErrorKind::BadArgument, "--engine", "", "experiment 'snippet-clusters' is the snippet prior's");
  }
  return a.experiments;
}

EvaluationOptions evaluationOptions(const EvaluateArgs& a, ProgressPrinter& printer) {
  EvaluationOptions o;
  o.anglesDeg = parseAngleSpec(a.angles.empty() ? "-90:90:1" : a.angles);
  o.lsq = a.method != "map";
  o.map = a.method != "lsq";
  if (a.sigma2Mm2 > 0) o.sigma2Mm2 = a.sigma2Mm2;
  if (a.components > 0) o.model.components = a.components;
  o.cameraSkeleton = asksFor(a, EngineKind::Skeleton);
  o.cameraSnippet = asksFor(a, EngineKind::Snippet);
  o.cameraDetectorHipOffsetMm = a.detectorHipOffsetMm;
  o.cameraAllowForDetectorOffsets = !a.noDetectorOffsets;
  o.cameraWideFactors = a.factors;
  if (!a.keepClips.empty()) o.keepClipsDir = a.keepClips;
  if (a.cameras > 0) o.cameraWideCameras = a.cameras;
  o.threads = a.threads > 0 ? a.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  o.progress = [&printer](int done, int total, const std::string& what) { printer(done, total, what); };
  return o;
}

void printHeadline(const EvaluationResults& r, const fs::path& out) {
  std::cerr << std::fixed << std::setprecision(1) << r.walkers << " walkers, " << r.subjects << " subjects, N = "
            << r.components << " components (95 %: " << r.components95 << ")";
  if (r.sigma2OptMm2) std::cerr << ", sigma2 optimum " << *r.sigma2OptMm2 << " mm2";
  std::cerr << "\n";
  for (const auto& [name, s] : r.timingsS) std::cerr << "  " << name << ": " << std::setprecision(2) << s << " s\n";
  for (const auto& w : r.warnings) std::cerr << "warning: " << w << "\n";
  std::cerr << "wrote " << out.string() << "\n";
}

std::vector<EngineKind> enginesAskedFor(const EvaluateArgs& a) {
  std::vector<EngineKind> kinds;
  for (EngineKind k : {EngineKind::Eigenwalker, EngineKind::Snippet, EngineKind::Skeleton})
    if (asksFor(a, k)) kinds.push_back(k);
  return kinds;
}

// Experiment "engines" (engines_experiment.h): the eigenwalker folds of the camera setting
// are built here, like the paper's experiments build theirs.
void runEnginesExperiment(const Dataset& dataset, const std::vector<Walker>& walkers, const EvaluateArgs& a,
                          int threads, EvaluationResults& results) {
  const auto t0 = std::chrono::steady_clock::now();
  EnginesExperimentOptions o;
  o.threads = threads;
  o.engines = enginesAskedFor(a);
  if (!a.angles.empty()) o.anglesDeg = parseAngleSpec(a.angles);
  if (a.cameras > 0) o.camerasPerWalker = a.cameras;
  if (!a.keepClips.empty()) o.keepClipsDir = a.keepClips;
  if (a.sigma2Mm2 > 0) o.sigma2Mm2 = a.sigma2Mm2;
  if (a.components > 0) o.model.components = a.components;
  if (a.clusters > 0) o.prior.clusters = a.clusters;
  if (a.clusterComponents > 0) o.prior.components = a.clusterComponents;
  const std::vector<ExperimentWalker> experimentSet = experimentWalkers(walkers, dataset);
  std::cerr << "engines: " << dataset.subjects().size() << " folds on " << threads << " threads\n";
  const std::vector<Fold> folds = buildFolds(experimentSet, o.model, threads);
  results.engines = compareEngines(dataset, walkers, experimentSet, folds, o);
  results.warnings.insert(results.warnings.end(), results.engines.warnings.begin(), results.engines.warnings.end());
  results.ran.insert(Experiment::Engines);
  results.timingsS.emplace_back("engines", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

// Experiment "semantic" (semantic_experiment.h): the walkers' attributes as axes in gait space.
void runSemanticExperiment(const std::vector<Walker>& walkers, const EvaluateArgs& a, int threads,
                           EvaluationResults& results) {
  const auto t0 = std::chrono::steady_clock::now();
  SemanticExperimentOptions o;
  o.threads = threads;
  if (!a.angles.empty()) o.anglesDeg = parseAngleSpec(a.angles);
  if (a.sigma2Mm2 > 0) o.sigma2Mm2 = a.sigma2Mm2;
  if (a.components > 0) o.model.components = a.components;
  std::cerr << "semantic: " << walkers.size() << " walkers on " << threads << " threads\n";
  results.semantic = semanticExperiment(walkers, o);
  for (const auto& n : results.semantic.notes) results.warnings.push_back("semantic: " + n);
  results.ran.insert(Experiment::Semantic);
  results.timingsS.emplace_back("semantic", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

// The snippet engine's experiments (snippet_experiment.h) learn from the dataset's trials.
void runSnippetExperiments(const Dataset& dataset, const std::vector<Walker>& walkers,
                           const std::set<Experiment>& experiments, const EvaluateArgs& a, EvaluationResults& results) {
  const int threads = a.threads > 0 ? a.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (experiments.count(Experiment::Snippet)) {
    const auto t0 = std::chrono::steady_clock::now();
    SnippetExperimentOptions o;
    o.threads = threads;
    if (!a.engines.empty()) {
      o.engines.clear();
      for (const auto& e : a.engines) o.engines.push_back(parseEngineKind(e, "--engine"));
    }
    if (a.sigma2Mm2 > 0) o.sigma2Mm2 = a.sigma2Mm2;
    if (a.components > 0) o.model.components = a.components;
    if (a.clusters > 0) o.prior.clusters = a.clusters;
    if (a.clusterComponents > 0) o.prior.components = a.clusterComponents;
    std::cerr << "snippet: " << dataset.subjects().size() << " folds on " << threads << " threads\n";
    results.snippet = snippetComparison(dataset, walkers, o);
    results.warnings.insert(results.warnings.end(), results.snippet.warnings.begin(), results.snippet.warnings.end());
    results.ran.insert(Experiment::Snippet);
    results.timingsS.emplace_back("snippet", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (experiments.count(Experiment::SnippetClusters)) {
    const auto t0 = std::chrono::steady_clock::now();
    SnippetPriorOptions base;
    if (a.clusterComponents > 0) base.components = a.clusterComponents;
    results.snippetClusters = chooseSnippetClusters(dataset, {1, 2, 4, 8, 16, 32}, base, 5, threads);
    results.ran.insert(Experiment::SnippetClusters);
    results.timingsS.emplace_back("snippet-clusters",
                                  std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  if (experiments.count(Experiment::Engines)) runEnginesExperiment(dataset, walkers, a, threads, results);
  if (experiments.count(Experiment::Semantic)) runSemanticExperiment(walkers, a, threads, results);
}

int runEvaluate(const EvaluateArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  const fs::path out = folderPathWithoutTrailingSeparator(a.out);  // "results/" is "results"
  if (out.filename().empty() || out.filename() == "." || out.filename() == "..") {
    throw Error(ErrorKind::BadArgument, "--out", "", "must name a folder, got '" + a.out + "'");
  }
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec)) {
    throw Error(ErrorKind::BadArgument, out.string(), "", "exists and is not a folder");
  }
  const std::set<Experiment> experiments = chosenExperiments(experimentsForEngines(a));
  ProgressPrinter printer;
  const EvaluationOptions options = evaluationOptions(a, printer);

  const std::vector<fs::path> paths(a.data.begin(), a.data.end());
  const Dataset dataset = loadDataset(paths, {}, [&printer](int done, int total, const std::string&) {
    printer(done, total, "load");
  });
  std::vector<std::string> warnings = dataset.warnings;
  const std::vector<Walker> walkers = makeWalkers(dataset, &warnings);
  for (const auto& w : warnings) std::cerr << "warning: " << w << "\n";
  if (walkers.empty()) throwBadData(a.data.front(), "", "no usable walker in the data");
  const double loadS = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  std::set<Experiment> eigenwalkerExperiments = experiments;
  eigenwalkerExperiments.erase(Experiment::Snippet);
  eigenwalkerExperiments.erase(Experiment::SnippetClusters);
  eigenwalkerExperiments.erase(Experiment::Engines);
  eigenwalkerExperiments.erase(Experiment::Semantic);
  EvaluationResults results = runEvaluation(experimentWalkers(walkers, dataset), eigenwalkerExperiments, options);
  runSnippetExperiments(dataset, walkers, experiments, a, results);
  results.timingsS.insert(results.timingsS.begin(), {"load", loadS});
  EvaluationProvenance provenance{commandLine(), {}};
  for (const auto& t : dataset.trials) provenance.dataFiles.push_back(t.info.file);
  ResultsFolderOptions folder;
#ifdef EW_HAVE_PLOTS
  if (!a.noPlots) folder.plots = rasterPlotWriter();
#endif
  writeResultsFolder(out, results, provenance, folder);
  printHeadline(results, out);
  std::cerr << "total " << std::setprecision(2)
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() << " s\n";
  return 0;
}

}  // namespace

void addEvaluateCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<EvaluateArgs>();
  auto* cmd = app.add_subcommand(
      "evaluate",
      "Leave-one-subject-out evaluation (Zhang & Troje 2007; docs/METHOD.md §7-8). Writes into DIR:\n"
      "  harmonics.csv      walker,subject,source,stride_hz,h1_share,h2_share,residual_share\n"
      "  variance.csv       component,eigenvalue_mm2,variance_share,cumulative_share\n"
      "  sigma_sweep.csv    sigma2_mm2,method,mean_abs_error_mm2,mean_rel_error,mpjpe_mm\n"
      "  known_view.csv     subject,angle_deg,method,abs_error_mm2,rel_error,var_missing_mm2,mpjpe_mm\n"
      "  unknown_view.csv   subject,true_angle_deg,method,est_angle_deg,angle_error_deg,abs_error_mm2,mpjpe_mm\n"
      "  noise.csv          subject,noise_mm,angle_deg,method,abs_error_mm2,rel_error,var_missing_mm2,mpjpe_mm\n"
      "  missing_joints.csv subject,missing,angle_deg,method,abs_error_mm2,rel_error,var_missing_mm2,mpjpe_mm\n"
      "  lower_body.csv     subject,walker,estimated_joint,method,mpjpe_mm (pelvis, hips, knees, ankles kept in\n"
      "                     3D; the other joints estimated from the model; method map, lsq or mean = baseline)\n"
      "  camera.csv         one row per held-out walker x random camera x pixel noise: the clip written as\n"
      "                     OpenPose JSON, read back and reconstructed with everything unknown (--experiment\n"
      "                     camera only, not in all; docs/CAMERA.md); beside it the skeleton and snippet\n"
      "                     engines given the true camera (skeleton_*, snippet_* columns; --engine narrows)\n"
      "  camera_wide.csv    the camera experiment widened (issue 55; --experiment camera-wide only): the\n"
      "                     eigenwalker alone at 2 px, one factor changed at a time (clip length in strides,\n"
      "                     walker height in px, speed, layout, fps, elevation, image size known, where the\n"
      "                     camera aims, focal length known, points off the picture dropped, the scene's\n"
      "                     horizon read off a video) and all at their hardest;\n"
      "                     camera_wide_summary.csv per factor and level: refusals, MPJPE, the camera's\n"
      "                     elevation, the walker's view elevation and the distance errors, and how often\n"
      "                     the fit's SDs hold the truth (--factor narrows, --cameras per walker;\n"
      "                     docs/CAMERA.md)\n"
      "  snippet_engines.csv subject,clip,angle_deg,engine,frames,mpjpe_mm,depth_error_mm2,error,seconds: the snippet engine\n"
      "                     (Howe, Leventon & Freeman 1999) beside the eigenwalker on the same 2D frames; clip is\n"
      "                     trial, 0.5 s or whole trial (--experiment snippet only; docs/SNIPPETS.md)\n"
      "  snippet_phase.csv  angle_deg,engine,phase_bin,mpjpe_mm,frames: per-frame error over the gait cycle\n"
      "  snippet_theta.csv  subject,angle_deg,snippet,true_deg,estimated_deg,error_deg,clip_estimate_deg: unknown view\n"
      "  gait_agreement.csv subject,engine,angle_deg,measure,mocap,reconstructed: gait measures of each engine's\n"
      "                     reconstruction beside the motion capture's (--experiment snippet; docs/GAIT.md)\n"
      "  gait_bland_altman.csv engine,angle_deg,measure,unit,pairs,unmeasured,mocap_mean,bias,sd,loa_low,loa_high,\n"
      "                     mean_abs_difference: their agreement (Bland-Altman)\n"
      "  snippet_clusters.csv clusters,held_out_log_likelihood,em_held_out_log_likelihood (--experiment\n"
      "                     snippet-clusters only)\n"
      "  engines.csv        setting,subject,engine,variant,angle_deg,camera,noise,noise_unit,frames,mpjpe_mm,\n"
      "                     depth_error_mm2,seconds,error: every engine on the same held-out walkers, views\n"
      "                     (orthographic, 2D noise in mm; --angles, default 0,30,60,90) and random cameras\n"
      "                     (OpenPose JSON, noise in px; --cameras per walker, default 3) (--experiment engines\n"
      "                     only; docs/RESULTS.md); engines_summary.csv per setting, engine, variant and noise:\n"
      "                     clips, failures, mean and median MPJPE, seconds per clip, ms per frame;\n"
      "                     engines_gait_agreement.csv and engines_gait_bland_altman.csv the gait measures'\n"
      "                     agreement per setting, view and noise\n"
      "  semantic_axes.csv  attribute,label,source,kind,walkers,mean,sd,loo_r2,loo_rmse,loo_accuracy,chance,gain,\n"
      "                     steerable,slider_measured_change,slider_ratio: each attribute of the walkers (manifest\n"
      "                     columns, measured gait) as an axis in gait space, leave one subject out (--experiment\n"
      "                     semantic only; docs/SEMANTIC.md); semantic_views.csv and semantic_views_summary.csv the\n"
      "                     attributes predicted from one 2D view (--angles, default 0:90:15; known and searched view)\n"
      "  summary.json, fig*.png. DIR is written to a temporary sibling and renamed into place.");
  cmd->add_option("--data", args->data, "Trial files, folders (recursive) or manifest CSVs")->required();
  cmd->add_option("--out", args->out, "Output folder (replaced only after success)")->required();
  cmd->add_option("--experiment", args->experiments,
                  "variance, sigma-sweep, known-view, unknown-view, noise, missing-joints, lower-body, camera, "
                  "camera-wide, snippet, "
                  "snippet-clusters, engines, semantic or all "
                  "(repeat or comma-separate)")
      ->delimiter(',')
      ->check(CLI::IsMember({"variance", "sigma-sweep", "known-view", "unknown-view", "noise", "missing-joints", "lower-body", "camera", "camera-wide", "snippet", "snippet-clusters", "engines", "semantic", "all"}))
      ->capture_default_str();
  cmd->add_option("--angles", args->angles,
                  "View angles in degrees: FROM:TO:STEP or a list a,b,c (default -90:90:1; experiment 'engines' "
                  "0,30,60,90)");
  cmd->add_option("--detector-hip-offset", args->detectorHipOffsetMm,
                  "Experiment 'camera': the simulated detector puts each hip this many mm out from its joint centre "
                  "(default: the keypoint tables' offset, docs/KEYPOINTS.md \"Detector hips\")")
      ->check(finiteIn(-200.0, 200.0));
  cmd->add_flag("--no-detector-offsets", args->noDetectorOffsets,
                "Experiment 'camera': read the clips taking the detector's hips for joint centres");
  cmd->add_option("--cameras", args->cameras,
                  "Experiments 'engines' and 'camera-wide': random cameras per held-out walker (default 3)")
      ->check(finiteIn(1, 100));
  cmd->add_option("--keep-clips", args->keepClips,
                  "Experiments 'camera', 'engines' and 'camera-wide' (a folder per level): keep each clip's keypoint "
                  "file(s) in this folder, as SUBJECT_cameraK_Npx/ (open one with the viewer or reconstruct "
                  "--unknown-camera)");
  cmd->add_option("--factor", args->factors,
                  "Experiment 'camera-wide': the factors to run beside the base (repeat or comma-separate; "
                  "default all)")
      ->delimiter(',')
      ->check(CLI::IsMember({"length", "height", "speed", "layout", "fps", "elevation", "image", "aim", "focal", "edge", "horizon", "hardest"}));
  cmd->add_option("--method", args->method, "lsq, map or both")
      ->check(CLI::IsMember({"lsq", "map", "both"}))->capture_default_str();
  cmd->add_option("--sigma2", args->sigma2Mm2, "MAP noise variance in mm^2 (default: the sigma-sweep optimum)")
      ->check(kPositiveFinite);
  cmd->add_option("--components", args->components, "Eigenwalkers per model (default: 95 % of the variance)")
      ->check(finiteIn(1, 100000));
  cmd->add_option("--clusters", args->clusters,
                  "Snippet prior: mixture components m for experiment 'snippet' (default 8, docs/SNIPPETS.md)")
      ->check(finiteIn(1, 256));
  cmd->add_option("--cluster-components", args->clusterComponents,
                  "Snippet prior: principal components q per cluster (default 50, the paper's)")
      ->check(finiteIn(1, 10000));
  cmd->add_option("--threads", args->threads, "Worker threads (default: all cores)")->check(finiteIn(1, 1024));
  cmd->add_flag("--no-plots", args->noPlots, "Skip the PNG figures");
  cmd->add_option("--engine", args->engines,
                  "Engines to evaluate (repeatable; default eigenwalker and snippet): eigenwalker runs the "
                  "paper's experiments, snippet the snippet engine's ('snippet', 'snippet-clusters'), skeleton "
                  "(Zou et al. 2009, with each walker's own bone lengths) experiment 'snippet'; experiments "
                  "'snippet', 'engines' and 'camera' score each engine asked for ('camera' needs eigenwalker)")
      ->check(CLI::IsMember({"eigenwalker", "snippet", "skeleton"}));
  cmd->callback([args, &exitCode] {
    try {
      exitCode = runEvaluate(*args);
    } catch (const std::filesystem::filesystem_error& e) {
      throw Error(ErrorKind::Io, e.path1().string(), "", e.code().message());
    }
  });
}

}  // namespace ew::cli
