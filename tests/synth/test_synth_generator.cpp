// The synthetic walker generator (core/synth): determinism, anatomy, floor contact and
// the gait features it claims to reproduce (docs/SYNTHETIC.md).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "core/common/errors.h"
#include "core/eigenwalker/fourier.h"
#include "core/gait/prepare.h"
#include "core/io/joint_csv.h"
#include "core/synth/normative_gait.h"
#include "core/synth/population.h"
#include "core/synth/random.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

PopulationOptions smallPopulation(int count, std::uint64_t seed = 7) {
  PopulationOptions o;
  o.count = count;
  o.seed = seed;
  return o;
}

std::string fileBytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

Eigen::VectorXd column(const JointTrial& t, Joint j, int axis) {
  return t.positionsMm.col(3 * index(j) + axis);
}

// [SECTION] Random numbers and curves

TEST(SynthRandom, XoshiroStreamIsFixedAndNormalsAreStandard) {
  // xoshiro256** seeded by SplitMix64 is fully specified: pin the first value so a change
  // of generator (and so of every synthetic walker) cannot pass unnoticed.
  Rng a(42), b(42);
  const std::uint64_t first = a.next();
  EXPECT_EQ(first, b.next());
  Rng c(43);
  EXPECT_NE(first, c.next());
  Rng r(1);
  double sum = 0.0, sumSq = 0.0;
  constexpr int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double x = r.normal();
    sum += x;
    sumSq += x * x;
  }
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(sumSq / n, 1.0, 0.01);
  EXPECT_NE(childSeed(5, 0), childSeed(5, 1));
}

TEST(SynthNormativeCurves, ReproduceTheNormativeLandmarks) {
  const PeriodicCurve& knee = normativeKneeFlexion();
  const PeriodicCurve& hip = normativeHipFlexion();
  const PeriodicCurve& ankle = normativeAnkleDorsiflexion();
  double swingPeak = 0, loadingPeak = 0, hipMin = 1e9, hipMax = -1e9, ankleMin = 1e9;
  for (int k = 0; k < 1000; ++k) {
    const double t = k / 1000.0;
    if (t > 0.5 && t < 0.9) swingPeak = std::max(swingPeak, knee(t));
    if (t < 0.3) loadingPeak = std::max(loadingPeak, knee(t));
    hipMin = std::min(hipMin, hip(t));
    hipMax = std::max(hipMax, hip(t));
    ankleMin = std::min(ankleMin, ankle(t));
  }
  EXPECT_NEAR(swingPeak, 60.0, 4.0);    // swing peak ~60°
  EXPECT_NEAR(loadingPeak, 19.0, 3.0);  // loading-response bump
  EXPECT_LT(knee(0.4), 9.0);            // extended in mid-stance
  EXPECT_NEAR(hipMax, 31.0, 3.0);       // +30° flexion
  EXPECT_NEAR(hipMin, -8.0, 3.0);       // −10° extension
  EXPECT_NEAR(ankleMin, -16.0, 3.0);    // push-off plantarflexion
  const PeriodicCurve shifted = shiftedCurve(knee, 0.25);
  EXPECT_NEAR(shifted(0.4), knee(0.15), 1e-9);
}

// [SECTION] Determinism

TEST(SynthDeterminism, SameSeedGivesTheSameCsvBytes) {
  const auto dir = test::makeTempDir("synth_det");
  const auto a = generatePopulation(smallPopulation(3, 11));
  const auto b = generatePopulation(smallPopulation(3, 11));
  const auto c = generatePopulation(smallPopulation(3, 12));
  ASSERT_EQ(a.size(), 3u);
  for (size_t i = 0; i < a.size(); ++i) {
    writeJointCsv(dir / "a.csv", a[i].trial.positionsMm, a[i].trial.rateHz);
    writeJointCsv(dir / "b.csv", b[i].trial.positionsMm, b[i].trial.rateHz);
    writeJointCsv(dir / "c.csv", c[i].trial.positionsMm, c[i].trial.rateHz);
    EXPECT_EQ(fileBytes(dir / "a.csv"), fileBytes(dir / "b.csv")) << a[i].id;
    EXPECT_NE(fileBytes(dir / "a.csv"), fileBytes(dir / "c.csv")) << a[i].id;
  }
  std::filesystem::remove_all(dir);
}

TEST(SynthDeterminism, WalkerIDependsOnlyOnSeedAndI) {
  const auto three = generatePopulation(smallPopulation(3));
  const auto five = generatePopulation(smallPopulation(5));
  for (size_t i = 0; i < three.size(); ++i) {
    EXPECT_EQ(three[i].id, five[i].id);
    EXPECT_TRUE(three[i].trial.positionsMm == five[i].trial.positionsMm) << three[i].id;
  }
  EXPECT_EQ(five[4].id, "SYN005");
}

