#include "core/eigenwalker/fourier.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/common/symmetric_eigen.h"
#include "core/eigenwalker/minimize_1d.h"

namespace ew {
namespace {

using Matrix5d = Eigen::Matrix<double, 5, 5>;
using Vector5d = Eigen::Matrix<double, 5, 1>;

constexpr double kTwoPi = 2.0 * std::numbers::pi;
constexpr double kMinCycles = 0.99;     // "one full cycle", allowing frame quantisation
constexpr int kScanComponents = 6;      // principal components the ω scan looks at
constexpr double kScanRateHz = 25.0;    // the coarse scan runs on data decimated to ≥ this
constexpr double kHintVarianceSlack = 0.02;
// Coarse ω grid points at most: 20 per second of data for the default range, so 1e6
// points is 14 hours of frames; beyond that the rate is wrong or the data is not one walk.
constexpr double kMaxScanPoints = 1e6;

std::string formatHz(double omegaRadS) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f Hz", omegaRadS / kTwoPi);
  return buf;
}

// [SECTION] Input cleaning

struct CleanFrames {
  Eigen::MatrixXd centered;  // valid frames minus the column means
  Eigen::RowVectorXd mean;
  Eigen::VectorXd times;     // seconds, i / fs of each kept frame
  int dropped = 0;
  double durationS = 0.0;    // from the first to one past the last kept frame
};

[[noreturn]] void fitError(ErrorKind kind, const FourierFitOptions& options,
                           const std::string& problem) {
  throw Error(kind, options.file, "", "Fourier fit: " + problem);
}

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// The options' own preconditions (caller mistakes), checked before any data is looked at.
void checkOptions(const FourierFitOptions& o) {
  const auto positive = [](const std::optional<double>& v) {
    return !v || (std::isfinite(*v) && *v > 0.0);
  };
  if (!positive(o.omegaFixedRadS))
    fitError(
        ErrorKind::BadArgument, o,
        "the fixed ω must be positive and finite, got " + number(*o.omegaFixedRadS) + " rad/s");
  if (!positive(o.omegaHintRadS))
    fitError(ErrorKind::BadArgument, o,
             "the ω hint must be positive and finite, got " + number(*o.omegaHintRadS) + " rad/s");
  if (!o.omegaFixedRadS &&
      !(std::isfinite(o.omegaMaxRadS) && o.omegaMinRadS > 0.0 && o.omegaMinRadS < o.omegaMaxRadS))
    fitError(ErrorKind::BadArgument, o,
             "the ω scan range must satisfy 0 < min < max < ∞, got [" + number(o.omegaMinRadS) +
                 ", " + number(o.omegaMaxRadS) + "] rad/s");
  if (!(o.maxMissingFraction >= 0.0 && o.maxMissingFraction <= 1.0))
    fitError(ErrorKind::BadArgument, o,
             "the allowed missing fraction must be in [0, 1], got " + number(o.maxMissingFraction));
  if (!(o.hintAgreement >= 0.0 && std::isfinite(o.hintAgreement)))
    fitError(ErrorKind::BadArgument, o,
             "the hint agreement must be finite and ≥ 0, got " + number(o.hintAgreement));
}

CleanFrames cleanFrames(const Eigen::Ref<const Eigen::MatrixXd>& frames, double rateHz,
                        const FourierFitOptions& options) {
  const auto cols = frames.cols();
  if (cols != kDims3 && cols != kDims2)
    fitError(ErrorKind::BadArgument, options,
             "needs 45 (3D) or 30 (2D) columns, got " + std::to_string(cols));
  if (!(rateHz > 0.0) || !std::isfinite(rateHz))
    fitError(ErrorKind::BadArgument, options,
             "frame rate must be positive and finite, got " + number(rateHz) + " Hz");
  if (frames.rows() > std::numeric_limits<int>::max())
    fitError(ErrorKind::BadData, options, std::to_string(frames.rows()) + " frames are too many");
  const auto rows = static_cast<int>(frames.rows());
  if (rows == 0) fitError(ErrorKind::BadData, options, "no frames");
  std::vector<int> kept;
  kept.reserve(static_cast<size_t>(rows));
  for (int i = 0; i < rows; ++i) {
    if (frames.row(i).allFinite()) kept.push_back(i);
  }
  CleanFrames out;
  out.dropped = rows - static_cast<int>(kept.size());
  if (out.dropped > options.maxMissingFraction * rows) {
    fitError(ErrorKind::BadData, options,
             std::to_string(out.dropped) + " of " + std::to_string(rows) +
                 " frames have missing values (the Fourier fit allows " +
                 std::to_string(static_cast<int>(options.maxMissingFraction * 100)) + " %)");
  }
  if (kept.size() < 8)
    fitError(ErrorKind::BadData, options,
             "too few frames for a Fourier fit: " + std::to_string(kept.size()) +
                 " complete, at least 8 needed");
  const auto n = static_cast<Eigen::Index>(kept.size());
  if (out.dropped == 0) {  // the common case: one contiguous copy
    out.centered = frames;
    out.times = Eigen::VectorXd::LinSpaced(n, 0.0, static_cast<double>(n - 1) / rateHz);
  } else {
    out.centered.resize(n, cols);
    out.times.resize(n);
    for (Eigen::Index i = 0; i < n; ++i) {
      out.centered.row(i) = frames.row(kept[static_cast<size_t>(i)]);
      out.times(i) = kept[static_cast<size_t>(i)] / rateHz;
    }
  }
  out.mean = out.centered.colwise().mean();
  out.centered.rowwise() -= out.mean;
  // Finite coordinates can still overflow the sums of squares every step below relies on.
  if (!out.mean.allFinite() || !std::isfinite(out.centered.squaredNorm()))
    fitError(ErrorKind::BadData, options,
             "coordinates too large: their sums of squares overflow (a wrong unit?)");
  out.durationS = (kept.back() - kept.front() + 1) / rateHz;
  if (!std::isfinite(out.durationS))
    fitError(ErrorKind::BadData, options,
             std::to_string(rows) + " frames at " + number(rateHz) +
                 " Hz last longer than a double holds");
  return out;
}

// [SECTION] Variance explained as a function of ω

// Basis row [1, sin θ, cos θ, sin 2θ, cos 2θ] at phase angle θ = ωt (+ φ).
inline Vector5d basisRow(double angle) {
  const double s = std::sin(angle), c = std::cos(angle);
  Vector5d a;
  a << 1.0, s, c, 2.0 * s * c, c * c - s * s;
  return a;
}

Eigen::MatrixXd designMatrix(const Eigen::VectorXd& times, double omega) {
  Eigen::MatrixXd a(times.size(), 5);
  for (Eigen::Index i = 0; i < times.size(); ++i) a.row(i) = basisRow(omega * times(i)).transpose();
  return a;
}

// Signals for the scan (T × k), with their sample times.
struct ScanSignal {
  Eigen::MatrixXd values;
  Eigen::VectorXd times;
  double totalSS = 0.0;
  bool uniform = false;  // times(i) = times(0) + i·step (lets the basis use a recurrence)
  double step = 0.0;
};

void markUniform(ScanSignal& sig) {
  const Eigen::Index n = sig.times.size();
  sig.step = n > 1 ? (sig.times(n - 1) - sig.times(0)) / static_cast<double>(n - 1) : 0.0;
  sig.uniform = n > 1;
  for (Eigen::Index i = 0; i < n && sig.uniform; ++i)
    sig.uniform = std::abs(sig.times(i) - (sig.times(0) + static_cast<double>(i) * sig.step)) <= 1e-9 * sig.step;
}

// The basis [1, sin ωt, cos ωt, sin 2ωt, cos 2ωt] at the signal's times. Uniform times
// rotate a phasor (re-seeded every 64 samples so rounding cannot drift) instead of
// calling sin and cos per sample: the scan evaluates this a hundred times per fit.
void fillBasis(const ScanSignal& sig, double omega, Eigen::Matrix<double, Eigen::Dynamic, 5>& a) {
  const Eigen::Index n = sig.times.size();
  a.resize(n, 5);
  const double cd = std::cos(omega * sig.step), sd = std::sin(omega * sig.step);
  double c = 1.0, s = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!sig.uniform || i % 64 == 0) {
      c = std::cos(omega * sig.times(i));
      s = std::sin(omega * sig.times(i));
    } else {
      const double cn = c * cd - s * sd;
      s = s * cd + c * sd;
      c = cn;
    }
    a(i, 0) = 1.0;
    a(i, 1) = s;
    a(i, 2) = c;
    a(i, 3) = 2.0 * s * c;
    a(i, 4) = c * c - s * s;
  }
}

