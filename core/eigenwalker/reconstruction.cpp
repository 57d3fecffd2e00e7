#include "core/eigenwalker/reconstruction.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <tuple>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/minimize_1d.h"
#include "core/eigenwalker/projection.h"

namespace ew {
namespace {

// [SECTION] Per-observation terms

// What one search needs from ŵ: the observed u and v rows and their per-axis products
// with E and w̄ (computed once per ŵ, O(m·N)).
struct ObservedTerms {
  Eigen::VectorXd exU, eyU, ezV;  // Exᵀu, Eyᵀu, Ezᵀ(v − w̄z)
  double uu = 0.0, uMx = 0.0, uMy = 0.0, vResidualSq = 0.0;  // uᵀu, uᵀw̄x, uᵀw̄y, ‖v − w̄z‖²
};

[[noreturn]] void reconstructionError(ErrorKind kind, const std::string& problem) {
  throw Error(kind, "", "", "reconstruction: " + problem);
}

// O(1): a ModelGram as precomputeModelGram makes it (a default-constructed one is empty).
void checkGram(const ModelGram& g) {
  const auto n = static_cast<Eigen::Index>(g.components);
  const auto m = static_cast<Eigen::Index>(g.observedPoints.size());
  if (n < 1 || m < 1 || g.mean.size() != kFourierDims3 || g.eigenwalkers.rows() != kFourierDims3 ||
      g.eigenwalkers.cols() != n || g.ex.rows() != m || g.ex.cols() != n || g.gxx.rows() != n ||
      g.inverseLambda.size() != n)
    reconstructionError(
        ErrorKind::BadArgument,
        "the model Gram is empty or inconsistent (build it with precomputeModelGram)");
}

ObservedTerms observedTerms(const ModelGram& g, const Eigen::Ref<const Eigen::VectorXd>& obs) {
  checkGram(g);
  if (obs.size() != kFourierDims2)
    reconstructionError(
        ErrorKind::BadArgument,
        "observed 2D Fourier vector must have 150 values, got " + std::to_string(obs.size()));
  const auto m = static_cast<Eigen::Index>(g.observedPoints.size());
  Eigen::VectorXd u(m), v(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const int p = g.observedPoints[static_cast<size_t>(i)];
    u(i) = obs(2 * p);
    v(i) = obs(2 * p + 1);
  }
  if (!u.allFinite() || !v.allFinite())
    reconstructionError(
        ErrorKind::BadArgument,
        "observed 2D Fourier vector has non-finite values at joints not marked missing");
  ObservedTerms t;
  const Eigen::VectorXd vr = v - g.mz;
  t.exU.noalias() = g.ex.transpose() * u;
  t.eyU.noalias() = g.ey.transpose() * u;
  t.ezV.noalias() = g.ez.transpose() * vr;
  t.uu = u.squaredNorm();
  t.uMx = u.dot(g.mx);
  t.uMy = u.dot(g.my);
  t.vResidualSq = vr.squaredNorm();
  if (!std::isfinite(t.uu) || !std::isfinite(t.vResidualSq) || !t.exU.allFinite() ||
      !t.eyU.allFinite() || !t.ezV.allFinite())
    reconstructionError(ErrorKind::BadData,
                        "observed 2D coordinates too large: their sums of squares overflow");
  return t;
}

// [SECTION] Profile objective

// Evaluates J(α) and k(α) from the Gram terms with preallocated workspace.
class ViewEvaluator {
 public:
  ViewEvaluator(const ModelGram& g, const ObservedTerms& t, const EstimatorOptions& e)
      : g_(g), t_(t), map_(e.estimator == Estimator::Map), sigma2_(e.sigma2Mm2),
        gram_(g.components, g.components), b_(g.components), bFixed_(g.components),
        k_(g.components), llt_(g.components), ldlt_(g.components) {
    if (map_ && !(e.sigma2Mm2 >= 0.0 && std::isfinite(e.sigma2Mm2)))
      reconstructionError(ErrorKind::BadArgument,
                          "MAP needs a finite σ² ≥ 0 mm², got " + std::to_string(e.sigma2Mm2));
  }

  double operator()(double alphaDeg) {
    factor(alphaDeg);
    return solve(+1.0);
  }

  // J(α) and J(α + 180°): G is quadratic in (cos α, sin α) so both share one Cholesky;
  // only the data's u terms change sign. Leaves k() at α + 180°.
  std::pair<double, double> pair(double alphaDeg) {
    factor(alphaDeg);
    const double j = solve(+1.0);
    return {j, solve(-1.0)};
  }

