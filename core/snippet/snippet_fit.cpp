#include "core/snippet/snippet_fit.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/minimize_1d.h"
#include "core/eigenwalker/projection.h"

namespace ew {

namespace {

[[noreturn]] void fitError(const std::string& problem) {
  throw Error(ErrorKind::BadArgument, "snippet fit", "", problem);
}

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// One view of the observation: which points are used and their (u, v).
struct Points {
  int count = 0;                  // S·15
  std::vector<bool> used;
  Eigen::VectorXd u, v;           // 0 where unused
  int usedCount() const { return static_cast<int>(std::count(used.begin(), used.end(), true)); }
};

Points observedPoints(const Eigen::Ref<const Eigen::MatrixXd>& y, const std::vector<bool>& allowed) {
  Points p;
  p.count = static_cast<int>(y.rows()) * kJointCount;
  p.used.assign(static_cast<size_t>(p.count), false);
  p.u = Eigen::VectorXd::Zero(p.count);
  p.v = Eigen::VectorXd::Zero(p.count);
  for (int f = 0; f < y.rows(); ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const int i = f * kJointCount + j;
      const double u = y(f, 2 * j), v = y(f, 2 * j + 1);
      if (!std::isfinite(u) || !std::isfinite(v)) continue;
      if (!allowed.empty() && !allowed[static_cast<size_t>(i)]) continue;
      p.used[static_cast<size_t>(i)] = true;
      p.u(i) = u;
      p.v(i) = v;
    }
  }
  return p;
}

// The snippet's x, y, z per point (S·15 each).
struct PointCoords {
  Eigen::VectorXd x, y, z;
};

PointCoords pointCoords(const Eigen::Ref<const Eigen::VectorXd>& snippet) {
  const Eigen::Index n = snippet.size() / 3;
  PointCoords c{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    c.x(i) = snippet(3 * i);
    c.y(i) = snippet(3 * i + 1);
    c.z(i) = snippet(3 * i + 2);
  }
  return c;
}

double squaredMiss(const Points& p, const PointCoords& c, const SnippetCamera& cam) {
  const double a = degToRad(cam.alphaDeg);
  const double ca = std::cos(a), sa = std::sin(a);
  double sum = 0.0;
  for (int i = 0; i < p.count; ++i) {
    if (!p.used[static_cast<size_t>(i)]) continue;
    const double du = p.u(i) - cam.scale * (ca * c.x(i) + sa * c.y(i)) - cam.shift.x();
    const double dv = p.v(i) - cam.scale * c.z(i) - cam.shift.y();
    sum += du * du + dv * dv;
  }
  return sum;
}

// Best (s, t) for a view angle: linear least squares (s from the centred values; t the
// mean miss). A scale that comes out ≤ 0 (the image upside down) is floored at a tiny
// positive value, which the caller sees as a bad fit.
SnippetCamera cameraAtAngle(const Points& p, const PointCoords& c, double alphaDeg,
                            std::optional<double> knownScale) {
  const double a = degToRad(alphaDeg);
  const double ca = std::cos(a), sa = std::sin(a);
  double n = 0, su = 0, sv = 0, spu = 0, spv = 0;
  for (int i = 0; i < p.count; ++i) {
    if (!p.used[static_cast<size_t>(i)]) continue;
    n += 1;
    su += p.u(i);
    sv += p.v(i);
    spu += ca * c.x(i) + sa * c.y(i);
    spv += c.z(i);
  }
  const double mu = su / n, mv = sv / n, mpu = spu / n, mpv = spv / n;
  SnippetCamera cam;
  cam.alphaDeg = alphaDeg;
  if (knownScale) {
    cam.scale = *knownScale;
  } else {
    double num = 0, den = 0;
    for (int i = 0; i < p.count; ++i) {
      if (!p.used[static_cast<size_t>(i)]) continue;
      const double pu = ca * c.x(i) + sa * c.y(i) - mpu, pv = c.z(i) - mpv;
      num += (p.u(i) - mu) * pu + (p.v(i) - mv) * pv;
      den += pu * pu + pv * pv;
    }
    cam.scale = den > 0 ? std::max(num / den, 1e-9) : 1.0;
  }
  cam.shift = Eigen::Vector2d(mu - cam.scale * mpu, mv - cam.scale * mpv);
  return cam;
}

// The camera step of EM: α scanned in 5° steps within the window, the best refined by
// Brent; kept only when it lowers the miss (so L cannot drop).
SnippetCamera cameraStep(const Points& p, const Eigen::VectorXd& snippet, const SnippetCamera& current,
                         const SnippetFitOptions& o) {
  const PointCoords c = pointCoords(snippet);
  if (o.alphaDeg) return cameraAtAngle(p, c, current.alphaDeg, o.scale);
  const auto miss = [&](double alpha) { return squaredMiss(p, c, cameraAtAngle(p, c, alpha, o.scale)); };
  const double window = std::clamp(o.alphaWindowDeg, 5.0, 180.0);
  double bestAlpha = current.alphaDeg, bestMiss = miss(current.alphaDeg);
  for (double d = -window; d <= window + 1e-9; d += 5.0) {
    const double m = miss(current.alphaDeg + d);
    if (m < bestMiss) { bestMiss = m; bestAlpha = current.alphaDeg + d; }
  }
  const Minimum1d refined = minimizeBrent(miss, bestAlpha - 5.0, bestAlpha + 5.0, 1e-4, 60);
  if (refined.value < bestMiss) bestAlpha = refined.x;
  SnippetCamera next = cameraAtAngle(p, c, bestAlpha, o.scale);
  next.alphaDeg = wrapDeg(next.alphaDeg);
  return squaredMiss(p, c, next) <= squaredMiss(p, c, cameraAtAngle(p, c, current.alphaDeg, o.scale))
             ? next
             : cameraAtAngle(p, c, current.alphaDeg, o.scale);
}

// One cluster under a camera (α, s): the joint MAP of the snippet x and the image shift t.
// t has a flat prior, so maximising over it leaves the data centred per image axis over the
// used points (P: the centring projector): ‖P(y − A x)‖². In that subspace the noise is
// still isotropic, so the PPCA Woodbury form holds with B_c = P A W, whose Gram is
// BᵀB minus a rank-2 term (the column sums of the u and v rows). Then t = mean(y − A x̂).
struct ClusterPosterior {
  Eigen::VectorXd snippet;   // posterior mean of x (the MAP under this cluster)
  Eigen::Vector2d shift;     // the best image shift for it
  double logMarginal = 0.0;  // log p(P y | cluster, α, s): the centred data's evidence
};

ClusterPosterior clusterPosterior(const PpcaComponent& comp, const ClusterFactors& f, const Points& p,
                                  const SnippetCamera& cam, double nu) {
  const double a = degToRad(cam.alphaDeg);
  const double ca = std::cos(a), sa = std::sin(a), s = cam.scale;
  const Eigen::Index q = f.wx.cols();
  Eigen::MatrixXd btb = ca * ca * f.gxx + sa * sa * f.gyy + ca * sa * f.gxySym + f.gzz;
  Eigen::VectorXd ru = Eigen::VectorXd::Zero(p.count), rv = Eigen::VectorXd::Zero(p.count);
  Eigen::VectorXd sumU = Eigen::VectorXd::Zero(q), sumV = Eigen::VectorXd::Zero(q);
  int used = 0;
  for (int i = 0; i < p.count; ++i) {
    const Eigen::RowVectorXd bu = ca * f.wx.row(i) + sa * f.wy.row(i);
    if (!p.used[static_cast<size_t>(i)]) {
      // Gram blocks hold every point: take the unused ones back out.
      btb.noalias() -= bu.transpose() * bu;
      btb.noalias() -= f.wz.row(i).transpose() * f.wz.row(i);
      continue;
    }
    ++used;
    sumU += bu.transpose();
    sumV += f.wz.row(i).transpose();
    ru(i) = p.u(i) - s * (ca * f.mx(i) + sa * f.my(i));
    rv(i) = p.v(i) - s * f.mz(i);
  }
  const double n = static_cast<double>(used);
  const double meanU = ru.sum() / n, meanV = rv.sum() / n;
  for (int i = 0; i < p.count; ++i) {
    if (!p.used[static_cast<size_t>(i)]) continue;
    ru(i) -= meanU;
    rv(i) -= meanV;
  }
  btb.noalias() -= (sumU * sumU.transpose() + sumV * sumV.transpose()) / n;
  btb *= s * s;
  const Eigen::VectorXd btr = s * (ca * (f.wx.transpose() * ru) + sa * (f.wy.transpose() * ru) +
                                   f.wz.transpose() * rv);
  const double beta = 1.0 / (s * s * comp.noiseVariance + nu);
  Eigen::MatrixXd mz = Eigen::MatrixXd::Identity(q, q) + beta * btb;
  const Eigen::LLT<Eigen::MatrixXd> llt(mz);
  const Eigen::VectorXd z = beta * llt.solve(btr);
  // e = r_c − B_c z̄, per point (B_c z̄ = B z̄ minus its mean over the used points).
  const double zu = s * sumU.dot(z) / n, zv = s * sumV.dot(z) / n;
  const Eigen::VectorXd dx = f.wx * z, dy = f.wy * z, dz = f.wz * z;
  ClusterPosterior out;
  const double m = 2.0 * n - 2.0;  // two dimensions went to the shift
  const double rr = ru.squaredNorm() + rv.squaredNorm();
  double logDetMz = 0.0;
  for (Eigen::Index i = 0; i < q; ++i) logDetMz += 2.0 * std::log(llt.matrixL()(i, i));
  out.logMarginal = -0.5 * (beta * (rr - btr.dot(z)) - m * std::log(beta) + logDetMz + m * std::log(kTwoPi));
  // x̂ = μ + W z̄ + σ² β Aᵀ e  (A = s C(α): Aᵀ puts e_u on x, y and e_v on z).
  const Eigen::Index count = p.count;
  out.snippet.resize(3 * count);
  const double g = comp.noiseVariance * beta * s;
  double shiftU = 0.0, shiftV = 0.0;
  for (Eigen::Index i = 0; i < count; ++i) {
    const bool on = p.used[static_cast<size_t>(i)];
    const double eu = on ? ru(i) - (s * (ca * dx(i) + sa * dy(i)) - zu) : 0.0;
    const double ev = on ? rv(i) - (s * dz(i) - zv) : 0.0;
    out.snippet(3 * i) = f.mx(i) + dx(i) + g * ca * eu;
    out.snippet(3 * i + 1) = f.my(i) + dy(i) + g * sa * eu;
    out.snippet(3 * i + 2) = f.mz(i) + dz(i) + g * ev;
    if (on) {
      shiftU += p.u(i) - s * (ca * out.snippet(3 * i) + sa * out.snippet(3 * i + 1));
      shiftV += p.v(i) - s * out.snippet(3 * i + 2);
    }
  }
  out.shift = Eigen::Vector2d(shiftU / n, shiftV / n);
  return out;
}

ClusterFactors makeFactors(const PpcaComponent& c) {
  const Eigen::Index d = c.mean.size(), n = d / 3, q = c.variances.size();
  const Eigen::MatrixXd w =
      c.basis * (c.variances.array() - c.noiseVariance).sqrt().matrix().asDiagonal();
  ClusterFactors f;
  f.wx.resize(n, q); f.wy.resize(n, q); f.wz.resize(n, q);
  f.mx.resize(n); f.my.resize(n); f.mz.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    f.wx.row(i) = w.row(3 * i); f.wy.row(i) = w.row(3 * i + 1); f.wz.row(i) = w.row(3 * i + 2);
    f.mx(i) = c.mean(3 * i); f.my(i) = c.mean(3 * i + 1); f.mz(i) = c.mean(3 * i + 2);
  }
  f.gxx = f.wx.transpose() * f.wx;
  f.gyy = f.wy.transpose() * f.wy;
  const Eigen::MatrixXd gxy = f.wx.transpose() * f.wy;
  f.gxySym = gxy + gxy.transpose();
  f.gzz = f.wz.transpose() * f.wz;
  return f;
}