// Sum over the signals of the squared norm of their least-squares fit by the 5 basis
// functions (the signals are centred, so this is the variance explained, times T).
double explainedSS(const ScanSignal& sig, double omega) {
  Eigen::Matrix<double, Eigen::Dynamic, 5> a;
  fillBasis(sig, omega, a);
  // Coefficient-wise (lazy) products: small outputs of long contiguous dot products,
  // where GEMM's packing would cost more than the arithmetic.
  const Matrix5d g = a.transpose().lazyProduct(a);
  const Eigen::Matrix<double, 5, Eigen::Dynamic> b = a.transpose().lazyProduct(sig.values);
  const Eigen::LDLT<Matrix5d> ldlt(g);
  return (b.array() * ldlt.solve(b).array()).sum();
}

// The data's dominant principal directions (from the decimated frames), and the frames
// (full rate) and decimated frames expressed in them.
struct ScanSignals {
  ScanSignal full, decimated;
};

ScanSignals makeScanSignals(const CleanFrames& cf, double rateHz) {
  const Eigen::Index n = cf.centered.rows();
  // Block length in double first: rateHz / kScanRateHz may exceed any integer.
  const double blocks =
      std::clamp(std::floor(rateHz / kScanRateHz), 1.0, std::max(1.0, static_cast<double>(n / 8)));
  const auto m = static_cast<Eigen::Index>(blocks);
  const Eigen::Index nd = n / m;  // whole blocks only, so uniform frames stay uniform
  Eigen::MatrixXd dec(nd, cf.centered.cols());
  Eigen::VectorXd decTimes(nd);
  for (Eigen::Index g = 0; g < nd; ++g) {
    dec.row(g) = cf.centered.middleRows(g * m, m).colwise().mean();
    decTimes(g) = cf.times.segment(g * m, m).mean();
  }
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero(dec.cols(), dec.cols());
  gram.selfadjointView<Eigen::Lower>().rankUpdate(dec.transpose());
  const SymmetricEigen eig = symmetricEigen(gram);
  const auto k = std::min<Eigen::Index>(kScanComponents, dec.cols());
  const Eigen::MatrixXd basis = eig.vectors.rightCols(k);  // largest eigenvalues last
  ScanSignals s;
  // Lazy: a 480 × 45 by 45 × 6 product is cheaper than packing its operands for GEMM.
  s.full.values = cf.centered.lazyProduct(basis);
  s.full.times = cf.times;
  s.full.totalSS = s.full.values.squaredNorm();
  markUniform(s.full);
  s.decimated.values.noalias() = dec * basis;
  s.decimated.times = decTimes;
  s.decimated.totalSS = s.decimated.values.squaredNorm();
  markUniform(s.decimated);
  return s;
}

