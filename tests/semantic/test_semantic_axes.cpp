// Semantic axes (core/semantic): the predictor and direction on attributes whose truth is
// known, the attribute table's rules, the slider check on the synthetic population and on the
// shared walkers, and the CLI's experiment "semantic".
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>

#include "core/common/errors.h"
#include "core/experiments/semantic_experiment.h"
#include "core/gait/dataset.h"
#include "core/semantic/semantic_axes.h"
#include "core/semantic/walker_attributes.h"
#include "core/synth/population.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

const std::vector<Walker>& syntheticWalkers() {
  static const std::vector<Walker> walkers = [] {
    PopulationOptions o;
    o.count = 30;
    return makeWalkers(syntheticDataset(o));
  }();
  return walkers;
}

WalkerAttribute numericAttribute(const std::string& name, std::vector<double> values) {
  WalkerAttribute a;
  a.name = name;
  a.label = name;
  a.source = "test";
  a.values = std::move(values);
  return a;
}

// An attribute that is exactly linear in the walker's features: the predictor recovers it and
// a move along the axis changes the prediction by gain · Δ with a gain of nearly 1.
TEST(SemanticAxes, AnAttributeLinearInTheWalkerIsPredictedAndSteered) {
  const auto& walkers = syntheticWalkers();
  const EigenwalkerModel model = buildModel(walkers);
  const AxisWalkers aw = axisWalkers(model, walkers);
  std::vector<double> values;
  for (Eigen::Index r = 0; r < aw.k.cols(); ++r)
    values.push_back(1.5 + 0.002 * aw.k(0, r) - 0.004 * aw.k(2, r) + 0.1 * aw.omegaRadS(r));
  const SemanticAxis axis = fitSemanticAxis(numericAttribute("linear", values), model.eigenvalues, aw);
  double worst = 0.0;
  for (Eigen::Index r = 0; r < aw.k.cols(); ++r)
    worst = std::max(worst, std::abs(predictAttribute(axis, aw.k.col(r), aw.omegaRadS(r)) - values[static_cast<size_t>(r)]));
  EXPECT_LT(worst, 0.02 * axis.sd) << "ridge " << axis.ridge;
  EXPECT_GT(axis.gain, 0.98);
  EXPECT_TRUE(axis.steerable);
  const Eigen::VectorXd k0 = aw.k.col(3);
  const double before = predictAttribute(axis, k0, aw.omegaRadS(3));
  const double after = predictAttribute(axis, k0 + 0.5 * axis.directionK, aw.omegaRadS(3) + 0.5 * axis.directionOmega);
  EXPECT_NEAR(after - before, 0.5 * axis.gain, 1e-9);
}

TEST(SemanticAxes, NoiseIsNotPredictedAndATwoClassSplitIs) {
  const auto& walkers = syntheticWalkers();
  ModelOptions options;
  const std::vector<AxisFold> folds = axisFolds(walkers, options);
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  std::vector<double> noise;
  for (size_t r = 0; r < walkers.size(); ++r) noise.push_back(normal(rng));
  const AxisQuality q = leaveOneSubjectOut(numericAttribute("noise", noise), walkers, folds);
  EXPECT_EQ(q.walkers, static_cast<int>(walkers.size()));
  EXPECT_LT(q.r2, 0.2);

  // Two classes of leg length (a body size the walker shows plainly): short and long, the
  // walkers within 15 mm of the median (about 0.4 SD) left unlabelled as ambiguous.
  const AttributeTable table = walkerAttributes(walkers);
  const WalkerAttribute* leg = table.find("leg_length_m");
  ASSERT_NE(leg, nullptr);
  std::vector<double> sorted = leg->values;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2), sorted.end());
  const double median = sorted[sorted.size() / 2];
  WalkerAttribute longLegs = numericAttribute("long_legs", {});
  longLegs.categorical = true;
  longLegs.classes = {"short", "long"};
  for (double v : leg->values) longLegs.values.push_back(std::abs(v - median) < 0.015 ? NAN : v > median ? 1.0 : 0.0);
  const AxisQuality c = leaveOneSubjectOut(longLegs, walkers, folds);
  EXPECT_GE(c.walkers, 15);
  EXPECT_GE(c.accuracy, 0.85);
  EXPECT_LT(c.chance, 0.7);
  EXPECT_TRUE(std::isnan(c.r2));
}

