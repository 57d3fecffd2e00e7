#include "core/snippet/snippet_prior.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/common/errors.h"
#include "core/common/symmetric_eigen.h"
#include "core/synth/random.h"

namespace ew {

namespace {

[[noreturn]] void priorError(const std::string& problem) {
  throw Error(ErrorKind::BadArgument, "snippet prior", "", problem);
}

void checkOptions(const SnippetPriorOptions& o) {
  if (o.frames < 1 || o.frames > 301) priorError("snippet length must be 1…301 frames");
  if (!(o.rateHz > 0.0 && o.rateHz <= 1000.0)) priorError("rate must be in (0, 1000] Hz");
  if (o.clusters < 1 || o.clusters > 256) priorError("clusters must be 1…256");
  if (o.components < 0) priorError("components must be ≥ 0");
  if (o.hop < 1) priorError("hop must be ≥ 1");
  if (o.kmeansIterations < 1) priorError("k-means iterations must be ≥ 1");
  if (o.emIterations < 0) priorError("EM iterations must be ≥ 0");
  if (!(o.minNoiseVarianceMm2 > 0.0 && std::isfinite(o.minNoiseVarianceMm2)))
    priorError("the noise variance floor must be positive");
}

// k-means++ seeding (Arthur & Vassilvitskii 2007), then Lloyd iterations. An emptied
// cluster takes the point farthest from its centre.
std::vector<int> kmeans(const Eigen::MatrixXd& x, int k, int iterations, std::uint64_t seed) {
  const Eigen::Index n = x.cols();
  Rng rng(seed);
  Eigen::MatrixXd centres(x.rows(), k);
  centres.col(0) = x.col(static_cast<Eigen::Index>(rng.uniform() * static_cast<double>(n)));
  Eigen::VectorXd nearest = (x.colwise() - centres.col(0)).colwise().squaredNorm().transpose();
  for (int c = 1; c < k; ++c) {
    const double total = nearest.sum();
    double pick = rng.uniform() * total;
    Eigen::Index chosen = n - 1;
    for (Eigen::Index i = 0; i < n; ++i) {
      pick -= nearest(i);
      if (pick < 0.0) { chosen = i; break; }
    }
    centres.col(c) = x.col(chosen);
    nearest = nearest.cwiseMin((x.colwise() - centres.col(c)).colwise().squaredNorm().transpose());
  }
  std::vector<int> label(static_cast<size_t>(n), -1);
  for (int it = 0; it < iterations; ++it) {
    bool changed = false;
    // ‖x − c‖² = ‖x‖² − 2 xᵀc + ‖c‖²: one matrix product per iteration.
    const Eigen::MatrixXd cross = centres.transpose() * x;  // k × n
    const Eigen::VectorXd cNorm = centres.colwise().squaredNorm().transpose();
    for (Eigen::Index i = 0; i < n; ++i) {
      Eigen::Index best = 0;
      (cNorm - 2.0 * cross.col(i)).minCoeff(&best);
      if (label[static_cast<size_t>(i)] != best) { label[static_cast<size_t>(i)] = static_cast<int>(best); changed = true; }
    }
    Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(x.rows(), k);
    std::vector<int> count(static_cast<size_t>(k), 0);
    for (Eigen::Index i = 0; i < n; ++i) {
      sums.col(label[static_cast<size_t>(i)]) += x.col(i);
      ++count[static_cast<size_t>(label[static_cast<size_t>(i)])];
    }
    for (int c = 0; c < k; ++c) {
      if (count[static_cast<size_t>(c)] > 0) {
        centres.col(c) = sums.col(c) / count[static_cast<size_t>(c)];
        continue;
      }
      Eigen::Index far = 0;
      Eigen::VectorXd d(n);
      for (Eigen::Index i = 0; i < n; ++i) d(i) = (x.col(i) - centres.col(label[static_cast<size_t>(i)])).squaredNorm();
      d.maxCoeff(&far);
      centres.col(c) = x.col(far);
      label[static_cast<size_t>(far)] = c;
      changed = true;
    }
    if (!changed && it > 0) break;
  }
  return label;
}

// The left singular vectors of a d × n matrix and its squared singular values, largest first
// (min(d, n) of them): the eigenvectors of the smaller of its two Gram matrices, brought over to
// the left through the matrix when that is n × n. Eigen's SVDs would do, but compiling BDCSVD cost
// 25 s (GCC) and 46 s (clang with the sanitizers) of CI's build, the eigensolver none more
// (core/common/symmetric_eigen.h). The squared singular values lose nothing the PPCA keeps: it
// keeps the axes whose variance stands above the noise's.
struct PrincipalAxes {
  Eigen::MatrixXd directions;     // d × min(d, n), unit columns
  Eigen::VectorXd squaredLengths;
};

PrincipalAxes principalAxes(const Eigen::MatrixXd& a) {
  const bool wide = a.cols() < a.rows();  // fewer points than dimensions: the points' Gram matrix
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(wide ? a.cols() : a.rows(), wide ? a.cols() : a.rows());
  if (wide)
    gram.selfadjointView<Eigen::Lower>().rankUpdate(a.transpose());
  else
    gram.selfadjointView<Eigen::Lower>().rankUpdate(a);
  const SymmetricEigen eig = symmetricEigen(gram);
  PrincipalAxes axes{eig.vectors.rowwise().reverse(), eig.values.reverse().cwiseMax(0.0)};
  if (wide) {
    axes.directions = a * axes.directions;
    for (Eigen::Index i = 0; i < axes.directions.cols(); ++i) {
      const double norm = axes.directions.col(i).norm();
      if (norm > 0.0) axes.directions.col(i) /= norm;
    }
  }
  return axes;
}

// Maximum-likelihood PPCA of weighted points: mean, q leading variances and σ².
PpcaComponent weightedPpca(const Eigen::MatrixXd& x, const Eigen::VectorXd& weights, int q,
                           double noiseFloor) {
  const double total = weights.sum();
  PpcaComponent c;
  c.mean = x * weights / total;
  Eigen::MatrixXd centred = x.colwise() - c.mean;
  centred.array().rowwise() *= weights.transpose().array().sqrt();
  const Eigen::Index d = x.rows();
  const double trace = centred.squaredNorm() / total;
  const int qMax = static_cast<int>(std::min<Eigen::Index>({static_cast<Eigen::Index>(q), d - 1, x.cols() - 1}));
  const PrincipalAxes axes = principalAxes(centred);
  const Eigen::VectorXd lambda = axes.squaredLengths / total;
  const int kept = std::max(0, std::min<int>(qMax, static_cast<int>(lambda.size())));
  const double rest = std::max(0.0, trace - lambda.head(kept).sum());
  c.noiseVariance = std::max(noiseFloor, kept < d ? rest / static_cast<double>(d - kept) : noiseFloor);
  int q2 = 0;
  while (q2 < kept && lambda(q2) > c.noiseVariance * (1.0 + 1e-9)) ++q2;
  c.basis = axes.directions.leftCols(q2);
  c.variances = lambda.head(q2);
  return c;
}

double logSumExp(const Eigen::Ref<const Eigen::VectorXd>& v) {
  const double m = v.maxCoeff();
  if (!std::isfinite(m)) return m;
  return m + std::log((v.array() - m).exp().sum());
}

// The columns of x whose weight is above `cut`, with their weights.
struct WeightedColumns {
  Eigen::MatrixXd x;
  Eigen::VectorXd w;
};
WeightedColumns columnsAbove(const Eigen::MatrixXd& x, const Eigen::VectorXd& w, double cut) {
  const Eigen::Index kept = (w.array() > cut).count();
  WeightedColumns out{Eigen::MatrixXd(x.rows(), kept), Eigen::VectorXd(kept)};
  for (Eigen::Index i = 0, k = 0; i < x.cols(); ++i)
    if (w(i) > cut) {
      out.x.col(k) = x.col(i);
      out.w(k++) = w(i);
    }
  return out;
}

// A few EM steps on the whole mixture (responsibilities, then weighted PPCA per cluster).
void refineByEm(SnippetPrior& prior, const Eigen::MatrixXd& x, const SnippetPriorOptions& o) {
  const Eigen::Index n = x.cols();
  const int m = static_cast<int>(prior.components.size());
  for (int it = 0; it < o.emIterations; ++it) {
    Eigen::MatrixXd resp(n, m);
    for (Eigen::Index i = 0; i < n; ++i)
      resp.row(i) = responsibilitiesFromLog(weightedLogDensities(prior, x.col(i))).transpose();
    for (int j = 0; j < m; ++j) {
      const Eigen::VectorXd w = resp.col(j);
      const double nj = w.sum();
      if (!(nj >= 2.0)) continue;  // a cluster that lost its points keeps its last fit
      // Responsibilities far in the tail (down to denormals) move the moments by less than
      // 1e-12 and, left in, made the SVD return NaN (m = 32, fold SM2014007, second step).
      const WeightedColumns mine = columnsAbove(x, w, 1e-12 * nj / static_cast<double>(n));
      PpcaComponent c = weightedPpca(mine.x, mine.w, o.components, o.minNoiseVarianceMm2);
      if (!c.mean.allFinite() || !c.basis.allFinite() || !c.variances.allFinite()) continue;  // keeps its last fit
      c.weight = nj / static_cast<double>(n);
      c.members = static_cast<int>(std::lround(nj));
      prior.components[static_cast<size_t>(j)] = std::move(c);
    }
    double sum = 0.0;
    for (const auto& c : prior.components) sum += c.weight;
    for (auto& c : prior.components) c.weight /= sum;
    ++prior.emIterations;
  }
}

}  // namespace

SnippetPrior fitSnippetMixture(const Eigen::Ref<const Eigen::MatrixXd>& snippets,
                               const SnippetPriorOptions& options) {
  checkOptions(options);
  const Eigen::Index d = static_cast<Eigen::Index>(options.frames) * kSnippetJointValues;
  const bool toy = snippets.rows() != d;  // low-dimensional data (tests): any D
  if (snippets.rows() < 2 || (!toy && snippets.rows() != d)) priorError("snippets have the wrong length");
  if (snippets.cols() < 2 * options.clusters)
    priorError("only " + std::to_string(snippets.cols()) + " snippets for " +
               std::to_string(options.clusters) + " clusters (2 per cluster needed)");
  if (!snippets.allFinite()) priorError("snippets hold non-finite values");
  const Eigen::MatrixXd x = snippets;
  const std::vector<int> label = kmeans(x, options.clusters, options.kmeansIterations, options.seed);
  SnippetPrior prior;
  prior.frames = toy ? 0 : options.frames;
  prior.rateHz = options.rateHz;
  prior.trainingSnippets = static_cast<int>(x.cols());
  for (int j = 0; j < options.clusters; ++j) {
    Eigen::VectorXd w = Eigen::VectorXd::Zero(x.cols());
    for (Eigen::Index i = 0; i < x.cols(); ++i) w(i) = label[static_cast<size_t>(i)] == j ? 1.0 : 0.0;
    const int members = static_cast<int>(w.sum());
    if (members < 2) continue;  // a single snippet has no spread: left to the others
    // Only the members enter the SVD (a D × n_j matrix, not D × n).
    const WeightedColumns mine = columnsAbove(x, w, 0.0);
    PpcaComponent c = weightedPpca(mine.x, mine.w, options.components, options.minNoiseVarianceMm2);
    c.members = members;
    prior.components.push_back(std::move(c));
  }
  int used = 0;
  for (const auto& c : prior.components) used += c.members;
  for (auto& c : prior.components) c.weight = static_cast<double>(c.members) / used;
  refineByEm(prior, x, options);
  return prior;
}

SnippetPrior trainSnippetPrior(const std::vector<SnippetTrainingTrial>& trials,
                               const SnippetPriorOptions& options) {
  checkOptions(options);
  const Eigen::MatrixXd snippets = cutTrainingSnippets(trials, options.frames, options.hop, options.rateHz);
  if (snippets.cols() < 2 * options.clusters) {
    std::vector<std::string> names;
    for (const auto& t : trials) names.push_back(t.name);
    throw Error(ErrorKind::BadData, listForMessage(names, 3), "",
                "snippet prior: the trials give " + std::to_string(snippets.cols()) +
                    " snippets of " + std::to_string(options.frames) + " frames; " +
                    std::to_string(2 * options.clusters) + " needed for " +
                    std::to_string(options.clusters) + " clusters");
  }
  SnippetPrior prior = fitSnippetMixture(snippets, options);
  for (const auto& t : trials)
    if (std::find(prior.subjects.begin(), prior.subjects.end(), t.subject) == prior.subjects.end())
      prior.subjects.push_back(t.subject);
  return prior;
}

double componentLogDensity(const PpcaComponent& c, const Eigen::Ref<const Eigen::VectorXd>& x) {
  const Eigen::VectorXd e = x - c.mean;
  const Eigen::VectorXd proj = c.basis.transpose() * e;
  const double s2 = c.noiseVariance;
  // eᵀC⁻¹e = (‖e‖² − Σ (1 − σ²/λ_i) (u_iᵀe)²) / σ²
  const double maha =
      (e.squaredNorm() - (proj.array().square() * (1.0 - s2 / c.variances.array())).sum()) / s2;
  const double d = static_cast<double>(x.size());
  const double q = static_cast<double>(c.variances.size());
  const double logDet = c.variances.array().log().sum() + (d - q) * std::log(s2);
  return -0.5 * (maha + logDet + d * std::log(2.0 * std::numbers::pi));
}

Eigen::VectorXd weightedLogDensities(const SnippetPrior& prior, const Eigen::Ref<const Eigen::VectorXd>& x) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(prior.components.size()));
  for (size_t j = 0; j < prior.components.size(); ++j)
    out(static_cast<Eigen::Index>(j)) =
        std::log(prior.components[j].weight) + componentLogDensity(prior.components[j], x);
  return out;
}