  const Eigen::VectorXd& k() const { return k_; }
  int evaluations() const { return evaluations_; }

 private:
  void factor(double alphaDeg) {
    const double a = degToRad(alphaDeg);
    c_ = std::cos(a);
    s_ = std::sin(a);
    const double cc = c_ * c_, ss = s_ * s_, cs = c_ * s_;
    gram_.noalias() = cc * g_.gxx + ss * g_.gyy + cs * g_.gxySym + g_.gzz;
    if (map_) gram_.diagonal() += sigma2_ * g_.inverseLambda;
    bFixed_.noalias() = t_.ezV - (cc * g_.exMx + ss * g_.eyMy + cs * g_.exMyEyMx);
    ddFixed_ = cc * g_.mxMx + ss * g_.myMy + 2.0 * cs * g_.mxMy + t_.uu + t_.vResidualSq;
    llt_.compute(gram_);
    cholesky_ = llt_.info() == Eigen::Success;
    if (!cholesky_) ldlt_.compute(gram_);  // G singular (most joints missing): pivoted LDLT
  }

  // sign = +1 at α, −1 at α + 180° (cos and sin both change sign).
  double solve(double sign) {
    b_.noalias() = bFixed_ + (sign * c_) * t_.exU + (sign * s_) * t_.eyU;
    // ‖ŵ − ŵ̄(α)‖² = ‖u − c·w̄x − s·w̄y‖² + ‖v − w̄z‖²
    const double dd = ddFixed_ - 2.0 * sign * (c_ * t_.uMx + s_ * t_.uMy);
    k_ = cholesky_ ? Eigen::VectorXd(llt_.solve(b_)) : Eigen::VectorXd(ldlt_.solve(b_));
    ++evaluations_;
    return dd - k_.dot(b_);
  }