TEST(SemanticAxes, TooFewOrEqualValuesAreNamedErrors) {
  const auto& walkers = syntheticWalkers();
  const EigenwalkerModel model = buildModel(walkers);
  const AxisWalkers aw = axisWalkers(model, walkers);
  std::vector<double> two(walkers.size(), NAN);
  two[0] = 1.0;
  two[1] = 2.0;
  try {
    fitSemanticAxis(numericAttribute("sparse", two), model.eigenvalues, aw);
    FAIL() << "two values fitted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("semantic axis sparse: 2 walkers have a value"), std::string::npos) << e.what();
  }
  try {
    fitSemanticAxis(numericAttribute("flat", std::vector<double>(walkers.size(), 3.0)), model.eigenvalues, aw);
    FAIL() << "a constant fitted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("every walker has the same value"), std::string::npos) << e.what();
  }
  EXPECT_THROW(fitSemanticAxis(numericAttribute("short", {1.0, 2.0, 3.0}), model.eigenvalues, aw), Error);
}

TEST(SemanticAxes, ManifestColumnsBecomeNumericOrTwoClassAttributes) {
  std::vector<Walker> walkers(syntheticWalkers().begin(), syntheticWalkers().begin() + 6);
  const std::vector<std::string> sex{"F", "M", "F", "M", "M", "F"};
  const std::vector<std::string> group{"a", "b", "c", "a", "b", "c"};
  for (size_t i = 0; i < walkers.size(); ++i) {
    walkers[i].attributes = {{"sex", sex[i]}, {"group", group[i]}, {"site", "lab"},
                             {"mass_kg", i == 2 ? "NaN" : std::to_string(60 + i)},
                             {"knee_loading_deg", std::to_string(10 + i)}};
    if (i == 0) walkers[i].attributes["odd"] = "x";
    if (i > 0) walkers[i].attributes["odd"] = "y";
  }
  const AttributeTable table = walkerAttributes(walkers);
  const WalkerAttribute* s = table.find("sex");
  ASSERT_NE(s, nullptr);
  EXPECT_TRUE(s->categorical);
  EXPECT_EQ(s->lowWord, "female");
  EXPECT_EQ(s->highWord, "male");
  EXPECT_EQ(s->values[1], 1.0);
  const WalkerAttribute* mass = table.find("mass_kg");
  ASSERT_NE(mass, nullptr);
  EXPECT_FALSE(mass->categorical);
  EXPECT_EQ(mass->highWord, "heavier");
  EXPECT_TRUE(std::isnan(mass->values[2]));  // "NaN" is no value, not a class
  EXPECT_EQ(mass->known(), 5);
  // A column the field has no words for is read from its name and its unit's suffix.
  const WalkerAttribute* loading = table.find("knee_loading_deg");
  ASSERT_NE(loading, nullptr);
  EXPECT_EQ(loading->label, "knee loading (°)");
  EXPECT_EQ(loading->highWord, "more knee loading");
  EXPECT_EQ(table.find("group"), nullptr);
  EXPECT_EQ(table.find("site"), nullptr);
  EXPECT_EQ(table.find("odd"), nullptr);
  std::string notes;
  for (const auto& n : table.notes) notes += n + "\n";
  EXPECT_NE(notes.find("group: 3 classes"), std::string::npos) << notes;
  EXPECT_NE(notes.find("site: every walker has the same value"), std::string::npos) << notes;
  EXPECT_NE(notes.find("odd: class 'x' has a single walker"), std::string::npos) << notes;
  for (const auto& name : measuredAttributeNames()) EXPECT_NE(table.find(name), nullptr) << name;
}