// Aᵀ(A v) restricted to the used points, for the conjugate-gradient M-step.
Eigen::VectorXd applyCameraNormal(const Points& p, const SnippetCamera& cam, const Eigen::VectorXd& v) {
  const double a = degToRad(cam.alphaDeg);
  const double ca = std::cos(a), sa = std::sin(a), s2 = cam.scale * cam.scale;
  Eigen::VectorXd out = Eigen::VectorXd::Zero(v.size());
  for (int i = 0; i < p.count; ++i) {
    if (!p.used[static_cast<size_t>(i)]) continue;
    const double u = ca * v(3 * i) + sa * v(3 * i + 1);
    out(3 * i) = s2 * ca * u;
    out(3 * i + 1) = s2 * sa * u;
    out(3 * i + 2) = s2 * v(3 * i + 2);
  }
  return out;
}

// M-step for x with several clusters responsible: H x = b with
// H = AᵀA/ν + Σ r_j C_j⁻¹, b = Aᵀ(y − t)/ν + Σ r_j C_j⁻¹ μ_j; H is symmetric positive
// definite, so conjugate gradients converge to the exact maximiser.
Eigen::VectorXd mixtureMStep(const SnippetPrior& prior, const Eigen::VectorXd& r, const Points& p,
                             const SnippetCamera& cam, double nu, const Eigen::VectorXd& start) {
  const double a = degToRad(cam.alphaDeg);
  const double ca = std::cos(a), sa = std::sin(a), s = cam.scale;
  Eigen::VectorXd b = Eigen::VectorXd::Zero(start.size());
  for (int i = 0; i < p.count; ++i) {
    if (!p.used[static_cast<size_t>(i)]) continue;
    const double eu = p.u(i) - cam.shift.x(), ev = p.v(i) - cam.shift.y();
    b(3 * i) = s * ca * eu / nu;
    b(3 * i + 1) = s * sa * eu / nu;
    b(3 * i + 2) = s * ev / nu;
  }
  std::vector<size_t> active;
  for (size_t j = 0; j < prior.components.size(); ++j)
    if (r(static_cast<Eigen::Index>(j)) > 1e-12) active.push_back(j);
  for (size_t j : active)
    b += r(static_cast<Eigen::Index>(j)) * applyInverseCovariance(prior.components[j], prior.components[j].mean);
  const auto apply = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd out = applyCameraNormal(p, cam, v) / nu;
    for (size_t j : active) out += r(static_cast<Eigen::Index>(j)) * applyInverseCovariance(prior.components[j], v);
    return out;
  };
  Eigen::VectorXd x = start;
  Eigen::VectorXd res = b - apply(x);
  Eigen::VectorXd dir = res;
  double rs = res.squaredNorm();
  const double stop = 1e-24 * std::max(b.squaredNorm(), 1e-300);
  for (int it = 0; it < 4 * static_cast<int>(x.size()) && rs > stop; ++it) {
    const Eigen::VectorXd hd = apply(dir);
    const double step = rs / dir.dot(hd);
    x += step * dir;
    res -= step * hd;
    const double next = res.squaredNorm();
    dir = res + (next / rs) * dir;
    rs = next;
  }
  return x;
}