// [SECTION] ω scan and refinement

struct Peak {
  double omega = 0.0;
  double explained = 0.0;  // fraction of the scan signals' variance
  int gridIndex = -1;
};

struct Scan {
  std::vector<double> omegas, explained;  // coarse grid (decimated signals)
  std::vector<int> maxima;                // grid indices of local maxima
};

Scan coarseScan(const ScanSignal& sig, double lo, double hi, double durationS,
                const FourierFitOptions& options) {
  const double step = std::numbers::pi / (4.0 * durationS);
  // The grid grows with the duration: bounded before the cast and the allocation.
  const double points = std::ceil((hi - lo) / step) + 1.0;
  if (!(points <= kMaxScanPoints))
    fitError(ErrorKind::BadData, options,
             number(durationS) + " s of frames would need " + number(points) +
                 " frequency scan points (at most " + number(kMaxScanPoints) +
                 "): check the frame rate or cut the recording");
  const int count = std::max(3, static_cast<int>(points));
  Scan scan;
  scan.omegas.resize(static_cast<size_t>(count));
  scan.explained.resize(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double omega = lo + (hi - lo) * i / (count - 1);
    scan.omegas[static_cast<size_t>(i)] = omega;
    scan.explained[static_cast<size_t>(i)] = explainedSS(sig, omega);
  }
  const auto& f = scan.explained;
  for (int i = 0; i < count; ++i) {
    const auto u = static_cast<size_t>(i);
    const bool aboveLeft = i == 0 || f[u] >= f[u - 1];
    const bool aboveRight = i == count - 1 || f[u] > f[u + 1];
    if (aboveLeft && aboveRight) scan.maxima.push_back(i);
  }
  return scan;
}