// The bar: +1 SD on the speed axis changes the synthesised walker's measured speed by
// +1 SD within 10 %; the generating attributes' quality on the synthetic population.
TEST(SemanticAxes, TheSyntheticPopulationsSpeedAxisMovesMeasuredSpeedByWhatItSays) {
  SemanticExperimentOptions o;
  o.anglesDeg = {0.0, 90.0};
  o.unknownView = false;
  o.threads = 2;
  const SemanticExperimentResults r = semanticExperiment(syntheticWalkers(), o);
  const auto row = [&](const std::string& name) {
    for (const auto& a : r.axes)
      if (a.attribute == name) return a;
    ADD_FAILURE() << "no axis " << name;
    return SemanticAxisRow{};
  };
  EXPECT_NEAR(row("measured_speed_mps").sliderRatio, 1.0, 0.10);
  EXPECT_NEAR(row("measured_height_m").sliderRatio, 1.0, 0.10);
  EXPECT_GT(row("height_m").looR2, 0.8);
  EXPECT_GT(row("speed_mps").looR2, 0.7);
  EXPECT_GT(row("female").looAccuracy, row("female").chance);
  ASSERT_FALSE(r.viewSummary.empty());
  for (const auto& s : r.viewSummary)
    if (s.attribute == "height_m") {
      EXPECT_LT(s.rmse2d, 0.6 * s.sd) << s.angleDeg;
    }
}

TEST(SemanticAxes, TheSharedWalkersSpeedAxisMovesMeasuredSpeedByWhatItSays) {
  EW_REQUIRE_SHARED_DATA();
  const std::vector<Walker> walkers = makeWalkers(loadDataset({test::sharedDataDir() / "walkers.csv"}));
  SemanticExperimentOptions o;
  o.anglesDeg = {90.0};
  o.threads = 2;
  const SemanticExperimentResults r = semanticExperiment(walkers, o);
  for (const auto& a : r.axes) {
    if (a.attribute == "measured_speed_mps") {
      EXPECT_NEAR(a.sliderRatio, 1.0, 0.10);
      EXPECT_GT(a.looR2, 0.7);
    }
    if (a.attribute == "measured_height_m") {
      EXPECT_GT(a.looR2, 0.8);
    }
  }
  for (const auto& s : r.viewSummary)
    if (s.attribute == "measured_speed_mps" && s.view == "known") {
      EXPECT_LT(s.rmse2d, 0.5 * s.sd);
    }
}

TEST(SemanticAxes, TheCliWritesTheSemanticExperiment) {
  const fs::path dir = test::makeTempDir("semantic_cli");
  const fs::path data = dir / "population";
  ASSERT_EQ(test::runProgram(EW_CLI_PATH, {"synth", "--out", data.string(), "--count", "12"}, dir).exitCode, 0);
  const auto run = test::runProgram(EW_CLI_PATH,
                                    {"evaluate", "--data", (data / "walkers.csv").string(), "--out", (dir / "out").string(),
                                     "--experiment", "semantic", "--angles", "0,90", "--threads", "2"},
                                    dir);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  for (const char* f : {"semantic_axes.csv", "semantic_views.csv", "semantic_views_summary.csv", "summary.json"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  const auto summary = nlohmann::json::parse(test::readTextFile(dir / "out" / "summary.json"));
  ASSERT_TRUE(summary.contains("semantic"));
  EXPECT_GE(summary["semantic"]["axes"].size(), 10u);
  const std::string views = test::readTextFile(dir / "out" / "semantic_views_summary.csv");
  EXPECT_NE(views.find("height_m,numeric,known,90,12,"), std::string::npos) << views.substr(0, 400);
}

}  // namespace
}  // namespace ew