double logDensity(const SnippetPrior& prior, const Eigen::Ref<const Eigen::VectorXd>& x) {
  return logSumExp(weightedLogDensities(prior, x));
}

double meanLogDensity(const SnippetPrior& prior, const Eigen::Ref<const Eigen::MatrixXd>& snippets) {
  if (snippets.cols() == 0) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (Eigen::Index i = 0; i < snippets.cols(); ++i) sum += logDensity(prior, snippets.col(i));
  return sum / static_cast<double>(snippets.cols());
}

Eigen::VectorXd responsibilitiesFromLog(const Eigen::Ref<const Eigen::VectorXd>& logWeighted) {
  const double m = logWeighted.maxCoeff();
  Eigen::VectorXd r = (logWeighted.array() - m).exp();
  return r / r.sum();
}

Eigen::VectorXd applyInverseCovariance(const PpcaComponent& c, const Eigen::Ref<const Eigen::VectorXd>& v) {
  const Eigen::VectorXd proj = c.basis.transpose() * v;
  const Eigen::VectorXd shrink = (1.0 - c.noiseVariance / c.variances.array()).matrix().cwiseProduct(proj);
  return (v - c.basis * shrink) / c.noiseVariance;
}

void checkSnippetPrior(const SnippetPrior& prior) {
  if (prior.components.empty()) priorError("no clusters");
  const Eigen::Index d = prior.components.front().mean.size();
  if (prior.frames > 0 && d != prior.dimension()) priorError("cluster means do not have S·45 values");
  double sum = 0.0;
  for (size_t j = 0; j < prior.components.size(); ++j) {
    const PpcaComponent& c = prior.components[j];
    const std::string name = "cluster " + std::to_string(j);
    if (c.mean.size() != d || c.basis.rows() != d || c.basis.cols() != c.variances.size())
      priorError(name + ": inconsistent sizes");
    if (!c.mean.allFinite() || !c.basis.allFinite() || !c.variances.allFinite())
      priorError(name + ": non-finite values");
    if (!(c.noiseVariance > 0.0 && std::isfinite(c.noiseVariance))) priorError(name + ": σ² must be positive");
    if ((c.variances.array() <= c.noiseVariance).any()) priorError(name + ": a variance is not above σ²");
    if (!(c.weight > 0.0 && c.weight <= 1.0)) priorError(name + ": weight outside (0, 1]");
    sum += c.weight;
  }
  if (std::abs(sum - 1.0) > 1e-9) priorError("weights do not sum to 1");
}

}  // namespace ew
