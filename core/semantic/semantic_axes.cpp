#include "core/semantic/semantic_axes.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "core/common/errors.h"
#include "core/common/thin_svd.h"
#include "core/experiments/leave_one_out.h"

namespace ew {
namespace {

[[noreturn]] void axisError(const std::string& attribute, const std::string& problem) {
  throw Error(ErrorKind::BadData, "", "", "semantic axis " + attribute + ": " + problem);
}

// z = [k_n / √λ_n ; (ω − ω̄) / s_ω] for each walker (rows).
Eigen::MatrixXd features(const SemanticAxis& axis, const Eigen::MatrixXd& k, const Eigen::VectorXd& omega) {
  const Eigen::Index n = axis.kScale.size();
  Eigen::MatrixXd z(k.cols(), n + 1);
  for (Eigen::Index r = 0; r < k.cols(); ++r) {
    for (Eigen::Index i = 0; i < n; ++i) z(r, i) = i < k.rows() ? k(i, r) / axis.kScale(i) : 0.0;
    z(r, n) = (omega(r) - axis.omegaMean) / axis.omegaSd;
  }
  return z;
}

// Ridge regression of centred y on centred Z, the ridge chosen by the closed-form leave-one-out
// error: with Z_c = U S Vᵀ, the hat matrix of ridge μ plus the intercept is
// H = U diag(s²/(s²+μ)) Uᵀ + 11ᵀ/n, and a walker's LOO residual is e_i / (1 − H_ii).
struct RidgeResult {
  Eigen::VectorXd weights;
  double intercept = 0.0, ridge = 0.0;
};

RidgeResult ridgeRegression(const Eigen::MatrixXd& z, const Eigen::VectorXd& y) {
  const double n = static_cast<double>(y.size());
  const Eigen::RowVectorXd zMean = z.colwise().mean();
  const Eigen::MatrixXd zc = z.rowwise() - zMean;
  const double yMean = y.mean();
  const Eigen::VectorXd yc = y.array() - yMean;
  const ThinSvd svd = thinSvd(zc);
  const Eigen::VectorXd& s = svd.singularValues;
  const Eigen::MatrixXd& u = svd.u;
  const Eigen::VectorXd uty = u.transpose() * yc;
  double bestPress = std::numeric_limits<double>::infinity();
  double bestRidge = 1.0;
  for (int step = 0; step <= 32; ++step) {
    const double mu = std::pow(10.0, -3.0 + 0.25 * step);  // 1e-3 … 1e5 in whitened units
    const Eigen::VectorXd shrink = s.array().square() / (s.array().square() + mu);
    const Eigen::VectorXd fitted = u * (shrink.asDiagonal() * uty);
    const Eigen::VectorXd leverage = (u.array().square().rowwise() * shrink.transpose().array()).rowwise().sum();
    double press = 0.0;
    for (Eigen::Index i = 0; i < y.size(); ++i) {
      const double denom = 1.0 - leverage(i) - 1.0 / n;
      if (denom < 1e-9) {
        press = std::numeric_limits<double>::infinity();
        break;
      }
      const double e = (yc(i) - fitted(i)) / denom;
      press += e * e;
    }
    if (press < bestPress) {
      bestPress = press;
      bestRidge = mu;
    }
  }
  RidgeResult out;
  out.ridge = bestRidge;
  const Eigen::VectorXd coef = (s.array() / (s.array().square() + bestRidge)).matrix().asDiagonal() * uty;
  out.weights = svd.v * coef;
  out.intercept = yMean - zMean.dot(out.weights);
  return out;
}

void checkValues(const WalkerAttribute& a, const std::vector<int>& rows) {
  if (rows.size() < 3) axisError(a.name, std::to_string(rows.size()) + " walkers have a value; an axis needs 3");
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int r : rows) {
    lo = std::min(lo, a.values[static_cast<size_t>(r)]);
    hi = std::max(hi, a.values[static_cast<size_t>(r)]);
  }
  if (!(hi > lo)) axisError(a.name, a.categorical ? "every walker is in one class" : "every walker has the same value");
}

// Threshold midway between the two classes' mean fitted values.
double classBoundary(const Eigen::VectorXd& fitted, const Eigen::VectorXd& y) {
  double sum[2] = {0, 0};
  int count[2] = {0, 0};
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    const int c = y(i) > 0.5 ? 1 : 0;
    sum[c] += fitted(i);
    ++count[c];
  }
  return 0.5 * (sum[0] / count[0] + sum[1] / count[1]);
}

}  // namespace

