// The classic displays of biological motion (core/teaching/biological_motion.h): each keeps
// what the literature says it keeps — a dot's own trajectory, its own motion, the image —
// and destroys what it says it destroys.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/common/errors.h"
#include "core/common/skeleton.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"
#include "core/teaching/biological_motion.h"

namespace ew {
namespace {

constexpr double kOmega = 2.0 * std::numbers::pi * 0.9;  // 0.9 strides a second
constexpr double kPhase = 0.3;

const Eigen::VectorXd& walker() {
  static const Eigen::VectorXd w = defaultRealModel().mean;
  return w;
}

// The walker's own joints at t (synthesizeFrames, the reference for every display).
Eigen::Matrix3Xd joints(double t) {
  Eigen::VectorXd times(1);
  times << t;
  const Eigen::MatrixXd f = synthesizeFrames(walker(), kOmega, kPhase, times);
  return Eigen::Map<const Eigen::Matrix3Xd>(f.data(), 3, kJointCount);
}

BiologicalMotionDisplay display(const BiologicalMotionOptions& o) {
  return BiologicalMotionDisplay(walker(), kOmega, kPhase, o);
}

double strideS() { return 2.0 * std::numbers::pi / kOmega; }

// The smallest distance from p to joint j's path over a cycle (sampled finely).
double distanceToPath(const Eigen::Vector3d& p, int j, const Eigen::Vector3d& shift = Eigen::Vector3d::Zero()) {
  double best = INFINITY;
  for (int i = 0; i < 4000; ++i) best = std::min(best, (joints(strideS() * i / 4000).col(j) + shift - p).norm());
  return best;
}

TEST(BiologicalMotion, ThePlainDisplayIsTheWalker) {
  const auto d = display({});
  for (double t : {0.0, 0.37, 1.9}) {
    EXPECT_LT((d.at(t).walkerMm - joints(t)).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_EQ(d.at(t).noiseMm.cols(), 0);
  }
  EXPECT_TRUE(displayKeepsTheForm({}));
}

TEST(BiologicalMotion, PhaseScrambledDotsKeepTheirOwnTrajectoriesNotTheForm) {
  BiologicalMotionOptions o;
  o.scramble = Scramble::Phase;
  const auto d = display(o);
  double apart = 0.0;
  for (int k = 0; k < 12; ++k) {
    const double t = strideS() * k / 12.0;
    const Eigen::Matrix3Xd dots = d.at(t).walkerMm;
    for (int j = 0; j < kJointCount; ++j) EXPECT_LT(distanceToPath(dots.col(j), j), 1.0) << j;
    apart = std::max(apart, (dots - joints(t)).colwise().norm().maxCoeff());
  }
  EXPECT_GT(apart, 100.0);  // the dots are not where the walker's joints are together
  EXPECT_FALSE(displayKeepsTheForm(o));
}

TEST(BiologicalMotion, PositionScrambledDotsKeepTheirOwnMotionElsewhere) {
  BiologicalMotionOptions o;
  o.scramble = Scramble::Position;
  const auto d = display(o);
  const Eigen::Matrix3Xd d0 = d.at(0.0).walkerMm, j0 = joints(0.0);
  for (double t : {0.2, 0.55, 1.3}) {
    const Eigen::Matrix3Xd motion = d.at(t).walkerMm - d0, own = joints(t) - j0;
    EXPECT_LT((motion - own).cwiseAbs().maxCoeff(), 1e-9);
  }
  EXPECT_GT((d0 - j0).colwise().norm().maxCoeff(), 100.0);
}

TEST(BiologicalMotion, MaskDotsMoveAsTheWalkersDotsDo) {
  BiologicalMotionOptions o;
  o.maskDots = 6;
  const auto d = display(o);
  ASSERT_EQ(d.at(0.0).noiseMm.cols(), 6);
  // Each noise dot traces some joint's path, moved: its path's extent is that joint's.
  for (int k = 0; k < 6; ++k) {
    Eigen::Vector3d low = Eigen::Vector3d::Constant(INFINITY), high = -low;
    for (int i = 0; i < 2000; ++i) {
      const Eigen::Vector3d p = d.at(strideS() * i / 2000).noiseMm.col(k);
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    double best = INFINITY;
    for (int j = 0; j < kJointCount; ++j) {
      Eigen::Vector3d jl = Eigen::Vector3d::Constant(INFINITY), jh = -jl;
      for (int i = 0; i < 2000; ++i) {
        jl = jl.cwiseMin(joints(strideS() * i / 2000).col(j));
        jh = jh.cwiseMax(joints(strideS() * i / 2000).col(j));
      }
      best = std::min(best, ((high - low) - (jh - jl)).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(best, 0.5) << "noise dot " << k;
  }
}

TEST(BiologicalMotion, TheSameSeedGivesTheSameDisplay) {
  BiologicalMotionOptions o;
  o.scramble = Scramble::Position;
  o.maskDots = 20;
  const auto a = display(o), b = display(o);
  EXPECT_EQ(a.at(0.7).noiseMm, b.at(0.7).noiseMm);
  EXPECT_EQ(a.at(0.7).walkerMm, b.at(0.7).walkerMm);
  o.seed = 2;
  EXPECT_NE(display(o).at(0.7).noiseMm, a.at(0.7).noiseMm);
}

TEST(BiologicalMotion, InvertedIsUpsideDownAboutTheSameMiddle) {
  BiologicalMotionOptions o;
  o.inverted = true;
  const auto d = display(o);
  const double sum0 = d.at(0.0).walkerMm(2, 0) + joints(0.0)(2, 0);
  for (double t : {0.0, 0.4, 0.9})
    for (int j = 0; j < kJointCount; ++j) {
      EXPECT_NEAR(d.at(t).walkerMm(2, j) + joints(t)(2, j), sum0, 1e-9);
      EXPECT_NEAR(d.at(t).walkerMm(0, j), joints(t)(0, j), 1e-12);
    }
  // The head is now below the ankles.
  EXPECT_LT(d.at(0.0).walkerMm(2, index(Joint::Head)), d.at(0.0).walkerMm(2, index(Joint::LAnkle)));
}

TEST(BiologicalMotion, BackwardsIsTheWalkPlayedInReverseProgressionToo) {
  BiologicalMotionOptions o;
  o.backwards = true;
  o.translating = true;
  o.speedMmS = 1200.0;
  const auto d = display(o);
  BiologicalMotionOptions forward = o;
  forward.backwards = false;
  const auto f = display(forward);
  EXPECT_LT((d.at(0.8).walkerMm - f.at(-0.8).walkerMm).cwiseAbs().maxCoeff(), 1e-9);
  // Translating: the pelvis moves forward at the speed (walking in place plus v t).
  EXPECT_NEAR(f.at(1.0).walkerMm(1, 2) - joints(1.0)(1, 2), 1200.0, 1e-9);
  EXPECT_NEAR(d.at(1.0).walkerMm(1, 2) - joints(-1.0)(1, 2), -1200.0, 1e-9);
}

TEST(BiologicalMotion, LifetimeDotsSitOnTheLimbsAndMoveOnWhenTheyDie) {
  BiologicalMotionOptions o;
  o.dotLifetimeS = 0.2;
  o.lifetimeDots = 8;
  const auto d = display(o);
  EXPECT_FALSE(displayKeepsTheForm(o));
  const auto onALimb = [&](const Eigen::Vector3d& p, double t) {
    const Eigen::Matrix3Xd j = joints(t);
    double best = INFINITY;
    for (const auto& [a, b] : kBones) {
      const Eigen::Vector3d u = j.col(index(a)), v = j.col(index(b));
      const double s = std::clamp((p - u).dot(v - u) / (v - u).squaredNorm(), 0.0, 1.0);
      best = std::min(best, (u + s * (v - u) - p).norm());
    }
    return best;
  };
  for (double t : {0.0, 0.13, 0.61})
    for (int i = 0; i < 8; ++i) EXPECT_LT(onALimb(d.at(t).walkerMm.col(i), t), 1e-9);
  // Dot 0 lives [0, 0.2) s: the same place on its limb at 0.05 and 0.15, another at 0.25.
  const Eigen::Matrix3Xd j1 = joints(0.05), j2 = joints(0.15);
  const auto fraction = [](const Eigen::Matrix3Xd& j, const Eigen::Vector3d& p) {
    for (const auto& [a, b] : kBones) {
      const Eigen::Vector3d u = j.col(index(a)), v = j.col(index(b));
      const double s = (p - u).dot(v - u) / (v - u).squaredNorm();
      if ((u + s * (v - u) - p).norm() < 1e-9 && s >= 0 && s <= 1) return index(a) * 100 + index(b) + s;
    }
    return -1.0;
  };
  EXPECT_NEAR(fraction(j1, d.at(0.05).walkerMm.col(0)), fraction(j2, d.at(0.15).walkerMm.col(0)), 1e-9);
  EXPECT_NE(fraction(joints(0.25), d.at(0.25).walkerMm.col(0)), fraction(j1, d.at(0.05).walkerMm.col(0)));
}

// The 2D→3D ambiguity: the walker mirrored in depth projects to the same image at that view.
TEST(BiologicalMotion, TheDepthReversedWalkerProjectsToTheSameImage) {
  for (double alpha : {0.0, 30.0, -75.0, 90.0, 160.0}) {
    const Eigen::VectorXd mirrored = depthReversedWalker(walker(), alpha);
    EXPECT_LT((projectToView(mirrored, alpha) - projectToView(walker(), alpha)).cwiseAbs().maxCoeff(), 1e-6) << alpha;
    EXPECT_LT((depthAtView(mirrored, alpha) + depthAtView(walker(), alpha)).cwiseAbs().maxCoeff(), 1e-6) << alpha;
    EXPECT_GT((mirrored - walker()).cwiseAbs().maxCoeff(), 50.0) << alpha;  // another walker in 3D
    const Eigen::MatrixXd frames = synthesizeFrames(walker(), kOmega, kPhase, frameTimes(20, 30.0));
    EXPECT_LT((projectFramesToView(depthReversedFrames(frames, alpha), alpha) - projectFramesToView(frames, alpha))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-6);
  }
}

TEST(BiologicalMotion, RefusesWhatCannotBeShown) {
  EXPECT_THROW(BiologicalMotionDisplay(Eigen::VectorXd::Zero(10), kOmega, 0.0, {}), Error);
  EXPECT_THROW(BiologicalMotionDisplay(walker(), 0.0, 0.0, {}), Error);
  Eigen::VectorXd bad = walker();
  bad(7) = NAN;
  EXPECT_THROW(BiologicalMotionDisplay(bad, kOmega, 0.0, {}), Error);
  BiologicalMotionOptions o;
  o.maskDots = kMaxMaskDots + 1;
  EXPECT_THROW(display(o), Error);
  o = {};
  o.dotLifetimeS = NAN;
  EXPECT_THROW(display(o), Error);
  EXPECT_THROW(depthReversedWalker(walker(), NAN), Error);
}

}  // namespace
}  // namespace ew
