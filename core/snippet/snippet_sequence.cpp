#include "core/snippet/snippet_sequence.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/projection.h"

namespace ew {

namespace {

std::vector<int> snippetStarts(int frames, int length, int hop) {
  std::vector<int> starts;
  for (int s = 0; s + length <= frames; s += hop) starts.push_back(s);
  if (starts.back() + length < frames) starts.push_back(frames - length);
  return starts;
}

// A snippet in the view's frame: U, D, V (mm) per frame and joint, each S × 15.
struct ViewSnippet {
  Eigen::MatrixXd u, d, v;
};

ViewSnippet toView(const SnippetFit& fit, int frames) {
  const double a = degToRad(fit.camera.alphaDeg), c = std::cos(a), s = std::sin(a);
  ViewSnippet out{Eigen::MatrixXd(frames, kJointCount), Eigen::MatrixXd(frames, kJointCount),
                  Eigen::MatrixXd(frames, kJointCount)};
  for (int f = 0; f < frames; ++f) {
    for (int j = 0; j < kJointCount; ++j) {
      const Eigen::Index i = static_cast<Eigen::Index>(f) * kDims3 + 3 * j;
      const double x = fit.snippet(i), y = fit.snippet(i + 1), z = fit.snippet(i + 2);
      out.u(f, j) = c * x + s * y + fit.camera.shift.x() / fit.camera.scale;
      out.d(f, j) = -s * x + c * y;
      out.v(f, j) = z + fit.camera.shift.y() / fit.camera.scale;
    }
  }
  return out;
}

// Triangular stitching weight: 1 at the middle frame, small but positive at the ends.
double stitchWeight(int offset, int length) {
  const double half = 0.5 * (length - 1);
  return 1.0 - std::abs(offset - half) / (half + 1.0);
}

struct Stitched {
  Eigen::MatrixXd u, d, v;               // T × 15
  Eigen::MatrixXd weight;                // T × K, normalised per frame
};

Stitched stitch(const std::vector<ViewSnippet>& views, const std::vector<int>& starts, int frames, int length) {
  const int k = static_cast<int>(views.size());
  Stitched st{Eigen::MatrixXd::Zero(frames, kJointCount), Eigen::MatrixXd::Zero(frames, kJointCount),
              Eigen::MatrixXd::Zero(frames, kJointCount), Eigen::MatrixXd::Zero(frames, k)};
  for (int s = 0; s < k; ++s)
    for (int f = 0; f < length; ++f) st.weight(starts[static_cast<size_t>(s)] + f, s) = stitchWeight(f, length);
  for (int f = 0; f < frames; ++f) st.weight.row(f) /= st.weight.row(f).sum();
  for (int s = 0; s < k; ++s) {
    for (int f = 0; f < length; ++f) {
      const int t = starts[static_cast<size_t>(s)] + f;
      const double w = st.weight(t, s);
      st.u.row(t) += w * views[static_cast<size_t>(s)].u.row(f);
      st.d.row(t) += w * views[static_cast<size_t>(s)].d.row(f);
      st.v.row(t) += w * views[static_cast<size_t>(s)].v.row(f);
    }
  }
  return st;
}

// Frames where an ankle stands: the lower ankle, moving slowly in the image.
std::vector<std::pair<int, int>> stancePairs(const Stitched& st, double rateHz) {
  const int frames = static_cast<int>(st.u.rows());
  const int ankles[2] = {index(Joint::RAnkle), index(Joint::LAnkle)};
  std::vector<double> speeds;
  Eigen::MatrixXd speed(std::max(frames - 1, 0), 2);
  for (int f = 0; f + 1 < frames; ++f)
    for (int a = 0; a < 2; ++a) {
      speed(f, a) = std::hypot(st.u(f + 1, ankles[a]) - st.u(f, ankles[a]),
                               st.v(f + 1, ankles[a]) - st.v(f, ankles[a])) * rateHz;
      speeds.push_back(speed(f, a));
    }
  std::vector<std::pair<int, int>> pairs;  // (frame, ankle joint)
  if (speeds.empty()) return pairs;
  std::sort(speeds.begin(), speeds.end());
  const double limit = 0.2 * speeds[static_cast<size_t>(0.95 * static_cast<double>(speeds.size() - 1))];
  for (int f = 0; f + 1 < frames; ++f) {
    for (int a = 0; a < 2; ++a) {
      const int other = ankles[1 - a];
      const bool lower = st.v(f, ankles[a]) <= st.v(f, other) && st.v(f + 1, ankles[a]) <= st.v(f + 1, other);
      if (lower && speed(f, a) < limit) pairs.emplace_back(f, ankles[a]);
    }
  }
  return pairs;
}

// The clip's remaining slip along the line of sight: a constant depth velocity Γ, the
// negated median depth velocity of the standing ankle (a median: a few frames taken for
// stance in error do not move it). Returns Γ·(f − mean f) per frame.
Eigen::VectorXd stanceCorrection(const Stitched& st, const Eigen::VectorXd& depthFix, double rateHz, int& count) {
  std::vector<double> velocity;
  for (const auto& [f, joint] : stancePairs(st, rateHz))
    velocity.push_back((st.d(f + 1, joint) + depthFix(f + 1)) - (st.d(f, joint) + depthFix(f)));
  count = static_cast<int>(velocity.size());
  const Eigen::Index frames = st.d.rows();
  if (velocity.empty()) return Eigen::VectorXd::Zero(frames);
  std::nth_element(velocity.begin(), velocity.begin() + static_cast<long>(velocity.size() / 2), velocity.end());
  const double gamma = -velocity[velocity.size() / 2];
  const double mid = 0.5 * static_cast<double>(frames - 1);
  return Eigen::VectorXd::LinSpaced(frames, -mid, mid) * gamma;
}

// δ_k and γ_k (see the header) by least squares from the overlaps; returns the depth
// correction per frame (T, the same for every joint).
Eigen::VectorXd overlapCorrection(const std::vector<ViewSnippet>& views, const std::vector<int>& starts,
                                  const Stitched& st, int length) {
  const int k = static_cast<int>(views.size());
  const int frames = static_cast<int>(st.u.rows());
  const double half = 0.5 * (length - 1);
  std::vector<Eigen::VectorXd> rows;
  std::vector<double> rhs;
  const auto add = [&](Eigen::VectorXd row, double value, double weight) {
    rows.push_back(weight * row);
    rhs.push_back(weight * value);
  };
  for (int s = 0; s + 1 < k; ++s) {
    const int a0 = starts[static_cast<size_t>(s)], b0 = starts[static_cast<size_t>(s + 1)];
    for (int t = b0; t < a0 + length; ++t) {
      Eigen::VectorXd row = Eigen::VectorXd::Zero(2 * k);
      row(s) = 1.0;
      row(k + s) = (t - a0) - half;
      row(s + 1) = -1.0;
      row(k + s + 1) = -((t - b0) - half);
      const double diff = views[static_cast<size_t>(s)].d.row(t - a0).mean() -
                          views[static_cast<size_t>(s + 1)].d.row(t - b0).mean();
      add(row, -diff, 1.0);
    }
  }
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(2 * k);
  sum.head(k).setOnes();
  add(sum, 0.0, 1.0);
  for (int s = 0; s < k; ++s) {
    Eigen::VectorXd ridge = Eigen::VectorXd::Zero(2 * k);
    ridge(k + s) = half;
    add(ridge, 0.0, 0.1);
  }
  Eigen::MatrixXd a(static_cast<Eigen::Index>(rows.size()), 2 * k);
  Eigen::VectorXd b(static_cast<Eigen::Index>(rows.size()));
  for (size_t i = 0; i < rows.size(); ++i) {
    a.row(static_cast<Eigen::Index>(i)) = rows[i].transpose();
    b(static_cast<Eigen::Index>(i)) = rhs[i];
  }
  const Eigen::VectorXd p = a.colPivHouseholderQr().solve(b);
  Eigen::VectorXd correction = Eigen::VectorXd::Zero(frames);
  for (int s = 0; s < k; ++s)
    for (int f = 0; f < length; ++f) {
      const int t = starts[static_cast<size_t>(s)] + f;
      correction(t) += st.weight(t, s) * (p(s) + p(k + s) * (f - half));
    }
  return correction;
}

void checkSequenceInput(const SnippetPrior& prior, const Eigen::Ref<const Eigen::MatrixXd>& uv, double rateHz,
                        const SnippetSequenceOptions& o) {
  if (uv.cols() != kDims2)
    throw Error(ErrorKind::BadArgument, "snippets", "", "2D frames need 30 columns (u, v of 15 joints)");
  if (!(rateHz > 0.0 && rateHz <= 10000.0))
    throw Error(ErrorKind::BadArgument, "snippets", "", "the frame rate must be in (0, 10000] Hz");
  if (o.hop < 1) throw Error(ErrorKind::BadArgument, "snippets", "", "hop must be ≥ 1");
  const double needS = (prior.frames - 1) / prior.rateHz;
  const double haveS = static_cast<double>(uv.rows() - 1) / rateHz;
  if (uv.rows() < 2 || haveS + 1e-9 < needS)
    throw Error(ErrorKind::BadData, "snippets", "",
                "the clip spans " + std::to_string(std::max(0.0, haveS)) + " s; the snippet engine needs " +
                    std::to_string(needS) + " s (" + std::to_string(prior.frames) + " frames at " +
                    std::to_string(prior.rateHz) + " Hz)");
}

}  // namespace

// With an even count the two middle angles tie (every angle between them has the same sum),
// and which one rounding made the least would decide on the last bits of the fits.
double circularMedianDeg(const std::vector<double>& angles) {
  std::vector<double> cost(angles.size(), 0.0);
  for (std::size_t i = 0; i < angles.size(); ++i)
    for (double b : angles) cost[i] += std::abs(wrapDeg(angles[i] - b));
  const double least = *std::min_element(cost.begin(), cost.end());
  const double tie = 1e-9 * 180.0 * static_cast<double>(angles.size());  // far above rounding, far below a degree
  std::vector<double> tied;
  for (std::size_t i = 0; i < angles.size(); ++i)
    if (cost[i] <= least + tie) tied.push_back(angles[i]);
  if (tied.size() == 1) return tied.front();
  double sinSum = 0.0, cosSum = 0.0;
  for (double a : tied) {
    sinSum += std::sin(degToRad(a));
    cosSum += std::cos(degToRad(a));
  }
  return std::atan2(sinSum, cosSum) * 180.0 / std::numbers::pi;
}

SnippetSequence reconstructSnippetSequence(const PreparedSnippetPrior& prep,
                                           const Eigen::Ref<const Eigen::MatrixXd>& uv, double rateHz,
                                           const SnippetSequenceOptions& o) {
  const SnippetPrior& prior = prep.prior;
  checkSequenceInput(prior, uv, rateHz, o);
  const Eigen::MatrixXd y = resampleFrames(uv, rateHz, prior.rateHz);
  const int frames = static_cast<int>(y.rows()), length = prior.frames;
  SnippetSequence seq;
  seq.rateHz = prior.rateHz;
  seq.starts = snippetStarts(frames, length, o.hop);
  SnippetFitOptions fitOptions = o.fit;
  if (!fitOptions.alphaDeg) {
    for (int s : seq.starts)
      seq.freeAlphaDeg.push_back(fitSnippet(prep, y.middleRows(s, length), fitOptions).camera.alphaDeg);
    seq.alphaDeg = circularMedianDeg(seq.freeAlphaDeg);
    fitOptions.alphaStartDeg = seq.alphaDeg;
    fitOptions.alphaWindowDeg = o.localWindowDeg;
  } else {
    seq.alphaDeg = *fitOptions.alphaDeg;
  }
  std::vector<ViewSnippet> views;
  std::vector<double> scales;
  for (int s : seq.starts) {
    seq.snippets.push_back(fitSnippet(prep, y.middleRows(s, length), fitOptions));
    views.push_back(toView(seq.snippets.back(), length));
    scales.push_back(seq.snippets.back().camera.scale);
    seq.reprojectionRms += seq.snippets.back().reprojectionRms / static_cast<double>(seq.starts.size());
  }
  std::nth_element(scales.begin(), scales.begin() + static_cast<long>(scales.size() / 2), scales.end());
  seq.scale = scales[scales.size() / 2];
  const Stitched st = stitch(views, seq.starts, frames, length);
  Eigen::VectorXd dFix = overlapCorrection(views, seq.starts, st, length);
  if (o.groundContact) dFix += stanceCorrection(st, dFix, prior.rateHz, seq.stanceConstraints);
  // Back from the view (U, D, V) to the walker's frame at the clip's angle.
  const double a = degToRad(seq.alphaDeg), c = std::cos(a), s = std::sin(a);
  Eigen::MatrixXd world(frames, kDims3);
  for (int f = 0; f < frames; ++f)
    for (int j = 0; j < kJointCount; ++j) {
      const double u = st.u(f, j), d = st.d(f, j) + dFix(f);
      world(f, 3 * j) = c * u - s * d;
      world(f, 3 * j + 1) = s * u + c * d;
      world(f, 3 * j + 2) = st.v(f, j);
    }
  // Back to the input's frame times (the last resampled frame covers the tail).
  seq.framesMm.resize(uv.rows(), kDims3);
  for (Eigen::Index i = 0; i < uv.rows(); ++i) {
    const double pos = static_cast<double>(i) / rateHz * prior.rateHz;
    const int lo = std::min(static_cast<int>(std::floor(pos)), frames - 1);
    const int hi = std::min(lo + 1, frames - 1);
    const double w = std::min(pos - lo, 1.0);
    seq.framesMm.row(i) = (1.0 - w) * world.row(lo) + w * world.row(hi);
  }
  return seq;
}

}  // namespace ew
