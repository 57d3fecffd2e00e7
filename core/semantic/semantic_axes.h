#pragma once
// Semantic axes in gait space (Troje 2002, J. Vision 2(5):2, "Decomposing biological motion";
// generalised from sex to any attribute the walkers have, walker_attributes.h).
//
// A walker as the axes see it: its eigenwalker coefficients k (N) in some model and its stride
// frequency ω, as features z = [k_n / √λ_1 ; (ω − ω̄) / s_ω] — the first component and ω at unit
// SD, the other components at their own smaller scale, so that the ridge shrinks the weak
// components most (ridge on whitened scores, every component at unit SD, classified a clear
// two-class split of leg length worse: 79 % against 96 % of 24 synthetic walkers). Per attribute a:
//   predictor   â = b + cᵀz: ridge regression, its ridge chosen by the closed-form
//               leave-one-out error of the training walkers (PRESS); for a two-class attribute
//               the same regression on the class indicator 0/1, which for two classes is
//               Fisher's linear discriminant (Hastie, Tibshirani & Friedman, ESL §4.3), with the
//               class boundary midway between the two classes' mean predictions.
//   direction   the population's regression of the walker on the attribute,
//               g = Σ (z_r − z̄)(a_r − ā) / Σ (a_r − ā)²: the walker that goes with one unit more
//               of a (Troje 2002's axes). Moving a walker by Δ·g is what a slider does; for a
//               measured attribute the measured change is Δ when the attribute is linear in the
//               walker (semantic_experiment.h checks it). The predictor reads that move as
//               (cᵀg)·Δ, the axis's gain: below kMinAxisGain the attribute is not predictable
//               from the walker and the axis is not steerable.
// Quality: leave one subject out, the model refitted without the subject (as every other
// experiment here), R² and RMSE of the predicted values, or the accuracy beside chance (the
// larger class's share).

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/eigenwalker/model.h"
#include "core/eigenwalker/walker_set.h"
#include "core/semantic/walker_attributes.h"

namespace ew {

inline constexpr double kMinAxisGain = 0.05;

// The walkers in one model: coefficients (N × R) and ω (R, rad/s).
struct AxisWalkers {
  Eigen::MatrixXd k;
  Eigen::VectorXd omegaRadS;
};
// The walkers projected onto the model (k = Eᵀ(w − w̄)) beside their ω.
AxisWalkers axisWalkers(const EigenwalkerModel& model, const std::vector<Walker>& walkers);

struct SemanticAxis {
  std::string attribute, label, lowWord, highWord;
  bool categorical = false;
  std::vector<std::string> classes;  // categorical: the classes of 0 and 1
  int walkers = 0;                   // with a value, used in the fit
  double mean = NAN, sd = NAN;       // of the values (categorical: of the indicator)
  // Features
  Eigen::VectorXd kScale;            // the scale of each k_n in z: √λ_1 (N)
  double omegaMean = 0.0, omegaSd = 1.0;
  // Predictor â = intercept + weightsᵀ z
  Eigen::VectorXd weights;           // N + 1
  double intercept = 0.0;
  double ridge = 0.0;                // the ridge chosen
  double threshold = 0.5;            // categorical: class 1 when â ≥ threshold
  // Direction per unit of the attribute (k in mm, ω in rad/s)
  Eigen::VectorXd directionK;        // N
  double directionOmega = 0.0;
  double gain = 0.0;                 // cᵀg: how much of a move along g the predictor reads
  bool steerable = false;
};

// Fits the axis of `attribute` over the walkers with a value. eigenvalues: the model's λ (N).
// Throws Error(BadData) "semantic axis NAME: …" for fewer than 3 walkers with a value, all
// values equal, or a class with no walker; Error(BadArgument) for inconsistent sizes.
SemanticAxis fitSemanticAxis(const WalkerAttribute& attribute, const Eigen::Ref<const Eigen::VectorXd>& eigenvalues,
                             const AxisWalkers& walkers);

// â for a walker with coefficients k (the axis's N; extra entries ignored, missing ones 0).
double predictAttribute(const SemanticAxis& axis, const Eigen::Ref<const Eigen::VectorXd>& k, double omegaRadS);
// The class index (0 or 1) of a categorical axis's prediction.
int predictedClass(const SemanticAxis& axis, double prediction);

struct AxisQuality {
  std::string attribute;
  int walkers = 0;                  // predicted (with a value)
  double r2 = NAN, rmse = NAN;      // numeric: of the leave-one-subject-out predictions
  double accuracy = NAN, chance = NAN;  // categorical
  std::vector<double> predictions;  // per walker, NaN without a value (or when its fold failed)
};

// One fold per subject: the model refitted without it, its walkers' coefficients in that model.
struct AxisFold {
  std::string subject;
  EigenwalkerModel model;
  std::vector<int> train, test;  // walker indices
  AxisWalkers trainWalkers;      // in `model`, train order
};
std::vector<AxisFold> axisFolds(const std::vector<Walker>& walkers, const ModelOptions& options, int threads = 1);

// The attribute's axis fitted in each fold and the held-out walkers predicted from their own w.
AxisQuality leaveOneSubjectOut(const WalkerAttribute& attribute, const std::vector<Walker>& walkers,
                               const std::vector<AxisFold>& folds);

// The quality of held-out predictions of `attribute` (one per walker, NaN where there is none):
// R² and RMSE, or for two classes the accuracy of `classes` (the class predicted per walker)
// beside chance. R² is taken about the mean of the walkers predicted.
AxisQuality scorePredictions(const WalkerAttribute& attribute, std::vector<double> predictions,
                             const std::vector<int>& classes);

// The training rows of `attribute` in a fold (the attribute's values at fold.train).
WalkerAttribute trainingAttribute(const WalkerAttribute& attribute, const std::vector<int>& train);

}  // namespace ew
