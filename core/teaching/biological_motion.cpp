#include "core/teaching/biological_motion.h"

#include <cmath>
#include <numbers>
#include <random>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"

namespace ew {
namespace {

[[noreturn]] void refuseDisplay(const std::string& problem) {
  throw Error(ErrorKind::BadArgument, "", "", "biological motion: " + problem);
}

// Uniform in [0, 1) from the engine's bits: std::uniform_real_distribution differs between
// standard libraries, and a display must be the same everywhere.
double unit(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// A fresh generator for one lifetime dot's one life: its place does not depend on the order
// in which times are asked for.
std::mt19937_64 lifeGenerator(std::uint64_t seed, int dot, long long life) {
  std::seed_seq s{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                  static_cast<std::uint32_t>(dot), static_cast<std::uint32_t>(life),
                  static_cast<std::uint32_t>(static_cast<unsigned long long>(life) >> 32)};
  return std::mt19937_64(s);
}

// Joint j at time t of the two-harmonic walker w (METHOD §3), mm.
Eigen::Vector3d fourierJoint(const Eigen::VectorXd& w, double omega, double phase, int j, double timeS) {
  const double theta = omega * timeS + phase;
  const double basis[kFourierBlocks] = {1.0, std::sin(theta), std::cos(theta), std::sin(2.0 * theta),
                                        std::cos(2.0 * theta)};
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (int b = 0; b < kFourierBlocks; ++b) p += basis[b] * w.segment<3>(b * 3 * kJointCount + 3 * j);
  return p;
}

}  // namespace

bool displayKeepsTheForm(const BiologicalMotionOptions& o) {
  return o.scramble == Scramble::None && o.dotLifetimeS <= 0.0;
}

BiologicalMotionDisplay::BiologicalMotionDisplay(const Eigen::Ref<const Eigen::VectorXd>& w, double omegaRadS,
                                                 double phaseRad, const BiologicalMotionOptions& options)
    : w_(w), omega_(omegaRadS), phase_(phaseRad), options_(options) {
  if (w.size() != kFourierDims3) refuseDisplay("a walker has 225 Fourier values, got " + std::to_string(w.size()));
  if (!w.allFinite() || !std::isfinite(phaseRad)) refuseDisplay("the walker has a value that is not finite");
  if (!(omegaRadS > 0.0) || !std::isfinite(omegaRadS)) refuseDisplay("the stride frequency must be positive");
  if (options.maskDots < 0 || options.maskDots > kMaxMaskDots)
    refuseDisplay("mask dots must be 0 to " + std::to_string(kMaxMaskDots));
  if (!std::isfinite(options.dotLifetimeS) || options.dotLifetimeS < 0.0) refuseDisplay("a dot's lifetime must be ≥ 0 s");
  if (options.dotLifetimeS > 0.0 && (options.lifetimeDots < 1 || options.lifetimeDots > kMaxLifetimeDots))
    refuseDisplay("lifetime dots must be 1 to " + std::to_string(kMaxLifetimeDots));
  if (!std::isfinite(options.speedMmS)) refuseDisplay("the speed must be finite");

  // The walker's extent over one cycle: the stage the scrambled and noise dots are put on.
  Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = -low;
  constexpr int kSamples = 64;
  for (int i = 0; i < kSamples; ++i)
    for (int j = 0; j < kJointCount; ++j) {
      const Eigen::Vector3d p = fourierJoint(w_, omega_, phase_, j, strideS() * i / kSamples);
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
  midHeightMm_ = 0.5 * (low.z() + high.z());
  const Eigen::Vector3d mid = 0.5 * (low + high), half = 0.5 * (high - low);
  meanMm_ = Eigen::Map<const Eigen::Matrix3Xd>(w_.data(), 3, kJointCount);

  std::mt19937_64 rng(options.seed);
  const auto placeIn = [&](const Eigen::Vector3d& centre, const Eigen::Vector3d& halfSize) {
    return Eigen::Vector3d(centre.x() + (2.0 * unit(rng) - 1.0) * halfSize.x(),
                           centre.y() + (2.0 * unit(rng) - 1.0) * halfSize.y(),
                           centre.z() + (2.0 * unit(rng) - 1.0) * halfSize.z());
  };
  jointPhaseS_.resize(kJointCount);
  jointPlaceMm_.resize(3, kJointCount);
  for (int j = 0; j < kJointCount; ++j) {
    jointPhaseS_(j) = unit(rng) * strideS();
    jointPlaceMm_.col(j) = placeIn(mid, half);
  }
  noiseSource_.resize(static_cast<size_t>(options.maskDots));
  noisePhaseS_.resize(options.maskDots);
  noisePlaceMm_.resize(3, options.maskDots);
  for (int k = 0; k < options.maskDots; ++k) {
    noiseSource_[static_cast<size_t>(k)] = static_cast<int>(unit(rng) * kJointCount);
    noisePhaseS_(k) = unit(rng) * strideS();
    noisePlaceMm_.col(k) = placeIn(mid, 2.0 * half);
  }
}

double BiologicalMotionDisplay::strideS() const { return 2.0 * std::numbers::pi / omega_; }

Eigen::Matrix3Xd BiologicalMotionDisplay::jointsAt(double t) const {
  Eigen::Matrix3Xd joints(3, kJointCount);
  for (int j = 0; j < kJointCount; ++j) {
    switch (options_.scramble) {
      case Scramble::None: joints.col(j) = fourierJoint(w_, omega_, phase_, j, t); break;
      case Scramble::Phase: joints.col(j) = fourierJoint(w_, omega_, phase_, j, t + jointPhaseS_(j)); break;
      case Scramble::Position:
        joints.col(j) = fourierJoint(w_, omega_, phase_, j, t) - meanMm_.col(j) + jointPlaceMm_.col(j);
        break;
    }
  }
  return joints;
}

DisplayDots BiologicalMotionDisplay::at(double timeS) const {
  // Walking backwards is the walk played in reverse, its progression too.
  const double t = options_.backwards ? -timeS : timeS;
  const Eigen::Matrix3Xd joints = jointsAt(t);
  DisplayDots dots;
  if (options_.dotLifetimeS > 0.0) {
    dots.walkerMm.resize(3, options_.lifetimeDots);
    for (int i = 0; i < options_.lifetimeDots; ++i) {
      // Lives are staggered: dot i's lives start i/n of a lifetime apart.
      const double age = timeS / options_.dotLifetimeS + static_cast<double>(i) / options_.lifetimeDots;
      std::mt19937_64 life = lifeGenerator(options_.seed, i, static_cast<long long>(std::floor(age)));
      const auto& [from, to] = kBones[static_cast<size_t>(unit(life) * kBones.size())];
      const double along = unit(life);
      dots.walkerMm.col(i) = (1.0 - along) * joints.col(index(from)) + along * joints.col(index(to));
    }
  } else {
    dots.walkerMm = joints;
  }
  dots.noiseMm.resize(3, options_.maskDots);
  for (int k = 0; k < options_.maskDots; ++k) {
    const int j = noiseSource_[static_cast<size_t>(k)];
    dots.noiseMm.col(k) = fourierJoint(w_, omega_, phase_, j, t + noisePhaseS_(k)) - meanMm_.col(j) + noisePlaceMm_.col(k);
  }
  if (options_.translating) dots.walkerMm.row(1).array() += options_.speedMmS * t;
  if (options_.inverted) {
    dots.walkerMm.row(2) = (2.0 * midHeightMm_ - dots.walkerMm.row(2).array()).matrix();
    // An empty matrix has no data to take a row of (UBSan: an offset on a null pointer).
    if (dots.noiseMm.cols() > 0) dots.noiseMm.row(2) = (2.0 * midHeightMm_ - dots.noiseMm.row(2).array()).matrix();
  }
  return dots;
}

Eigen::MatrixXd depthReversedFrames(const Eigen::Ref<const Eigen::MatrixXd>& frames, double alphaDeg) {
  if (frames.cols() % 3 != 0) refuseDisplay("frames must have x, y, z columns");
  if (!std::isfinite(alphaDeg)) refuseDisplay("the view angle must be finite");
  // The depth axis at α (projection.h: d = −x sin α + y cos α); p' = p − 2 d n.
  const double a = degToRad(alphaDeg);
  const Eigen::Vector3d n(-std::sin(a), std::cos(a), 0.0);
  Eigen::MatrixXd out = frames;
  for (Eigen::Index r = 0; r < out.rows(); ++r)
    for (Eigen::Index c = 0; c < out.cols(); c += 3) {
      const Eigen::Vector3d p = frames.row(r).segment<3>(c).transpose();
      out.row(r).segment<3>(c) = (p - 2.0 * p.dot(n) * n).transpose();
    }
  return out;
}

Eigen::VectorXd depthReversedWalker(const Eigen::Ref<const Eigen::VectorXd>& w, double alphaDeg) {
  if (w.size() != kFourierDims3) refuseDisplay("a walker has 225 Fourier values, got " + std::to_string(w.size()));
  // The reflection is linear, so each coefficient triple reflects as a point does.
  const Eigen::MatrixXd reflected = depthReversedFrames(w.transpose(), alphaDeg);
  return reflected.transpose();
}

}  // namespace ew