AxisWalkers axisWalkers(const EigenwalkerModel& model, const std::vector<Walker>& walkers) {
  AxisWalkers out;
  out.k.resize(model.componentCount(), static_cast<Eigen::Index>(walkers.size()));
  out.omegaRadS.resize(static_cast<Eigen::Index>(walkers.size()));
  for (size_t r = 0; r < walkers.size(); ++r) {
    out.k.col(static_cast<Eigen::Index>(r)) = projectOntoModel(model, walkers[r].fit.w);
    out.omegaRadS(static_cast<Eigen::Index>(r)) = walkers[r].fit.omegaRadS;
  }
  return out;
}

SemanticAxis fitSemanticAxis(const WalkerAttribute& attribute, const Eigen::Ref<const Eigen::VectorXd>& eigenvalues,
                             const AxisWalkers& walkers) {
  const Eigen::Index count = walkers.k.cols();
  if (static_cast<Eigen::Index>(attribute.values.size()) != count || walkers.omegaRadS.size() != count ||
      walkers.k.rows() != eigenvalues.size() || eigenvalues.size() == 0)
    throw Error(ErrorKind::BadArgument, "", "", "semantic axis " + attribute.name + ": inconsistent sizes");
  std::vector<int> rows;
  for (Eigen::Index r = 0; r < count; ++r)
    if (std::isfinite(attribute.values[static_cast<size_t>(r)])) rows.push_back(static_cast<int>(r));
  checkValues(attribute, rows);

  SemanticAxis axis;
  axis.attribute = attribute.name;
  axis.label = attribute.label;
  axis.lowWord = attribute.lowWord;
  axis.highWord = attribute.highWord;
  axis.categorical = attribute.categorical;
  axis.classes = attribute.classes;
  axis.walkers = static_cast<int>(rows.size());
  axis.kScale = Eigen::VectorXd::Constant(eigenvalues.size(), std::sqrt(std::max(eigenvalues.maxCoeff(), 1e-12)));

  Eigen::MatrixXd k(walkers.k.rows(), static_cast<Eigen::Index>(rows.size()));
  Eigen::VectorXd omega(static_cast<Eigen::Index>(rows.size())), y(static_cast<Eigen::Index>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i) {
    k.col(static_cast<Eigen::Index>(i)) = walkers.k.col(rows[i]);
    omega(static_cast<Eigen::Index>(i)) = walkers.omegaRadS(rows[i]);
    y(static_cast<Eigen::Index>(i)) = attribute.values[static_cast<size_t>(rows[i])];
  }
  axis.omegaMean = omega.mean();
  const double omegaSd = std::sqrt((omega.array() - axis.omegaMean).square().sum() / std::max<double>(1.0, static_cast<double>(omega.size()) - 1.0));
  axis.omegaSd = omegaSd > 1e-9 ? omegaSd : 1.0;
  axis.mean = y.mean();
  axis.sd = std::sqrt((y.array() - axis.mean).square().sum() / (static_cast<double>(y.size()) - 1.0));

  const Eigen::MatrixXd z = features(axis, k, omega);
  const RidgeResult fit = ridgeRegression(z, y);
  axis.weights = fit.weights;
  axis.intercept = fit.intercept;
  axis.ridge = fit.ridge;
  if (axis.categorical) axis.threshold = classBoundary((z * axis.weights).array() + axis.intercept, y);

  const Eigen::VectorXd yc = y.array() - axis.mean;
  const Eigen::MatrixXd zc = z.rowwise() - z.colwise().mean();
  const Eigen::VectorXd g = zc.transpose() * yc / yc.squaredNorm();
  axis.gain = axis.weights.dot(g);
  axis.steerable = axis.gain >= kMinAxisGain;
  const Eigen::Index n = axis.kScale.size();
  axis.directionK = g.head(n).cwiseProduct(axis.kScale);
  axis.directionOmega = g(n) * axis.omegaSd;
  return axis;
}

double predictAttribute(const SemanticAxis& axis, const Eigen::Ref<const Eigen::VectorXd>& k, double omegaRadS) {
  const Eigen::Index n = axis.kScale.size();
  double a = axis.intercept + axis.weights(n) * (omegaRadS - axis.omegaMean) / axis.omegaSd;
  for (Eigen::Index i = 0; i < n && i < k.size(); ++i) a += axis.weights(i) * k(i) / axis.kScale(i);
  return a;
}

