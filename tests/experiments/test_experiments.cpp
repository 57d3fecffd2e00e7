// core/experiments: the leave-one-subject-out evaluation on populations whose walkers lie
// in a low-dimensional affine subspace (every held-out walker is a combination of the
// others' eigenwalkers, so LSQ must reconstruct it exactly), the CSV schemas, summary.json
// and the never-half-written output folder.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "core/common/errors.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/synthetic_walkers.h"
#include "core/experiments/experiments.h"
#include "plots/raster_plot.h"
#include "core/experiments/results_folder.h"
#include "core/experiments/view_csv.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

constexpr double kOmega = 2.0 * std::numbers::pi * 0.9;  // 0.9 strides per second
constexpr double kRateHz = 60.0;

// `subjects` walkers w = base + B c with B of `dims` phase-aligned directions and small
// random c: the centred walkers span `dims` dimensions, so with more subjects than
// dimensions every held-out walker lies in the span of the other walkers' model.
// `outlier` > 0 pushes the last walker out of the span by that many mm (a control).
std::vector<ExperimentWalker> subspacePopulation(int subjects, int dims, double outlier = 0.0) {
  const Eigen::VectorXd base = syntheticBaseWalker();
  const Eigen::MatrixXd others = syntheticWalkerSet(dims, 11);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coef(-0.5, 0.5);
  std::vector<ExperimentWalker> walkers;
  for (int s = 0; s < subjects; ++s) {
    Eigen::VectorXd w = base;
    for (int d = 0; d < dims; ++d) w += coef(rng) * (others.col(d) - base);
    if (outlier > 0 && s == subjects - 1) w(2 * 75 + 3 * 3) += outlier;  // q1, r_shoulder x
    ExperimentWalker e;
    e.subject = "S" + std::to_string(s);
    e.id = e.subject + "/test";
    e.source = "synthetic";
    e.fit.w = w;
    e.fit.omegaRadS = kOmega;
    e.fit.h1Share = 0.9;
    e.fit.h2Share = 0.1;
    e.rateHz = kRateHz;
    e.framesMm = synthesizeFrames(w, kOmega, 0.0, frameTimes(2 * 67, kRateHz));  // 2 cycles
    walkers.push_back(e);
  }
  return walkers;
}

EvaluationOptions smallOptions() {
  EvaluationOptions o;
  o.anglesDeg = {-90, -35, 0, 20, 90};
  o.sigma2GridMm2 = {10, 100, 1000};
  o.noiseLevelsMm = {0.0, 20.0};
  o.missingJointSets = {{"l_wrist", {8}}, {"both_arms", {4, 5, 7, 8}}};
  o.model.components = 3;
  o.threads = 2;
  return o;
}

TEST(Experiments, InSpanWalkersReconstructExactlyWithLsq) {
  const auto walkers = subspacePopulation(8, 3);
  const std::set<Experiment> all(allExperiments().begin(), allExperiments().end());
  const EvaluationResults r = runEvaluation(walkers, all, smallOptions());
  EXPECT_EQ(r.walkers, 8);
  EXPECT_EQ(r.subjects, 8);
  EXPECT_EQ(r.ran.size(), all.size());
  ASSERT_EQ(r.knownView.size(), 8u * 5u * 2u);
  for (const auto& row : r.knownView) {
    EXPECT_GT(row.varMissingMm2, 1.0);
    if (row.method != "lsq") continue;
    EXPECT_LT(row.absErrorMm2, 1e-8) << row.subject << " at " << row.angleDeg;
    EXPECT_LT(row.mpjpeMm, 1e-5) << row.subject << " at " << row.angleDeg;
  }
  for (const auto& row : r.unknownView) {
    if (row.method != "lsq") continue;
    EXPECT_LT(row.angleErrorDeg, 0.01) << row.subject << " at " << row.trueAngleDeg;
    EXPECT_LT(row.absErrorMm2, 1e-4) << row.subject << " at " << row.trueAngleDeg;
  }
  for (const auto& row : r.missingJoints) {
    if (row.method == "lsq") { EXPECT_LT(row.absErrorMm2, 1e-8) << row.condition << " " << row.angleDeg; }
  }
  for (const auto& row : r.noise) {
    if (row.method == "lsq" && row.condition == "0") { EXPECT_LT(row.absErrorMm2, 1e-6) << row.angleDeg; }
    if (row.condition == "20") { EXPECT_GT(row.absErrorMm2, 1e-3) << row.angleDeg; }  // noise must show
  }
  for (const auto& row : r.sigmaSweep) {
    if (row.method == "lsq") { EXPECT_LT(row.meanAbsErrorMm2, 1e-8); }
    if (row.method == "map") { EXPECT_GT(row.meanAbsErrorMm2, 0.0); }  // the prior shrinks
  }
  ASSERT_TRUE(r.sigma2OptMm2.has_value());
  EXPECT_EQ(r.sigma2UsedMm2, *r.sigma2OptMm2);
  // The sweep's smallest σ² is best for in-span data (the prior only hurts): at the edge.
  EXPECT_EQ(*r.sigma2OptMm2, 10.0);
  EXPECT_TRUE(r.sigma2OptAtGridEdge);
}