double logPosteriorOf(const SnippetPrior& prior, const Points& p, const Eigen::VectorXd& x,
                      const SnippetCamera& cam, double nu) {
  const double miss = squaredMiss(p, pointCoords(x), cam);
  const double m = 2.0 * p.usedCount();
  return -0.5 * (miss / nu + m * std::log(kTwoPi * nu)) + logDensity(prior, x);
}

struct Run {
  Eigen::VectorXd x;
  SnippetCamera cam;
  Eigen::VectorXd resp;
  double logPosterior = -std::numeric_limits<double>::infinity();
  std::vector<double> trace;
  int iterations = 0;
};

Run runEm(const PreparedSnippetPrior& prep, const Points& p, Run run, double nu, const SnippetFitOptions& o) {
  const SnippetPrior& prior = prep.prior;
  run.logPosterior = logPosteriorOf(prior, p, run.x, run.cam, nu);
  for (int it = 0; it < o.maxIterations; ++it) {
    run.cam = cameraStep(p, run.x, run.cam, o);
    run.resp = responsibilitiesFromLog(weightedLogDensities(prior, run.x));
    Eigen::Index top = 0;
    const double rTop = run.resp.maxCoeff(&top);
    if (rTop > 1.0 - 1e-12) {
      // The joint maximiser over x and t: the shift moves with the snippet in one step.
      ClusterPosterior post = clusterPosterior(prior.components[static_cast<size_t>(top)],
                                               prep.factors[static_cast<size_t>(top)], p, run.cam, nu);
      run.x = std::move(post.snippet);
      run.cam.shift = post.shift;
    } else {
      run.x = mixtureMStep(prior, run.resp, p, run.cam, nu, run.x);
    }
    const double next = logPosteriorOf(prior, p, run.x, run.cam, nu);
    run.trace.push_back(next);
    ++run.iterations;
    const double change = next - run.logPosterior;
    run.logPosterior = next;
    if (std::abs(change) <= o.tolerance * std::max(1.0, std::abs(next))) break;
  }
  return run;
}