int predictedClass(const SemanticAxis& axis, double prediction) { return prediction >= axis.threshold ? 1 : 0; }

std::vector<AxisFold> axisFolds(const std::vector<Walker>& walkers, const ModelOptions& options, int threads) {
  std::vector<std::string> subjects;
  for (const Walker& w : walkers)
    if (std::find(subjects.begin(), subjects.end(), w.subject) == subjects.end()) subjects.push_back(w.subject);
  std::vector<AxisFold> folds(subjects.size());
  parallelFor(static_cast<int>(subjects.size()), threads, [&](int f) {
    AxisFold& fold = folds[static_cast<size_t>(f)];
    fold.subject = subjects[static_cast<size_t>(f)];
    std::vector<Walker> train;
    for (size_t r = 0; r < walkers.size(); ++r) {
      (walkers[r].subject == fold.subject ? fold.test : fold.train).push_back(static_cast<int>(r));
      if (walkers[r].subject != fold.subject) train.push_back(walkers[r]);
    }
    fold.model = buildModelWithoutSubject(walkers, fold.subject, options);
    fold.trainWalkers = axisWalkers(fold.model, train);
  });
  return folds;
}

WalkerAttribute trainingAttribute(const WalkerAttribute& attribute, const std::vector<int>& train) {
  WalkerAttribute a = attribute;
  a.values.clear();
  for (int r : train) a.values.push_back(attribute.values[static_cast<size_t>(r)]);
  return a;
}

AxisQuality leaveOneSubjectOut(const WalkerAttribute& attribute, const std::vector<Walker>& walkers,
                               const std::vector<AxisFold>& folds) {
  std::vector<double> predictions(walkers.size(), NAN);
  std::vector<int> classOf(walkers.size(), -1);
  for (const AxisFold& fold : folds) {
    std::vector<int> known;
    for (int r : fold.test)
      if (std::isfinite(attribute.values[static_cast<size_t>(r)])) known.push_back(r);
    if (known.empty()) continue;
    SemanticAxis axis;
    try {
      axis = fitSemanticAxis(trainingAttribute(attribute, fold.train), fold.model.eigenvalues, fold.trainWalkers);
    } catch (const Error&) {
      continue;  // too few training values in this fold: its walkers stay unpredicted
    }
    for (int r : known) {
      const Walker& w = walkers[static_cast<size_t>(r)];
      const double p = predictAttribute(axis, projectOntoModel(fold.model, w.fit.w), w.fit.omegaRadS);
      predictions[static_cast<size_t>(r)] = p;
      classOf[static_cast<size_t>(r)] = predictedClass(axis, p);
    }
  }
  return scorePredictions(attribute, std::move(predictions), classOf);
}

AxisQuality scorePredictions(const WalkerAttribute& attribute, std::vector<double> predictions,
                             const std::vector<int>& classes) {
  AxisQuality q;
  q.attribute = attribute.name;
  q.predictions = std::move(predictions);
  double sum = 0.0, ssRes = 0.0, ssTot = 0.0;
  int right = 0, ones = 0;
  std::vector<int> used;
  for (size_t r = 0; r < q.predictions.size(); ++r)
    if (std::isfinite(q.predictions[r])) used.push_back(static_cast<int>(r));
  q.walkers = static_cast<int>(used.size());
  if (used.empty()) return q;
  for (int r : used) sum += attribute.values[static_cast<size_t>(r)];
  const double mean = sum / static_cast<double>(used.size());
  for (int r : used) {
    const double a = attribute.values[static_cast<size_t>(r)];
    ssRes += (a - q.predictions[static_cast<size_t>(r)]) * (a - q.predictions[static_cast<size_t>(r)]);
    ssTot += (a - mean) * (a - mean);
    if (a > 0.5) ++ones;
    if (classes[static_cast<size_t>(r)] == (a > 0.5 ? 1 : 0)) ++right;
  }
  const double n = static_cast<double>(used.size());
  if (attribute.categorical) {
    q.accuracy = right / n;
    q.chance = std::max(ones, q.walkers - ones) / n;
  } else {
    q.r2 = ssTot > 0 ? 1.0 - ssRes / ssTot : NAN;
    q.rmse = std::sqrt(ssRes / n);
  }
  return q;
}

}  // namespace ew
