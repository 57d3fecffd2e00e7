#pragma once
// Bracketed 1-D minimisation (Brent: golden section with parabolic steps), used by the
// ω refinement of the Fourier fit (METHOD §3) and the view-angle refinement (METHOD §6).
// Header-only so the objective inlines: both callers evaluate it in tight loops.

#include <cmath>
#include <limits>
#include <string>

#include "core/common/errors.h"

namespace ew {

struct Minimum1d {
  double x = 0.0;
  double value = 0.0;
  int evaluations = 0;
};

// Minimises f on [lo, hi] until the bracket is narrower than about 2·xTol (absolute).
// Finds a local minimum; the caller brackets the one it wants. Needs finite lo ≤ hi, a
// positive finite xTol and maxEvaluations ≥ 1 (else Error(BadArgument)). f should be
// finite: callers check their result (a NaN value ends as the returned one).
template <class F>
Minimum1d minimizeBrent(F&& f, double lo, double hi, double xTol, int maxEvaluations = 200) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi) ||
      !(xTol > 0.0 && std::isfinite(xTol)) || maxEvaluations < 1)
    throw Error(ErrorKind::BadArgument, "", "",
                "1-D minimisation: needs a finite bracket lo ≤ hi and a positive tolerance, got [" +
                    std::to_string(lo) + ", " + std::to_string(hi) + "], tolerance " +
                    std::to_string(xTol));
  constexpr double kGolden = 0.3819660112501051;  // (3 − √5) / 2
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  double x = lo + kGolden * (hi - lo);
  double w = x, v = x;
  double fx = f(x);
  double fw = fx, fv = fx;
  double step = 0.0, previousStep = 0.0;
  int evaluations = 1;
  while (evaluations < maxEvaluations) {
    const double mid = 0.5 * (lo + hi);
    const double tol1 = xTol + 4.0 * kEps * std::abs(x);
    const double tol2 = 2.0 * tol1;
    if (std::abs(x - mid) <= tol2 - 0.5 * (hi - lo)) break;
    bool useGolden = true;
    if (std::abs(previousStep) > tol1) {
      // Parabola through (x, fx), (w, fw), (v, fv); accept its vertex only if it falls
      // inside the bracket and the step shrinks fast enough (else golden section).
      const double r = (x - w) * (fx - fv);
      double q = (x - v) * (fx - fw);
      double p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0.0) p = -p;
      q = std::abs(q);
      const double older = previousStep;
      previousStep = step;
      if (std::abs(p) < std::abs(0.5 * q * older) && p > q * (lo - x) && p < q * (hi - x)) {
        step = p / q;
        const double u = x + step;
        if (u - lo < tol2 || hi - u < tol2) step = std::copysign(tol1, mid - x);
        useGolden = false;
      }
    }
    if (useGolden) {
      previousStep = (x >= mid) ? lo - x : hi - x;
      step = kGolden * previousStep;
    }
    const double u = std::abs(step) >= tol1 ? x + step : x + std::copysign(tol1, step);
    const double fu = f(u);
    ++evaluations;
    if (fu <= fx) {
      if (u >= x) lo = x; else hi = x;
      v = w; fv = fw;
      w = x; fw = fx;
      x = u; fx = fu;
    } else {
      if (u < x) lo = u; else hi = u;
      if (fu <= fw || w == x) {
        v = w; fv = fw;
        w = u; fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u; fv = fu;
      }
    }
  }
  return {x, fx, evaluations};
}

}  // namespace ew
