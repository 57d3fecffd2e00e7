// Gait measures from a reconstruction against the motion capture (core/experiments/
// gait_agreement.h): Bland-Altman arithmetic on hand-made rows, a perfect reconstruction
// agreeing with itself, and one that cannot be measured giving NaN instead of an exception.
#include <gtest/gtest.h>

#include <cmath>

#include "core/experiments/gait_agreement.h"
#include "core/gait/prepare.h"
#include "core/synth/population.h"

namespace ew {
namespace {

TEST(BlandAltman, BiasAndLimitsOfAgreementAreComputedPerEngineViewAndMeasure) {
  std::vector<GaitAgreementRow> rows;
  const double diffs[] = {1.0, 2.0, 3.0};
  for (int k = 0; k < 3; ++k) rows.push_back({"S" + std::to_string(k), "A", 30.0, "cadence", 100.0, 100.0 + diffs[k]});
  rows.push_back({"S3", "A", 30.0, "cadence", 100.0, NAN});    // the reconstruction could not be measured
  rows.push_back({"S0", "A", 60.0, "cadence", 100.0, 90.0});   // another view: its own group
  const auto ba = blandAltman(rows);
  ASSERT_EQ(ba.size(), 2u);
  EXPECT_EQ(ba[0].engine, "A");
  EXPECT_EQ(ba[0].angleDeg, 30.0);
  EXPECT_EQ(ba[0].unit, "steps/min");
  EXPECT_EQ(ba[0].pairs, 3);
  EXPECT_EQ(ba[0].unmeasured, 1);
  EXPECT_DOUBLE_EQ(ba[0].bias, 2.0);
  EXPECT_DOUBLE_EQ(ba[0].sd, 1.0);
  EXPECT_DOUBLE_EQ(ba[0].loaLow, 2.0 - 1.96);
  EXPECT_DOUBLE_EQ(ba[0].loaHigh, 2.0 + 1.96);
  EXPECT_DOUBLE_EQ(ba[0].meanAbsDifference, 2.0);
  EXPECT_DOUBLE_EQ(ba[1].bias, -10.0);
  EXPECT_DOUBLE_EQ(ba[1].sd, 0.0);
}

// Experiment "engines": each setting and noise level is its own group; a camera group pools
// the cameras of one azimuth band (its angle is NaN, its band named).
TEST(BlandAltman, SettingsAndNoiseLevelsAreGroupsAndCamerasPoolTheirAzimuths) {
  std::vector<GaitAgreementRow> rows;
  const auto add = [&](const char* setting, double angle, double noise, double diff) {
    GaitAgreementRow r{"S", "A", angle, "speed", 1.0, 1.0 + diff};
    r.setting = setting;
    r.noise = noise;
    rows.push_back(r);
  };
  add("view", 30.0, 0.0, 0.1);
  add("view", 30.0, 10.0, 0.2);
  add("camera", 47.0, 0.0, 0.3);
  add("camera", -120.0, 0.0, 0.5);
  add("camera", 40.0, 2.0, 0.7);
  add("camera", -170.0, 0.0, 0.9);  // from behind: a band of its own
  add("camera", 29.0, 0.0, 1.1);    // from the front
  const auto ba = blandAltman(rows);
  ASSERT_EQ(ba.size(), 6u);
  EXPECT_EQ(ba[1].noise, 10.0);
  EXPECT_EQ(ba[2].setting, "camera");
  EXPECT_EQ(ba[2].band, "side");
  EXPECT_TRUE(std::isnan(ba[2].angleDeg));
  EXPECT_EQ(ba[2].pairs, 2);
  EXPECT_DOUBLE_EQ(ba[2].bias, 0.4);
  EXPECT_DOUBLE_EQ(ba[2].medianAbsDifference, 0.4);
  EXPECT_EQ(ba[4].band, "back");
  EXPECT_EQ(ba[5].band, "front");
  EXPECT_EQ(ba[3].noise, 2.0);
}

WalkingTrial syntheticTrial() {
  PopulationOptions o;
  o.count = 1;
  o.simulation.rateHz = 30.0;
  return prepareWalkingTrial(generatePopulation(o).front().trial);
}

TEST(GaitAgreement, AReconstructionEqualToTheTruthAgreesWithIt) {
  const WalkingTrial t = syntheticTrial();
  const auto& m = t.joints.positionsMm;
  const auto rows = gaitAgreementRows("SYN001", "perfect", 0.0, m, m, t.joints.rateHz);
  ASSERT_EQ(rows.size(), agreementMeasures().size());
  for (const auto& r : rows) {
    ASSERT_TRUE(std::isfinite(r.mocap)) << r.measure;
    ASSERT_TRUE(std::isfinite(r.reconstructed)) << r.measure;
    EXPECT_NEAR(r.reconstructed, r.mocap, 1e-9) << r.measure;
  }
}

TEST(GaitAgreement, AReconstructionThatDoesNotWalkIsUnmeasuredNotAnError) {
  const WalkingTrial t = syntheticTrial();
  const auto& m = t.joints.positionsMm;
  Eigen::MatrixXd still = m.row(0).replicate(m.rows(), 1);  // one pose held: no strides
  const auto rows = gaitAgreementRows("SYN001", "still", 0.0, m, still, t.joints.rateHz);
  for (const auto& r : rows) {
    EXPECT_TRUE(std::isfinite(r.mocap)) << r.measure;
    EXPECT_TRUE(std::isnan(r.reconstructed)) << r.measure;
  }
  EXPECT_EQ(blandAltman(rows).front().unmeasured, 1);
}

// A side's known walk over the floor is its speed, and puts its footprints down with it.
TEST(GaitAgreement, AKnownProgressionIsTheSidesSpeed) {
  const WalkingTrial t = syntheticTrial();
  const auto& m = t.joints.positionsMm;
  const auto rows = gaitAgreementRows("SYN001", "walked", 0.0, m, m, t.joints.rateHz, {1.234, false, std::nullopt}, {0.9, false, std::nullopt});
  for (const auto& r : rows) {
    if (r.measure == "speed") {
      EXPECT_DOUBLE_EQ(r.mocap, 1.234);
      EXPECT_DOUBLE_EQ(r.reconstructed, 0.9);
    }
    if (r.measure == "cadence") {
      EXPECT_NEAR(r.reconstructed, r.mocap, 1e-9);
    }
    if (r.measure == "stride_length") {
      EXPECT_LT(r.reconstructed, r.mocap - 0.2);
    }
    if (r.measure == "knee_flexion_curve") {
      EXPECT_NEAR(r.reconstructed, 0.0, 1e-9);
    }
  }
}

}  // namespace
}  // namespace ew