TEST(SynthDeterminism, BadOptionsAreRejected) {
  PopulationOptions o = smallPopulation(0);
  EXPECT_THROW(generatePopulation(o), Error);
  o = smallPopulation(2);
  o.simulation.cycles = 0.5;
  EXPECT_THROW(generatePopulation(o), Error);
  o = smallPopulation(2);
  o.simulation.rateHz = -1;
  EXPECT_THROW(generatePopulation(o), Error);
}

// [SECTION] Anatomy and the floor

class SynthPopulation : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    walkers_ = new std::vector<SynthWalker>(generatePopulation(smallPopulation(20, 3)));
  }
  static void TearDownTestSuite() { delete walkers_; }
  static std::vector<SynthWalker>* walkers_;
};
std::vector<SynthWalker>* SynthPopulation::walkers_ = nullptr;

TEST_F(SynthPopulation, BoneLengthsAreConstantWithinAWalker) {
  for (const auto& w : *walkers_) {
    for (const auto& [a, b] : kBones) {
      const Eigen::VectorXd len = (w.trial.positionsMm.middleCols<3>(3 * index(a)) -
                                   w.trial.positionsMm.middleCols<3>(3 * index(b)))
                                      .rowwise()
                                      .norm();
      EXPECT_LT(len.maxCoeff() - len.minCoeff(), 1e-9)
          << w.id << " " << jointName(a) << "-" << jointName(b);
    }
  }
}

TEST_F(SynthPopulation, FeetReachTheFloorAndNothingGoesThrough) {
  for (const auto& w : *walkers_) {
    const JointTrial& t = w.trial;
    double lowest = 1e9;
    for (int j = 0; j < kJointCount; ++j)
      lowest = std::min(lowest, t.positionsMm.col(3 * j + 2).minCoeff());
    EXPECT_GT(lowest, 0.0) << w.id;
    EXPECT_GE(w.toesMm.col(2).minCoeff(), -1e-9) << w.id;
    EXPECT_GE(w.toesMm.col(5).minCoeff(), -1e-9) << w.id;
    // Foot flat in every stance: each ankle comes down to its height above the sole.
    const double ankleHeight = w.params.body.ankleHeightMm;
    for (Joint a : {Joint::RAnkle, Joint::LAnkle}) {
      const double lowestAnkle = column(t, a, 2).minCoeff();
      EXPECT_GE(lowestAnkle, ankleHeight - 0.5) << w.id;
      EXPECT_LE(lowestAnkle, ankleHeight + 3.0) << w.id;
    }
  }
}

TEST_F(SynthPopulation, AnkleReachesTheSameLowPointEveryCycle) {
  for (const auto& w : *walkers_) {
    const JointTrial& t = w.trial;
    const int perCycle =
        static_cast<int>(std::lround(t.rateHz / (w.attributes.at("cadence_spm") / 120.0)));
    const Eigen::VectorXd z = column(t, Joint::RAnkle, 2);
    std::vector<double> minima;
    for (int begin = 0; begin + perCycle <= z.size(); begin += perCycle) {
      minima.push_back(z.segment(begin, perCycle).minCoeff());
    }
    ASSERT_GE(minima.size(), 3u);
    const auto [lo, hi] = std::minmax_element(minima.begin(), minima.end());
    EXPECT_LT(*hi - *lo, 2.0) << w.id;
  }
}

TEST_F(SynthPopulation, StanceFootStaysPlanted) {
  // While an ankle is at its foot-flat height the foot must not slide along the floor.
  for (const auto& w : *walkers_) {
    const JointTrial& t = w.trial;
    for (Joint a : {Joint::RAnkle, Joint::LAnkle}) {
      const Eigen::VectorXd z = column(t, a, 2), y = column(t, a, 1);
      const double flat = z.minCoeff() + 3.0;
      double runMin = 0, runMax = 0, worst = 0;
      bool inRun = false;
      for (Eigen::Index f = 0; f < z.size(); ++f) {
        if (z[f] > flat) {
          inRun = false;
          continue;
        }
        if (!inRun) runMin = runMax = y[f];
        inRun = true;
        runMin = std::min(runMin, y[f]);
        runMax = std::max(runMax, y[f]);
        worst = std::max(worst, runMax - runMin);
      }
      EXPECT_LT(worst, 25.0) << w.id << " " << jointName(a);
    }
  }
}

// [SECTION] Gait features

