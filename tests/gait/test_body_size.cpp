// A walker of no human size (a wrong length unit) is warned about, naming the file, the
// size measured and the unit that would make it a person; a person's size is not.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <numeric>
#include <limits>

#include "core/gait/body_size.h"
#include "core/gait/dataset.h"
#include "core/io/bvh_writer.h"
#include "core/io/c3d_reader.h"
#include "core/io/load_trial.h"
#include "tests/common/synthetic_gait.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

JointTrial analyticTrial(double scale, const std::string& units) {
  JointTrial t = test::analyticWalkTrial({});
  t.positionsMm *= scale;
  t.units = units;
  t.file = "walk.bvh";
  return t;
}

bool hasWarningWith(const std::vector<std::string>& warnings, const std::string& text) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const std::string& w) { return w.find(text) != std::string::npos; });
}

TEST(BodySize, APersonsSizeIsMeasuredAndNotWarnedAbout) {
  const JointTrial t = analyticTrial(1.0, "mm");
  const auto size = measureBodySize(t.positionsMm);
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->what, "head to ankles");
  EXPECT_GT(size->lengthMm, size->minMm);
  EXPECT_LT(size->lengthMm, size->maxMm);
  EXPECT_FALSE(bodySizeWarning(t).has_value());
}

TEST(BodySize, AWalkerInTheWrongUnitNamesTheFileTheSizeAndTheLikelyUnit) {
  // Millimetre numbers read as centimetres: ten times too tall.
  const auto w = bodySizeWarning(analyticTrial(10.0, "cm"));
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(w->rfind("walk.bvh: the walker measures ", 0), 0u) << *w;
  EXPECT_NE(w->find(" m from head to ankles"), std::string::npos) << *w;
  EXPECT_NE(w->find("the file's unit is probably mm, not cm; use --units mm"), std::string::npos)
      << *w;
  // Centimetre numbers read as metres: a hundred times too tall.
  const auto m = bodySizeWarning(analyticTrial(0.1 * 1000.0, "m"));
  ASSERT_TRUE(m.has_value());
  EXPECT_NE(m->find("probably cm, not m; use --units cm"), std::string::npos) << *m;
  // Metre numbers read as millimetres: a thousand times too small.
  const auto mm = bodySizeWarning(analyticTrial(0.001, "mm"));
  ASSERT_TRUE(mm.has_value());
  EXPECT_NE(mm->find("probably m, not mm; use --units m"), std::string::npos) << *mm;
}

TEST(BodySize, WithoutAHeadTheLegsAreMeasured) {
  JointTrial t = analyticTrial(1.0, "mm");
  t.positionsMm.middleCols<3>(3 * index(Joint::Head))
      .setConstant(std::numeric_limits<double>::quiet_NaN());
  const auto size = measureBodySize(t.positionsMm);
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->what, "hips to ankles");
  EXPECT_FALSE(bodySizeWarning(t).has_value());
  t.positionsMm *= 25.4;  // inch numbers read as mm
  t.units = "in";
  EXPECT_TRUE(bodySizeWarning(t).has_value());
}

TEST(BodySize, NothingToMeasureIsNoWarning) {
  JointTrial t = analyticTrial(1.0, "mm");
  t.positionsMm.setConstant(std::numeric_limits<double>::quiet_NaN());
  EXPECT_FALSE(measureBodySize(t.positionsMm).has_value());
  EXPECT_FALSE(bodySizeWarning(t).has_value());
}

// The case: a BVH loaded with the wrong --units (here cm for a file in mm) loads,
// walks, and now says so.
TEST(BodySize, ABvhLoadedWithTheWrongUnitWarns) {
  const auto dir = test::makeTempDir("body_size");
  const auto file = dir / "walk.bvh";
  writeBvh(file, test::analyticWalkFrames({}), 100.0);
  const WalkingTrial right = loadWalkingTrial(file);
  EXPECT_FALSE(hasWarningWith(right.joints.warnings, "the walker measures"));
  LoadOptions wrong;
  wrong.unitsOverride = "cm";
  const WalkingTrial trial = loadWalkingTrial(file, wrong);
  EXPECT_TRUE(hasWarningWith(trial.joints.warnings, file.string() + ": the walker measures"));
  EXPECT_TRUE(hasWarningWith(trial.joints.warnings, "probably mm, not cm; use --units mm"));
  // Said when the file is mapped to joints, before any walking check can fail (info lists
  // the joints' warnings beside a walking error).
  const JointTrial joints = mapRawTrial(readRawTrial(file, wrong), wrong);
  EXPECT_TRUE(hasWarningWith(joints.warnings, "use --units mm"));
  size_t count = 0;
  for (const auto& w : trial.joints.warnings)
    count += w.find("the walker measures") != std::string::npos;
  EXPECT_EQ(count, 1u);  // once, not again by a later stage
  std::filesystem::remove_all(dir);
}

// The head joint's height above the ankles, walking, as a share of the stature: measured on
// the 18 Schreiber-Moissenet walkers, whose C3D files record each subject's height
// (SUBJECT:VALUES). The constant is their mean; each walker's stature predicted from the
// other 17's mean share is within 7 % (the worst, 2014007, walks with the head low: −6.4 %),
// and 17 of the 18 within 2.5 %.
TEST(StatureFromTheHead, TheShareHoldsForEachSharedWalkerLeftOut) {
  EW_REQUIRE_SHARED_DATA();
  std::vector<std::string> warnings;
  std::vector<double> shares, headsMm, staturesMm;
  for (const auto& f : collectTrialFiles({test::sharedDataDir() / "walkers.csv"}, warnings)) {
    if (f.path.extension() != ".c3d") continue;
    const RawTrial raw = readC3d(f.path);
    ASSERT_TRUE(raw.subjectStatureMm.has_value()) << f.path;
    const Eigen::MatrixXd& m = loadWalkingTrial(f.path).joints.positionsMm;
    const Eigen::VectorXd ankles =
        0.5 * (m.col(3 * index(Joint::LAnkle) + 2) + m.col(3 * index(Joint::RAnkle) + 2));
    headsMm.push_back((m.col(3 * index(Joint::Head) + 2) - ankles).mean());
    staturesMm.push_back(*raw.subjectStatureMm);
    shares.push_back(headsMm.back() / staturesMm.back());
  }
  ASSERT_EQ(shares.size(), 18u);
  const double sum = std::accumulate(shares.begin(), shares.end(), 0.0);
  EXPECT_NEAR(sum / 18.0, kHeadAboveAnklesOfStature, 0.0005);
  int close = 0;
  for (std::size_t i = 0; i < shares.size(); ++i) {
    const double othersShare = (sum - shares[i]) / 17.0;
    const double error = headsMm[i] / othersShare / staturesMm[i] - 1.0;
    std::cout << "walker " << i << ": stature " << staturesMm[i] << " mm, predicted " << headsMm[i] / othersShare
              << " (" << 100.0 * error << " %)\n";
    EXPECT_LE(std::abs(error), 0.07) << i;
    close += std::abs(error) <= 0.025;
  }
  EXPECT_GE(close, 17);
  EXPECT_NEAR(statureFromHeadAboveAnklesMm(1500.0), 1500.0 / kHeadAboveAnklesOfStature, 1e-9);
}

}  // namespace
}  // namespace ew