TEST(Experiments, AWalkerOutsideTheSpanHasErrors) {
  const auto walkers = subspacePopulation(8, 3, 80.0);
  EvaluationOptions o = smallOptions();
  o.map = false;
  const EvaluationResults r = runEvaluation(walkers, {Experiment::KnownView}, o);
  double inSpan = 0, outlier = 0;
  for (const auto& row : r.knownView) (row.subject == "S7" ? outlier : inSpan) += row.absErrorMm2;
  EXPECT_GT(outlier, 10.0);
  // The outlier also moves the others' models off their span: errors, but smaller.
  EXPECT_LT(inSpan / 7.0, outlier);
  EXPECT_TRUE(r.sigmaSweep.empty());  // LSQ only: no σ² needed
}

TEST(Experiments, ResultsAreTheSameOnOneAndTwoThreads) {
  const auto walkers = subspacePopulation(6, 3, 40.0);
  EvaluationOptions o = smallOptions();
  o.sigma2Mm2 = 100.0;
  const std::set<Experiment> e = {Experiment::KnownView, Experiment::Noise};
  o.threads = 1;
  const auto one = runEvaluation(walkers, e, o);
  o.threads = 2;
  const auto two = runEvaluation(walkers, e, o);
  EXPECT_EQ(knownViewCsv(one.knownView), knownViewCsv(two.knownView));
  EXPECT_EQ(noiseCsv(one.noise), noiseCsv(two.noise));
}

TEST(Experiments, VarianceTableAndHarmonics) {
  const auto walkers = subspacePopulation(8, 3, 30.0);
  const EvaluationResults r = runEvaluation(walkers, {Experiment::Variance}, smallOptions());
  ASSERT_EQ(r.variance.size(), 7u);  // R − 1 eigenvalues
  EXPECT_NEAR(r.variance.back().cumulativeShare, 1.0, 1e-12);
  for (size_t i = 1; i < r.variance.size(); ++i) {
    EXPECT_LE(r.variance[i].eigenvalueMm2, r.variance[i - 1].eigenvalueMm2 * (1 + 1e-12));
  }
  EXPECT_EQ(r.components95, componentsForShare(r.variance, 0.95));
  EXPECT_LE(r.components95, 4);  // 3 directions + the outlier
  ASSERT_EQ(r.harmonics.size(), 8u);
  EXPECT_NEAR(r.harmonics[0].strideHz, 0.9, 1e-12);
  EXPECT_TRUE(r.knownView.empty());
}

TEST(Experiments, TooFewSubjectsIsBadData) {
  const auto walkers = subspacePopulation(2, 1);
  try {
    runEvaluation(walkers, {Experiment::KnownView}, smallOptions());
    FAIL() << "expected Error(BadData)";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadData);
    EXPECT_NE(std::string(e.what()).find("at least 3 subjects"), std::string::npos) << e.what();
  }
}