// Amplitude of harmonic h of x over whole cycles at stride frequency f (Hz).
double harmonicAmplitude(const Eigen::VectorXd& x, double rateHz, double strideHz, int h) {
  const int n = static_cast<int>(std::floor(static_cast<double>(x.size()) * strideHz / rateHz) *
                                 rateHz / strideHz);
  double c = 0, s = 0;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * h * strideHz * i / rateHz;
    c += x[i] * std::cos(angle);
    s += x[i] * std::sin(angle);
  }
  return 2.0 * std::hypot(c, s) / n;
}

TEST_F(SynthPopulation, PelvisBobsTwicePerStrideAndSwaysOnce) {
  int twicePerStride = 0;
  for (const auto& w : *walkers_) {
    const JointTrial& t = w.trial;
    const double f = w.attributes.at("cadence_spm") / 120.0;
    const Eigen::VectorXd z = column(t, Joint::Pelvis, 2), x = column(t, Joint::Pelvis, 0);
    // A leg-length difference or an asymmetric gait adds a once-per-stride component.
    twicePerStride += harmonicAmplitude(z, t.rateHz, f, 2) > harmonicAmplitude(z, t.rateHz, f, 1);
    const double bob = z.maxCoeff() - z.minCoeff();
    EXPECT_GT(bob, 15.0) << w.id;
    EXPECT_LT(bob, 110.0) << w.id;
    EXPECT_GT(harmonicAmplitude(x, t.rateHz, f, 1), harmonicAmplitude(x, t.rateHz, f, 2)) << w.id;
  }
  EXPECT_GE(twicePerStride, static_cast<int>(0.85 * static_cast<double>(walkers_->size())));
}

TEST_F(SynthPopulation, KneeAngleHasLoadingBumpAndSwingPeak) {
  for (const auto& w : *walkers_) {
    const Eigen::MatrixXd& m = w.trial.positionsMm;
    double peak = 0.0, least = 180.0;
    for (int f = 0; f < m.rows(); ++f) {
      const Eigen::Vector3d thigh = jointAt(m, f, Joint::RKnee) - jointAt(m, f, Joint::RHip);
      const Eigen::Vector3d shank = jointAt(m, f, Joint::RAnkle) - jointAt(m, f, Joint::RKnee);
      const double flexion =
          std::acos(thigh.normalized().dot(shank.normalized())) * 180.0 / std::numbers::pi;
      peak = std::max(peak, flexion);
      least = std::min(least, flexion);
    }
    EXPECT_GT(peak, 45.0) << w.id;
    EXPECT_LT(peak, 80.0) << w.id;
    EXPECT_LT(least, 16.0) << w.id;  // flexion in mid-stance, with knee valgus added in 3D
    EXPECT_GT(w.attributes.at("knee_loading_deg"), 5.0) << w.id;
  }
}

TEST_F(SynthPopulation, PopulationVariesAndIsNotATwoHarmonicModel) {
  double minHeight = 1e9, maxHeight = 0, minCadence = 1e9, maxCadence = 0, females = 0;
  for (const auto& w : *walkers_) {
    minHeight = std::min(minHeight, w.attributes.at("height_m"));
    maxHeight = std::max(maxHeight, w.attributes.at("height_m"));
    minCadence = std::min(minCadence, w.attributes.at("cadence_spm"));
    maxCadence = std::max(maxCadence, w.attributes.at("cadence_spm"));
    females += w.attributes.at("female");
    // Forward kinematics and the normative curves' higher harmonics leave variance
    // outside two harmonics, as real walking does.
    const WalkingTrial walking = prepareWalkingTrial(w.trial);
    FourierFitOptions o;
    o.omegaFixedRadS = 2.0 * std::numbers::pi * w.attributes.at("cadence_spm") / 120.0;
    const FourierFit fit = fitFourier(walking.joints.positionsMm, walking.joints.rateHz, o);
    EXPECT_GT(fit.h1Share, 0.75) << w.id;
    EXPECT_GT(fit.residualShare, 0.002) << w.id;
  }
  EXPECT_GT(maxHeight - minHeight, 0.12);
  EXPECT_GT(maxCadence - minCadence, 10.0);
  EXPECT_GT(females, 2.0);
  EXPECT_LT(females, 18.0);
}

TEST(SynthTreadmill, WalksInPlace) {
  PopulationOptions o = smallPopulation(3);
  o.simulation.treadmill = true;
  for (const auto& w : generatePopulation(o)) {
    const Eigen::VectorXd y = column(w.trial, Joint::Pelvis, 1);
    EXPECT_LT(y.maxCoeff() - y.minCoeff(), 120.0) << w.id;
    EXPECT_NEAR(y.mean(), 0.0, 1e-6) << w.id;
  }
}

}  // namespace
}  // namespace ew