struct Start {
  SnippetCamera cam;
  size_t cluster = 0;
  double score = -std::numeric_limits<double>::infinity();
  Eigen::VectorXd x;
};

std::vector<Start> rankedStarts(const PreparedSnippetPrior& prep, const Points& p, double nuPerScale2,
                                const SnippetFitOptions& o) {
  std::vector<double> angles;
  if (o.alphaDeg) {
    angles.push_back(*o.alphaDeg);
  } else if (o.alphaStartDeg) {
    angles.push_back(*o.alphaStartDeg);
  } else {
    const double step = std::clamp(o.alphaStepDeg, 1.0, 180.0);
    for (double a = -180.0 + step; a <= 180.0 + 1e-9; a += step) angles.push_back(a);
  }
  // Each cluster mean's points once, not once per start angle.
  std::vector<PointCoords> means;
  for (const auto& comp : prep.prior.components) means.push_back(pointCoords(comp.mean));
  std::vector<Start> best;  // the best cluster per angle
  for (double alpha : angles) {
    Start top;
    for (size_t j = 0; j < prep.prior.components.size(); ++j) {
      const PpcaComponent& comp = prep.prior.components[j];
      const SnippetCamera cam = cameraAtAngle(p, means[j], alpha, o.scale);
      const double nu = nuPerScale2 * cam.scale * cam.scale;
      ClusterPosterior post = clusterPosterior(comp, prep.factors[j], p, cam, nu);
      const double score = std::log(comp.weight) + post.logMarginal;
      if (score > top.score) {
        top = Start{cam, j, score, std::move(post.snippet)};
        top.cam.shift = post.shift;
      }
    }
    best.push_back(std::move(top));
  }
  std::sort(best.begin(), best.end(), [](const Start& a, const Start& b) { return a.score > b.score; });
  if (best.size() > static_cast<size_t>(std::max(1, o.alphaStarts))) best.resize(static_cast<size_t>(std::max(1, o.alphaStarts)));
  return best;
}