Peak refinePeak(const ScanSignal& full, const Scan& scan, int gridIndex) {
  const auto last = static_cast<int>(scan.omegas.size()) - 1;
  const double lo = scan.omegas[static_cast<size_t>(std::max(0, gridIndex - 1))];
  const double hi = scan.omegas[static_cast<size_t>(std::min(last, gridIndex + 1))];
  const auto m = minimizeBrent([&](double w) { return -explainedSS(full, w); }, lo, hi,
                               1e-9 * hi);
  return {m.x, full.totalSS > 0 ? -m.value / full.totalSS : 0.0, gridIndex};
}

int bestMaximum(const Scan& scan, const FourierFitOptions& options) {
  // Finite values always have a maximum; only a non-finite scan leaves none.
  if (scan.maxima.empty())
    fitError(ErrorKind::BadData, options, "the frequency scan found no peak (non-finite variance)");
  return *std::max_element(scan.maxima.begin(), scan.maxima.end(), [&](int a, int b) {
    return scan.explained[static_cast<size_t>(a)] < scan.explained[static_cast<size_t>(b)];
  });
}

int maximumNearest(const Scan& scan, double omega) {
  return *std::min_element(scan.maxima.begin(), scan.maxima.end(), [&](int a, int b) {
    return std::abs(std::log(scan.omegas[static_cast<size_t>(a)] / omega)) <
           std::abs(std::log(scan.omegas[static_cast<size_t>(b)] / omega));
  });
}

void chooseOmega(const CleanFrames& cf, double rateHz, const FourierFitOptions& options,
                 FourierFit& fit) {
  if (options.omegaFixedRadS) {
    fit.omegaRadS = *options.omegaFixedRadS;
    fit.omegaSource = "fixed";
    return;
  }
  const double oneCycle = kTwoPi / cf.durationS;
  const double lo = std::max(options.omegaMinRadS, kMinCycles * oneCycle);
  const double hi = options.omegaMaxRadS;
  if (lo >= hi) {
    fitError(ErrorKind::BadData, options,
             "less than one gait cycle: " + std::to_string(cf.durationS) +
                 " s of frames, a cycle at the fastest allowed " + formatHz(hi) + " takes " +
                 std::to_string(kTwoPi / hi) + " s");
  }
  const ScanSignals signals = makeScanSignals(cf, rateHz);
  const Scan scan = coarseScan(signals.decimated, lo, hi, cf.durationS, options);
  const Peak best = refinePeak(signals.full, scan, bestMaximum(scan, options));
  if (best.omega - lo <= 1e-6 * lo) {
    // The variance explained still grows towards lower ω: the frames' dominant period
    // is longer than they are (or than the slowest gait allowed).
    const bool cycleBound = lo > options.omegaMinRadS;
    fitError(ErrorKind::BadData, options,
             cycleBound ? "less than one gait cycle: the motion's period is longer than the " +
                              std::to_string(cf.durationS) + " s of frames"
                        : "no gait frequency in range: the motion is slower than " +
                              formatHz(options.omegaMinRadS));
  }
  fit.scanOmegaRadS = best.omega;
  fit.omegaRadS = best.omega;
  fit.omegaSource = "scan";
  if (!options.omegaHintRadS) return;

  const double hint = *options.omegaHintRadS;
  const int near = maximumNearest(scan, hint);
  if (near == best.gridIndex) {
    fit.omegaSource = "scan, agrees with hint";
    if (std::abs(best.omega / hint - 1.0) > options.hintAgreement) {
      fit.warnings.push_back("gait events give " + formatHz(hint) + " but the spectrum peaks at " +
                             formatHz(best.omega) + "; using " + formatHz(best.omega));
    }
    return;
  }
  const Peak atHint = refinePeak(signals.full, scan, near);
  const bool hintPeakClose = std::abs(atHint.omega / hint - 1.0) <= options.hintAgreement;
  if (hintPeakClose && atHint.explained >= best.explained - kHintVarianceSlack) {
    fit.omegaRadS = atHint.omega;
    fit.omegaSource = "hint";
    fit.warnings.push_back("spectral scan prefers " + formatHz(best.omega) + " (" +
                           std::to_string(best.explained * 100) + " % explained) over the gait "
                           "events' " + formatHz(atHint.omega) + " (" +
                           std::to_string(atHint.explained * 100) + " %); using the events'");
  } else {
    fit.warnings.push_back("gait events give " + formatHz(hint) +
                           ", which the frames do not support; using the spectral estimate " +
                           formatHz(best.omega));
  }
}

// [SECTION] Phase alignment

// Columns of the ankle heights (3D: z, 2D: v) that define the phase reference r(t).
std::pair<int, int> ankleHeightColumns(int dims) {
  const int per = dims / kJointCount;  // 3 or 2
  return {per * index(Joint::LAnkle) + per - 1, per * index(Joint::RAnkle) + per - 1};
}