  const ModelGram& g_;
  const ObservedTerms& t_;
  bool map_;
  double sigma2_;
  Eigen::MatrixXd gram_;
  Eigen::VectorXd b_, bFixed_, k_;
  Eigen::LLT<Eigen::MatrixXd> llt_;
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
  bool cholesky_ = true;
  double c_ = 1.0, s_ = 0.0, ddFixed_ = 0.0;
  int evaluations_ = 0;
};

// [SECTION] Outputs

Reconstruction makeReconstruction(const ModelGram& g, const Eigen::Ref<const Eigen::VectorXd>& obs,
                                  double alphaDeg, const Eigen::VectorXd& k, double objective) {
  // Finite inputs can still overflow the solve (a nearly singular G with huge data):
  // report it rather than hand back a NaN walker.
  if (!k.allFinite() || !std::isfinite(objective))
    reconstructionError(
        ErrorKind::BadData,
        "the solve gave non-finite coefficients or objective at " + std::to_string(alphaDeg) + "°");
  Reconstruction rec;
  rec.alphaDeg = wrapDeg(alphaDeg);
  rec.k = k;
  rec.objective = objective;
  rec.w = g.mean + g.eigenwalkers * k;
  Eigen::MatrixXd uv = projectToView(rec.w, alphaDeg);
  double residualSq = 0.0;
  for (const int p : g.observedPoints) {
    residualSq += (obs.segment<2>(2 * p) - uv.col(0).segment<2>(2 * p)).squaredNorm();
    uv.col(0).segment<2>(2 * p) = obs.segment<2>(2 * p);  // eq. 3.16: keep the observed u, v
  }
  rec.residualSq = residualSq;
  rec.wDataPreserving = composeFromView(uv, depthAtView(rec.w, alphaDeg), alphaDeg);
  return rec;
}

std::vector<int> circularLocalMinima(const Eigen::VectorXd& f) {
  const auto n = static_cast<int>(f.size());
  std::vector<int> minima;
  for (int i = 0; i < n; ++i) {
    const double prev = f((i + n - 1) % n), next = f((i + 1) % n);
    if (f(i) <= prev && f(i) < next) minima.push_back(i);
  }
  if (minima.empty()) {  // constant J (e.g. a model that ignores u): any angle is a minimum
    Eigen::Index i = 0;
    f.minCoeff(&i);
    minima.push_back(static_cast<int>(i));
  }
  return minima;
}

}  // namespace

// [SECTION] Precomputation

ModelGram precomputeModelGram(const EigenwalkerModel& model, const std::vector<int>& missingJoints) {
  checkModel(model, "reconstruction");
  ModelGram g;
  g.components = model.componentCount();
  g.missingJoints = missingJoints;
  std::sort(g.missingJoints.begin(), g.missingJoints.end());
  g.missingJoints.erase(std::unique(g.missingJoints.begin(), g.missingJoints.end()),
                        g.missingJoints.end());
  for (const int j : g.missingJoints) {
    if (j < 0 || j >= kJointCount)
      reconstructionError(ErrorKind::BadArgument,
                          "missing joint index out of range: " + std::to_string(j) + " (0…14)");
  }
  if (static_cast<int>(g.missingJoints.size()) == kJointCount)
    reconstructionError(ErrorKind::BadArgument, "every joint is marked missing");
  for (int b = 0; b < kFourierBlocks; ++b) {
    for (int j = 0; j < kJointCount; ++j) {
      if (!std::binary_search(g.missingJoints.begin(), g.missingJoints.end(), j))
        g.observedPoints.push_back(b * kJointCount + j);
    }
  }
  const auto m = static_cast<Eigen::Index>(g.observedPoints.size());
  const Eigen::Index n = g.components;
  g.ex.resize(m, n); g.ey.resize(m, n); g.ez.resize(m, n);
  g.mx.resize(m); g.my.resize(m); g.mz.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    const int p = g.observedPoints[static_cast<size_t>(i)];
    g.ex.row(i) = model.eigenwalkers.row(3 * p);
    g.ey.row(i) = model.eigenwalkers.row(3 * p + 1);
    g.ez.row(i) = model.eigenwalkers.row(3 * p + 2);
    g.mx(i) = model.mean(3 * p);
    g.my(i) = model.mean(3 * p + 1);
    g.mz(i) = model.mean(3 * p + 2);
  }
  g.gxx.noalias() = g.ex.transpose() * g.ex;
  g.gyy.noalias() = g.ey.transpose() * g.ey;
  g.gzz.noalias() = g.ez.transpose() * g.ez;
  const Eigen::MatrixXd gxy = g.ex.transpose() * g.ey;
  g.gxySym = gxy + gxy.transpose();
  g.exMx.noalias() = g.ex.transpose() * g.mx;
  g.eyMy.noalias() = g.ey.transpose() * g.my;
  g.exMyEyMx.noalias() = g.ex.transpose() * g.my + g.ey.transpose() * g.mx;
  g.ezMz.noalias() = g.ez.transpose() * g.mz;
  g.mxMx = g.mx.squaredNorm();
  g.myMy = g.my.squaredNorm();
  g.mxMy = g.mx.dot(g.my);
  const double floor = 1e-12 * std::max(model.eigenvalues.maxCoeff(), 1e-300);
  g.inverseLambda = model.eigenvalues.cwiseMax(floor).cwiseInverse();
  g.mean = model.mean;
  g.eigenwalkers = model.eigenwalkers;
  return g;
}

// [SECTION] Known view

Reconstruction reconstructKnownView(const ModelGram& gram,
                                    const Eigen::Ref<const Eigen::VectorXd>& observed,
                                    double alphaDeg, const EstimatorOptions& estimator) {
  if (!std::isfinite(alphaDeg))
    reconstructionError(ErrorKind::BadArgument,
                        "the view angle must be finite, got " + std::to_string(alphaDeg) + "°");
  const ObservedTerms terms = observedTerms(gram, observed);
  ViewEvaluator evaluate(gram, terms, estimator);
  const double j = evaluate(alphaDeg);
  return makeReconstruction(gram, observed, alphaDeg, evaluate.k(), j);
}

Reconstruction reconstructLsq(const ModelGram& gram,
                              const Eigen::Ref<const Eigen::VectorXd>& observed, double alphaDeg) {
  return reconstructKnownView(gram, observed, alphaDeg, {Estimator::Lsq, 0.0});
}

Reconstruction reconstructMap(const ModelGram& gram,
                              const Eigen::Ref<const Eigen::VectorXd>& observed, double alphaDeg,
                              double sigma2Mm2) {
  return reconstructKnownView(gram, observed, alphaDeg, {Estimator::Map, sigma2Mm2});
}

// [SECTION] Unknown view

bool isDepthReversedView(double alphaDeg, double bestDeg, double toleranceDeg) {
  return std::abs(wrapDeg(alphaDeg + bestDeg)) <= toleranceDeg;
}

bool isMirrorView(double alphaDeg, double bestDeg, double toleranceDeg) {
  return std::abs(wrapDeg(alphaDeg - (180.0 - bestDeg))) <= toleranceDeg;
}