TEST(Experiments, AngleSpecs) {
  EXPECT_EQ(parseAngleSpec("-90:90:1").size(), 181u);
  EXPECT_EQ(parseAngleSpec("-90:90:1").back(), 90.0);
  EXPECT_EQ(parseAngleSpec("0:90:30"), (std::vector<double>{0, 30, 60, 90}));
  EXPECT_EQ(parseAngleSpec("0,45,-30.5"), (std::vector<double>{0, 45, -30.5}));
  for (const char* bad : {"", "1:0:1", "0:10:0", "0:10", "a,b", "0:1e9:0.001", "10,"}) {
    EXPECT_THROW(parseAngleSpec(bad), Error) << bad;
  }
}

// [SECTION] Files

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string firstLine(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  return line;
}

TEST(ResultsFolder, HeadersSummaryAndFigures) {
  const fs::path tmp = test::makeTempDir("results_folder");
  const auto walkers = subspacePopulation(6, 3, 20.0);
  const std::set<Experiment> all(allExperiments().begin(), allExperiments().end());
  const EvaluationResults r = runEvaluation(walkers, all, smallOptions());
  ResultsFolderOptions withFigures;
  withFigures.plots = rasterPlotWriter();
  const auto names = writeResultsFolder(tmp / "out", r, {"eigenwalker-cli evaluate …", {"a.c3d"}}, withFigures);
  const fs::path out = tmp / "out";
  EXPECT_EQ(firstLine(out / "harmonics.csv"), "walker,subject,source,stride_hz,h1_share,h2_share,residual_share");
  EXPECT_EQ(firstLine(out / "variance.csv"), "component,eigenvalue_mm2,variance_share,cumulative_share");
  EXPECT_EQ(firstLine(out / "sigma_sweep.csv"), "sigma2_mm2,method,mean_abs_error_mm2,mean_rel_error,mpjpe_mm");
  EXPECT_EQ(firstLine(out / "known_view.csv"),
            "subject,angle_deg,method,abs_error_mm2,rel_error,var_missing_mm2,mpjpe_mm");
  EXPECT_EQ(firstLine(out / "unknown_view.csv"),
            "subject,true_angle_deg,method,est_angle_deg,angle_error_deg,abs_error_mm2,mpjpe_mm");
  EXPECT_EQ(firstLine(out / "noise.csv"),
            "subject,noise_mm,angle_deg,method,abs_error_mm2,rel_error,var_missing_mm2,mpjpe_mm");
  EXPECT_EQ(firstLine(out / "missing_joints.csv"),
            "subject,missing,angle_deg,method,abs_error_mm2,rel_error,var_missing_mm2,mpjpe_mm");
  EXPECT_EQ(firstLine(out / "lower_body.csv"), "subject,walker,estimated_joint,method,mpjpe_mm");
  // One line per row plus the header.
  const std::string known = readText(out / "known_view.csv");
  EXPECT_EQ(std::count(known.begin(), known.end(), '\n'), 1 + 6 * 5 * 2);

  const auto s = nlohmann::json::parse(readText(out / "summary.json"));
  for (const char* key : {"walkers", "subjects", "components", "h1_share_mean", "h2_share_mean", "components_95",
                          "sigma2_opt_mm2", "known_view", "unknown_view", "timings_s", "command_line", "data_files"}) {
    EXPECT_TRUE(s.contains(key)) << key;
  }
  EXPECT_EQ(s["walkers"], 6);
  for (const char* m : {"lsq", "map"}) {
    for (const char* key : {"mean_abs_error_mm2", "mean_rel_error", "mpjpe_mm"}) {
      EXPECT_TRUE(s["known_view"][m].contains(key)) << m << " " << key;
    }
    EXPECT_TRUE(s["unknown_view"][m].contains("mae_deg"));
    EXPECT_TRUE(s["unknown_view"][m].contains("mae_deg_abs_le_60"));
  }
  EXPECT_TRUE(s["known_view"].contains("map_vs_lsq_reduction"));
  for (const char* m : {"lsq", "map", "mean"}) EXPECT_TRUE(s["lower_body_estimated_mpjpe_mm"][m].contains("all")) << m;
  for (const char* t : {"variance", "folds", "sigma-sweep", "known-view", "unknown-view", "noise", "missing-joints",
                        "lower-body"}) {
    EXPECT_TRUE(s["timings_s"].contains(t)) << t;
  }
  EXPECT_EQ(s["data_files"][0], "a.c3d");
  {
    for (const char* png : {"fig2_cumulative_variance.png", "fig3_sigma_sweep.png", "fig5a_abs_error.png",
                            "fig5b_rel_error.png", "fig5c_var_missing.png", "fig6_view_angle.png", "noise.png",
                            "missing_joints.png", "lower_body.png"}) {
      EXPECT_TRUE(fs::exists(out / png)) << png;
      EXPECT_GT(fs::file_size(out / png), 5000u) << png;
    }
  }
  EXPECT_EQ(std::count(names.begin(), names.end(), "summary.json"), 1);
  // Nothing left beside the folder.
  for (const auto& entry : fs::directory_iterator(tmp)) EXPECT_EQ(entry.path().filename(), "out");
  fs::remove_all(tmp);
}