void checkFitInput(const SnippetPrior& prior, const Eigen::Ref<const Eigen::MatrixXd>& y,
                   const SnippetFitOptions& o) {
  if (y.rows() != prior.frames || y.cols() != kDims2)
    fitError("the 2D snippet is " + std::to_string(y.rows()) + " × " + std::to_string(y.cols()) +
             ", expected " + std::to_string(prior.frames) + " frames × 30");
  if (o.alphaDeg && !std::isfinite(*o.alphaDeg)) fitError("the view angle must be finite");
  if (o.alphaStartDeg && !std::isfinite(*o.alphaStartDeg)) fitError("the start angle must be finite");
  if (o.scale && !(*o.scale > 0.0 && std::isfinite(*o.scale))) fitError("the scale must be positive");
  if (!(o.noiseSdMm > 0.0 && std::isfinite(o.noiseSdMm))) fitError("the noise SD must be positive");
  if (o.maxIterations < 1) fitError("at least one iteration");
  if (!(o.tolerance >= 0.0)) fitError("the tolerance must be ≥ 0");
}

// Points whose residual the broad outlier Gaussian explains better than the inlier one.
std::vector<bool> inlierPoints(const Points& p, const Eigen::VectorXd& x, const SnippetCamera& cam,
                               const SnippetFitOptions& o) {
  const PointCoords c = pointCoords(x);
  const double a = degToRad(cam.alphaDeg), ca = std::cos(a), sa = std::sin(a);
  std::vector<double> miss;
  Eigen::VectorXd e = Eigen::VectorXd::Zero(p.count);
  for (int i = 0; i < p.count; ++i) {
    if (!p.used[static_cast<size_t>(i)]) continue;
    e(i) = std::hypot(p.u(i) - cam.scale * (ca * c.x(i) + sa * c.y(i)) - cam.shift.x(),
                      p.v(i) - cam.scale * c.z(i) - cam.shift.y());
    miss.push_back(e(i));
  }
  std::nth_element(miss.begin(), miss.begin() + static_cast<long>(miss.size() / 2), miss.end());
  // Rayleigh: the median of a 2D Gaussian miss is σ √(2 ln 2) = 1.1774 σ.
  const double sd = std::max(miss[miss.size() / 2] / 1.1774, o.outlierFloorMm * cam.scale);
  const double broad = 10.0 * sd;
  std::vector<bool> keep = p.used;
  for (int i = 0; i < p.count; ++i) {
    if (!p.used[static_cast<size_t>(i)]) continue;
    const double logIn = std::log(0.95) - 0.5 * e(i) * e(i) / (sd * sd) - 2.0 * std::log(sd);
    const double logOut = std::log(0.05) - 0.5 * e(i) * e(i) / (broad * broad) - 2.0 * std::log(broad);
    if (logOut > logIn) keep[static_cast<size_t>(i)] = false;
  }
  return keep;
}

}  // namespace