bool isFacingView(double alphaDeg, double bestDeg, double toleranceDeg) {
  return std::abs(wrapDeg(alphaDeg - (bestDeg + 180.0))) <= toleranceDeg;
}

Eigen::VectorXd viewObjective(const ModelGram& gram,
                              const Eigen::Ref<const Eigen::VectorXd>& observed,
                              const Eigen::Ref<const Eigen::VectorXd>& alphasDeg,
                              const EstimatorOptions& estimator) {
  if (!alphasDeg.allFinite())
    reconstructionError(ErrorKind::BadArgument, "view objective: the angles must be finite");
  const ObservedTerms terms = observedTerms(gram, observed);
  ViewEvaluator evaluate(gram, terms, estimator);
  Eigen::VectorXd j(alphasDeg.size());
  for (Eigen::Index i = 0; i < alphasDeg.size(); ++i) j(i) = evaluate(alphasDeg(i));
  return j;
}

ViewSearch searchViewAngle(const ModelGram& gram,
                           const Eigen::Ref<const Eigen::VectorXd>& observed,
                           const EstimatorOptions& estimator, const ViewSearchOptions& options) {
  if (!(options.coarseStepDeg >= 1e-3 && options.coarseStepDeg <= 30.0))
    reconstructionError(ErrorKind::BadArgument,
                        "view search: the coarse step must be in [0.001°, 30°], got " +
                            std::to_string(options.coarseStepDeg) + "°");
  if (!(options.toleranceDeg > 0.0 && std::isfinite(options.toleranceDeg)))
    reconstructionError(ErrorKind::BadArgument,
                        "view search: the tolerance must be positive and finite, got " +
                            std::to_string(options.toleranceDeg) + "°");
  if (!(options.relationToleranceDeg >= 0.0 && options.relationToleranceDeg <= 180.0))
    reconstructionError(ErrorKind::BadArgument,
                        "view search: the relation tolerance must be in [0°, 180°], got " +
                            std::to_string(options.relationToleranceDeg) + "°");
  const ObservedTerms terms = observedTerms(gram, observed);
  ViewEvaluator evaluate(gram, terms, estimator);
  ViewSearch out;
  const int count = static_cast<int>(std::round(360.0 / options.coarseStepDeg));
  const double step = 360.0 / count;
  out.scanAlphaDeg.resize(count);
  out.scanObjective.resize(count);
  for (int i = 0; i < count; ++i) out.scanAlphaDeg(i) = 180.0 - (count - 1 - i) * step;
  // The grid is symmetric under +180° when it has an even count: half the factorisations.
  const int half = count / 2;
  for (int i = 0; i < count; ++i) {
    if (count % 2 == 0 && i < half) {
      std::tie(out.scanObjective(i), out.scanObjective(i + half)) = evaluate.pair(out.scanAlphaDeg(i));
    } else if (count % 2 != 0) {
      out.scanObjective(i) = evaluate(out.scanAlphaDeg(i));
    }
  }
  for (const int i : circularLocalMinima(out.scanObjective)) {
    const double centre = out.scanAlphaDeg(i);
    const auto m = minimizeBrent(evaluate, centre - step, centre + step, 0.5 * options.toleranceDeg);
    const double alpha = wrapDeg(m.x);
    const bool duplicate = std::any_of(out.minima.begin(), out.minima.end(), [&](const auto& v) {
      return std::abs(wrapDeg(v.alphaDeg - alpha)) < 10.0 * options.toleranceDeg;
    });
    if (!duplicate) out.minima.push_back({alpha, m.value, false, false, false});
  }
  std::sort(out.minima.begin(), out.minima.end(),
            [](const ViewMinimum& a, const ViewMinimum& b) { return a.objective < b.objective; });
  const double best = out.minima.front().alphaDeg;
  for (auto& v : out.minima) {
    if (&v == &out.minima.front()) continue;
    v.depthReversedOfBest = isDepthReversedView(v.alphaDeg, best, options.relationToleranceDeg);
    v.mirrorOfBest = isMirrorView(v.alphaDeg, best, options.relationToleranceDeg);
    v.facingOfBest = isFacingView(v.alphaDeg, best, options.relationToleranceDeg);
  }
  const double j = evaluate(best);
  out.best = makeReconstruction(gram, observed, best, evaluate.k(), j);
  out.evaluations = evaluate.evaluations();
  return out;
}

}  // namespace ew