TEST(ResultsFolder, AFailureMidwayLeavesTheOldFolderUntouched) {
  const fs::path tmp = test::makeTempDir("results_fail");
  const auto walkers = subspacePopulation(5, 2, 10.0);
  EvaluationOptions o = smallOptions();
  o.sigma2Mm2 = 100.0;
  const EvaluationResults r = runEvaluation(walkers, {Experiment::Variance, Experiment::KnownView}, o);
  ResultsFolderOptions failing;
  int files = 0;
  failing.afterFile = [&files](const fs::path& file) {
    if (++files == 2) throw Error(ErrorKind::Io, file.string(), "", "disk full (simulated)");
  };
  // A new folder: absent after the failure.
  EXPECT_THROW(writeResultsFolder(tmp / "new", r, {}, failing), Error);
  EXPECT_FALSE(fs::exists(tmp / "new"));
  // An existing folder: unchanged.
  fs::create_directory(tmp / "old");
  std::ofstream(tmp / "old" / "marker.txt") << "previous run";
  files = 0;
  EXPECT_THROW(writeResultsFolder(tmp / "old", r, {}, failing), Error);
  EXPECT_EQ(readText(tmp / "old" / "marker.txt"), "previous run");
  EXPECT_FALSE(fs::exists(tmp / "old" / "harmonics.csv"));
  size_t entries = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(tmp)) ++entries;
  EXPECT_EQ(entries, 1u);  // no temporary folder left behind
  // And a successful run replaces it.
  writeResultsFolder(tmp / "old", r, {}, {});
  EXPECT_FALSE(fs::exists(tmp / "old" / "marker.txt"));
  EXPECT_TRUE(fs::exists(tmp / "old" / "known_view.csv"));
  fs::remove_all(tmp);
}

TEST(ViewCsv, RoundTripAndErrors) {
  const fs::path tmp = test::makeTempDir("view_csv");
  ViewSequence s{Eigen::MatrixXd::Random(7, 30) * 500.0, 100.0};
  s.framesMm(2, 5) = std::numeric_limits<double>::quiet_NaN();
  writeViewCsv(tmp / "v.csv", s, {"test"});
  const ViewSequence back = readViewCsv(tmp / "v.csv");
  EXPECT_DOUBLE_EQ(back.rateHz, 100.0);
  ASSERT_EQ(back.framesMm.rows(), 7);
  EXPECT_TRUE(std::isnan(back.framesMm(2, 5)));
  EXPECT_NEAR(back.framesMm(3, 7), s.framesMm(3, 7), 1e-6);
  EXPECT_EQ(firstLine(tmp / "v.csv"), "# test");
  EXPECT_EQ(viewCsvHeader().substr(0, 34), "frame,time_s,head_u,head_v,sternum");
  EXPECT_TRUE(viewCsvHeader().ends_with(",l_ankle_u,l_ankle_v"));
  EXPECT_THROW(parseViewCsv("frame,time_s,head_x\n", "x.csv"), Error);
  const std::string shortRow = viewCsvHeader() + "\n0,0,1,2\n";
  try {
    parseViewCsv(shortRow, "short.csv");
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("short.csv: line 2"), std::string::npos) << e.what();
  }
  fs::remove_all(tmp);
}

}  // namespace
}  // namespace ew