double wrapPi(double a) {
  a = std::remainder(a, kTwoPi);  // [−π, π]
  return a <= -std::numbers::pi ? a + kTwoPi : a;
}

}  // namespace

// [SECTION] Public API

Eigen::VectorXd frameTimes(int count, double rateHz) {
  if (count < 0)
    throw Error(ErrorKind::BadArgument, "", "",
                "frame times: the frame count must be ≥ 0, got " + std::to_string(count));
  if (!(rateHz > 0.0) || !std::isfinite(rateHz))
    throw Error(
        ErrorKind::BadArgument, "", "",
        "frame times: frame rate must be positive and finite, got " + number(rateHz) + " Hz");
  return Eigen::VectorXd::LinSpaced(count, 0.0, (count - 1) / rateHz);
}

Eigen::VectorXd rephase(const Eigen::Ref<const Eigen::VectorXd>& w, double fromPhaseRad,
                        double toPhaseRad) {
  if (w.size() != kFourierDims3 && w.size() != kFourierDims2)
    throw Error(ErrorKind::BadArgument, "", "",
                "rephase: w must have 225 or 150 values, got " + std::to_string(w.size()));
  if (!std::isfinite(fromPhaseRad) || !std::isfinite(toPhaseRad))
    throw Error(ErrorKind::BadArgument, "", "",
                "rephase: phases must be finite, got " + number(fromPhaseRad) + " and " +
                    number(toPhaseRad) + " rad");
  const Eigen::Index d = w.size() / kFourierBlocks;
  Eigen::VectorXd out = w;
  for (int h = 1; h <= 2; ++h) {
    const double beta = h * (fromPhaseRad - toPhaseRad);
    const double c = std::cos(beta), s = std::sin(beta);
    const auto p = w.segment((2 * h - 1) * d, d);
    const auto q = w.segment(2 * h * d, d);
    out.segment((2 * h - 1) * d, d) = c * p - s * q;
    out.segment(2 * h * d, d) = s * p + c * q;
  }
  return out;
}

Eigen::MatrixXd synthesizeFrames(const Eigen::Ref<const Eigen::VectorXd>& w, double omegaRadS,
                                 double phaseRad, const Eigen::Ref<const Eigen::VectorXd>& timesS) {
  if (w.size() != kFourierDims3 && w.size() != kFourierDims2)
    throw Error(
        ErrorKind::BadArgument, "", "",
        "Fourier synthesis: w must have 225 or 150 values, got " + std::to_string(w.size()));
  if (!w.allFinite())
    throw Error(ErrorKind::BadArgument, "", "", "Fourier synthesis: w has non-finite values");
  if (!std::isfinite(omegaRadS) || !std::isfinite(phaseRad))
    throw Error(ErrorKind::BadArgument, "", "",
                "Fourier synthesis: ω and φ must be finite, got " + number(omegaRadS) +
                    " rad/s and " + number(phaseRad) + " rad");
  if (!timesS.allFinite())
    throw Error(ErrorKind::BadArgument, "", "", "Fourier synthesis: the times must be finite");
  const Eigen::Index d = w.size() / kFourierBlocks;
  // Row-wise basis times the 5 × d coefficient blocks: one small GEMM.
  const Eigen::Map<const Eigen::MatrixXd> blocks(w.data(), d, kFourierBlocks);
  return fourierBasis(omegaRadS, phaseRad, timesS) * blocks.transpose();
}

Eigen::MatrixXd fourierBasis(double omegaRadS, double phaseRad, const Eigen::Ref<const Eigen::VectorXd>& timesS) {
  Eigen::MatrixXd a(timesS.size(), kFourierBlocks);
  for (Eigen::Index i = 0; i < timesS.size(); ++i)
    a.row(i) = basisRow(omegaRadS * timesS(i) + phaseRad).transpose();
  return a;
}

Eigen::MatrixXd fourierBasisPhaseDerivative(double omegaRadS, double phaseRad,
                                            const Eigen::Ref<const Eigen::VectorXd>& timesS) {
  Eigen::MatrixXd a(timesS.size(), kFourierBlocks);
  for (Eigen::Index i = 0; i < timesS.size(); ++i) {
    const double angle = omegaRadS * timesS(i) + phaseRad, s = std::sin(angle), c = std::cos(angle);
    a.row(i) << 0.0, c, -s, 2.0 * (c * c - s * s), -4.0 * s * c;
  }
  return a;
}

