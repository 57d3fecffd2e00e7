#include "core/eigenwalker/synthetic_walkers.h"

#include <cmath>
#include <random>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/fourier.h"

namespace ew {
namespace {

// Index of coordinate `axis` (0 x, 1 y, 2 z) of joint j in block b (0 p0, 1 p1, 2 q1,
// 3 p2, 4 q2) of a 225-vector.
int at(int block, Joint j, int axis) { return block * kDims3 + 3 * index(j) + axis; }

struct Pose {
  Joint joint;
  double x, y, z;  // mean posture, mm
};

constexpr Pose kMeanPosture[] = {
    {Joint::Head, 0, 10, 1650},      {Joint::Sternum, 0, 0, 1420},
    {Joint::Pelvis, 0, 0, 960},      {Joint::RShoulder, 180, -10, 1400},
    {Joint::RElbow, 200, -20, 1110}, {Joint::RWrist, 210, 20, 860},
    {Joint::LShoulder, -180, -10, 1400}, {Joint::LElbow, -200, -20, 1110},
    {Joint::LWrist, -210, 20, 860},  {Joint::RHip, 90, 0, 920},
    {Joint::RKnee, 95, 30, 520},     {Joint::RAnkle, 100, 0, 90},
    {Joint::LHip, -90, 0, 920},      {Joint::LKnee, -95, 30, 520},
    {Joint::LAnkle, -100, 0, 90},
};

// Fore-aft swing amplitude (mm, cos τ) of the left-side joints; the right side swings
// in antiphase, the arms against the legs.
struct Swing {
  Joint left, right;
  double amplitude;
};

constexpr Swing kSwings[] = {
    {Joint::LAnkle, Joint::RAnkle, 280}, {Joint::LKnee, Joint::RKnee, 160},
    {Joint::LHip, Joint::RHip, 35},      {Joint::LShoulder, Joint::RShoulder, -25},
    {Joint::LElbow, Joint::RElbow, -70}, {Joint::LWrist, Joint::RWrist, -140},
};

Eigen::VectorXd buildWalker(double size, const Eigen::VectorXd& swingGain, double bounce,
                            double sway, double lift) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(kFourierDims3);
  for (const auto& p : kMeanPosture) {
    w(at(0, p.joint, 0)) = size * p.x;
    w(at(0, p.joint, 1)) = size * p.y;
    w(at(0, p.joint, 2)) = size * p.z;
    const bool foot = p.joint == Joint::LAnkle || p.joint == Joint::RAnkle;
    w(at(4, p.joint, 2)) = foot ? 0.5 * bounce : bounce;          // 2nd-harmonic bounce
    w(at(1, p.joint, 0)) = foot ? 0.3 * sway : sway;              // lateral sway, sin τ
  }
  for (int i = 0; i < static_cast<int>(std::size(kSwings)); ++i) {
    const auto& s = kSwings[i];
    const double a = size * s.amplitude * swingGain(i);
    w(at(2, s.left, 1)) = a;
    w(at(2, s.right, 1)) = -a;
  }
  // Foot lift: z_l − z_r fundamental = 2·lift·sin τ (the phase reference, positive sine).
  w(at(1, Joint::LAnkle, 2)) = lift;
  w(at(1, Joint::RAnkle, 2)) = -lift;
  w(at(1, Joint::LKnee, 2)) = 0.4 * lift;
  w(at(1, Joint::RKnee, 2)) = -0.4 * lift;
  return w;
}

// Re-expressed so the fundamental of z_l_ankle − z_r_ankle is a pure positive sine again
// (METHOD §3), as a fitted walker would be.
Eigen::VectorXd phaseAligned(const Eigen::VectorXd& w) {
  const double rs = w(at(1, Joint::LAnkle, 2)) - w(at(1, Joint::RAnkle, 2));
  const double rc = w(at(2, Joint::LAnkle, 2)) - w(at(2, Joint::RAnkle, 2));
  return rephase(w, 0.0, std::atan2(rc, rs));
}

}  // namespace

Eigen::VectorXd syntheticBaseWalker() {
  return buildWalker(1.0, Eigen::VectorXd::Ones(std::size(kSwings)), 18.0, 20.0, 45.0);
}

Eigen::MatrixXd syntheticWalkerSet(int count, std::uint64_t seed) {
  // 225 doubles a walker: 100 000 walkers is 180 MB, far beyond any test or demo.
  constexpr int kMaxWalkers = 100'000;
  if (count < 1 || count > kMaxWalkers)
    throw Error(ErrorKind::BadArgument, "", "",
                "synthetic walkers: the count must be in [1, " + std::to_string(kMaxWalkers) +
                    "], got " + std::to_string(count));
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  Eigen::MatrixXd set(kFourierDims3, count);
  for (int r = 0; r < count; ++r) {
    Eigen::VectorXd gains(std::size(kSwings));
    for (auto& g : gains) g = 1.0 + 0.15 * unit(rng);
    const double size = 1.0 + 0.06 * unit(rng);
    Eigen::VectorXd w = buildWalker(size, gains, 18.0 * (1.0 + 0.2 * unit(rng)),
                                    20.0 * (1.0 + 0.3 * unit(rng)), 45.0 * (1.0 + 0.1 * unit(rng)));
    // Individual style: small independent offsets on every coefficient (mm), smaller on
    // the 2nd harmonic, as in real walkers.
    for (int i = 0; i < kFourierDims3; ++i) w(i) += (i < 3 * kDims3 ? 8.0 : 3.0) * unit(rng);
    set.col(r) = phaseAligned(w);
  }
  return set;
}

}  // namespace ew