PreparedSnippetPrior prepareSnippetPrior(const SnippetPrior& prior) {
  checkSnippetPrior(prior);
  PreparedSnippetPrior prep;
  prep.prior = prior;
  for (const auto& c : prior.components) prep.factors.push_back(makeFactors(c));
  return prep;
}

Eigen::MatrixXd renderSnippet(const Eigen::Ref<const Eigen::VectorXd>& snippet, int frames,
                              const SnippetCamera& cam) {
  const double a = degToRad(cam.alphaDeg), ca = std::cos(a), sa = std::sin(a);
  Eigen::MatrixXd y(frames, kDims2);
  for (int f = 0; f < frames; ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const Eigen::Index i = static_cast<Eigen::Index>(f) * kDims3 + 3 * j;
      y(f, 2 * j) = cam.scale * (ca * snippet(i) + sa * snippet(i + 1)) + cam.shift.x();
      y(f, 2 * j + 1) = cam.scale * snippet(i + 2) + cam.shift.y();
    }
  }
  return y;
}

double snippetLogPosterior(const SnippetPrior& prior, const Eigen::Ref<const Eigen::MatrixXd>& y,
                           const Eigen::Ref<const Eigen::VectorXd>& snippet,
                           const SnippetCamera& camera, double noiseVariance,
                           const std::vector<bool>& used) {
  return logPosteriorOf(prior, observedPoints(y, used), snippet, camera, noiseVariance);
}

ClusterMap clusterMap(const PpcaComponent& component, const Eigen::Ref<const Eigen::MatrixXd>& y,
                      const SnippetCamera& camera, double noiseVariance, const std::vector<bool>& used) {
  ClusterPosterior post =
      clusterPosterior(component, makeFactors(component), observedPoints(y, used), camera, noiseVariance);
  return {std::move(post.snippet), post.shift};
}

SnippetFit fitSnippet(const PreparedSnippetPrior& prep, const Eigen::Ref<const Eigen::MatrixXd>& y,
                      const SnippetFitOptions& o) {
  checkFitInput(prep.prior, y, o);
  Points p = observedPoints(y, {});
  if (p.usedCount() < 3) fitError("fewer than 3 points seen in the 2D snippet");
  const double noise2 = o.noiseSdMm * o.noiseSdMm;
  Run best;
  double nu = 0.0;
  for (const Start& s : rankedStarts(prep, p, noise2, o)) {
    Run run;
    run.x = s.x;
    run.cam = s.cam;
    const double runNu = noise2 * s.cam.scale * s.cam.scale;
    run = runEm(prep, p, std::move(run), runNu, o);
    if (run.logPosterior > best.logPosterior || best.x.size() == 0) { best = std::move(run); nu = runNu; }
  }
  std::vector<bool> kept = p.used;
  for (int round = 0; o.rejectOutliers && round < 3; ++round) {
    std::vector<bool> keep = inlierPoints(p, best.x, best.cam, o);
    if (keep == p.used || std::count(keep.begin(), keep.end(), true) < 3) break;
    p = observedPoints(y, keep);
    Run again = best;
    again.trace.clear();
    again = runEm(prep, p, std::move(again), nu, o);
    again.trace.insert(again.trace.begin(), best.trace.begin(), best.trace.end());
    best = std::move(again);
  }
  SnippetFit fit;
  fit.snippet = best.x;
  fit.camera = best.cam;
  fit.responsibilities = best.resp.size() ? best.resp : responsibilitiesFromLog(weightedLogDensities(prep.prior, best.x));
  fit.responsibilities.maxCoeff(&fit.cluster);
  fit.logPosterior = best.logPosterior;
  fit.trace = best.trace;
  fit.iterations = best.iterations;
  fit.outlierPoints.assign(static_cast<size_t>(p.count), false);
  const Points all = observedPoints(y, {});
  for (int i = 0; i < p.count; ++i)
    fit.outlierPoints[static_cast<size_t>(i)] = all.used[static_cast<size_t>(i)] && !p.used[static_cast<size_t>(i)];
  fit.reprojectionRms = std::sqrt(squaredMiss(p, pointCoords(best.x), best.cam) / std::max(1, p.usedCount()));
  return fit;
}

}  // namespace ew