FourierFit fitFourier(const Eigen::Ref<const Eigen::MatrixXd>& frames, double rateHz,
                      const FourierFitOptions& options) {
  checkOptions(options);
  const CleanFrames cf = cleanFrames(frames, rateHz, options);
  FourierFit fit;
  fit.framesUsed = static_cast<int>(cf.centered.rows());
  fit.framesDropped = cf.dropped;
  if (cf.dropped > 0)
    fit.warnings.push_back(std::to_string(cf.dropped) + " frames with missing values left out");
  chooseOmega(cf, rateHz, options, fit);
  fit.cycles = fit.omegaRadS * cf.durationS / kTwoPi;
  if (fit.cycles < kMinCycles) {
    fitError(ErrorKind::BadData, options,
             "less than one gait cycle: " + std::to_string(fit.cycles) + " cycles at " +
                 formatHz(fit.omegaRadS));
  }
  // Sampling must resolve the second harmonic (2ω below the Nyquist frequency πfs): at or
  // above it the basis columns alias, the 5 × 5 normal equations are singular and the
  // solve would quietly return zeros for the aliased coefficients.
  if (!(2.0 * fit.omegaRadS < std::numbers::pi * rateHz)) {
    fitError(ErrorKind::BadData, options,
             number(rateHz) + " Hz frames cannot resolve the second harmonic of a " +
                 formatHz(fit.omegaRadS) + " gait (the rate must exceed " +
                 number(4.0 * fit.omegaRadS / kTwoPi) + " Hz)");
  }

  // Least squares at ω with phase 0: coefficients x (5 × d) = G⁻¹ Aᵀ P.
  const Eigen::MatrixXd a = designMatrix(cf.times, fit.omegaRadS);
  const Matrix5d g = a.transpose().lazyProduct(a);
  const Eigen::MatrixXd atp = a.transpose().lazyProduct(cf.centered);
  const Eigen::MatrixXd x = Eigen::LDLT<Matrix5d>(g).solve(atp);
  const Eigen::Index d = cf.centered.cols();
  Eigen::VectorXd w0(kFourierBlocks * d);
  w0.head(d) = (cf.mean + x.row(0)).transpose();
  for (int b = 1; b < kFourierBlocks; ++b) w0.segment(b * d, d) = x.row(b).transpose();

  // Phase: the fundamental of r = z_l_ankle − z_r_ankle, a sin ωt + b cos ωt, equals
  // A sin(ωt + θ) with θ = atan2(b, a); expressing w with φ = θ makes it a pure +sine.
  const auto [lCol, rCol] = ankleHeightColumns(static_cast<int>(d));
  const double rs = x(1, lCol) - x(1, rCol), rc = x(2, lCol) - x(2, rCol);
  // Sums of squares from the normal equations (the fit is orthogonal to its residual):
  // ‖P − A x‖² = ‖P‖² − Σ x∘(AᵀP), and around p0: ‖P − 1 x₀‖² = ‖P‖² + T‖x₀‖² (P centred).
  const double dataSS = cf.centered.squaredNorm();
  const double residualSS = std::max(0.0, dataSS - (x.array() * atp.array()).sum());
  const double total = dataSS + static_cast<double>(cf.centered.rows()) * x.row(0).squaredNorm();
  const double scale = std::sqrt(total / static_cast<double>(cf.centered.size())) + 1e-300;
  if (!x.allFinite() || !std::isfinite(total))
    fitError(ErrorKind::BadData, options, "the least-squares fit gave non-finite coefficients");
  if (std::hypot(rs, rc) <= 1e-9 * scale) {
    fitError(ErrorKind::BadData, options,
             "the ankle height difference has no fundamental: cannot align the phase");
  }
  fit.phaseRad = wrapPi(std::atan2(rc, rs));
  fit.w = rephase(w0, 0.0, fit.phaseRad);

  const double perFrame = total / static_cast<double>(cf.centered.rows());
  const auto harmonicVar = [&](int h) {
    return 0.5 * (x.row(2 * h - 1).squaredNorm() + x.row(2 * h).squaredNorm());
  };
  fit.h1Share = perFrame > 0 ? harmonicVar(1) / perFrame : 0.0;
  fit.h2Share = perFrame > 0 ? harmonicVar(2) / perFrame : 0.0;
  fit.residualShare = total > 0 ? residualSS / total : 0.0;
  return fit;
}

}  // namespace ew
