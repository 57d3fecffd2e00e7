// A detector's hips are not hip-joint centres (core/camera/detector_offsets.h): the fit
// through the unknown camera allows for the layout's offsets and reports joint centres; the
// offset the shipped tables state is the one learnt from the Pose2Sim trial's triangulated
// BODY_25B keypoints against the default model (docs/KEYPOINTS.md, "Detector hips").

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "core/camera/camera_reconstruction.h"
#include "core/camera/detector_offsets.h"
#include "core/common/errors.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/io/trc_reader.h"
#include "core/keypoints/keypoint_layout.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/camera/filmed_walk.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

JointOffsetsMm hipsApart(double lateralMm, double upMm) {
  JointOffsetsMm o{};
  o[static_cast<std::size_t>(index(Joint::RHip))] = {lateralMm, 0.0, upMm};
  o[static_cast<std::size_t>(index(Joint::LHip))] = {-lateralMm, 0.0, upMm};
  o[static_cast<std::size_t>(index(Joint::Pelvis))] = {0.0, 0.0, upMm};
  return o;
}

struct Filmed {
  VectorXd times;
  MatrixXd centres;  // the walker's joint centres, T × 45
  KeypointTrial trial;
};

// The mean walker filmed by the crossing pinhole with a detector that puts each joint at its
// centre plus `offsets`, read as a trial that knows those offsets.
Filmed filmedByDetector(const JointOffsetsMm& offsets) {
  Filmed f;
  f.times = frameTimes(150, 30.0);
  f.centres = synthesizeFrames(defaultRealModel().mean, 2 * std::numbers::pi * test::kFilmedStrideHz, 0.2, f.times);
  MatrixXd detected = f.centres;
  addOffsets(detected, offsets);
  const MatrixXd px = projectWalk(detected, f.times, test::crossingPinhole(1500, 5.0));
  KeypointOptions k;
  k.fps = 30.0;
  f.trial = trialFromJoints(px, MatrixXd::Ones(px.rows(), kJointCount), "detector", "test", k);
  f.trial.detectorOffsetMm = offsets;
  return f;
}

CameraFitOptions knownFocal() {
  CameraFitOptions o;
  o.estimator = {Estimator::Lsq, 0.0};
  o.strideHzHint = test::kFilmedStrideHz;
  o.focalPx = 1500;
  return o;
}

double maxErrorMm(const CameraFit& fit, const Filmed& f) {
  return (synthesizeFrames(fit.w, fit.omegaRadS, fit.phaseRad, f.times) - f.centres).cwiseAbs().maxCoeff();
}

// Hips 40 mm out and 20 mm up, as Needham et al. 2021 measured orders of: allowed for, the
// joint centres come back exactly; taken for centres, the hips are off by the offset.
TEST(DetectorOffsets, TheFitReportsJointCentres) {
  const Filmed f = filmedByDetector(hipsApart(40.0, 20.0));
  const CameraFit fit = reconstructDetectedWalker(defaultRealModel(), f.trial, knownFocal());
  EXPECT_LT(maxErrorMm(fit, f), 1e-3);
  EXPECT_NEAR(fit.camera.alphaDeg, 40, 1e-3 * 40);
  EXPECT_LT(fit.reprojectionRmsPx, 1e-4);

  Filmed ignored = f;
  ignored.trial.detectorOffsetMm = {};
  const CameraFit naive = reconstructDetectedWalker(defaultRealModel(), ignored.trial, knownFocal());
  EXPECT_GT(maxErrorMm(naive, f), 15.0);
}

// A layout's sternum is the shoulders' midpoint, 41 mm behind and 66 mm below the model's on
// its mean walker: allowed for, the mean walker filmed that way comes back within the offset's
// own swing over the cycle (the shoulders move about the trunk); taken for the sternum, the fit
// bends the trunk to reach it.
TEST(DetectorOffsets, TheSternumMadeFromTheShouldersIsAllowedFor) {
  const Eigen::Vector3d offset = sternumAsShouldersMidpointOffsetMm(defaultRealModel());
  EXPECT_NEAR(offset.y(), -40.6, 0.5);
  EXPECT_NEAR(offset.z(), -66.5, 0.5);
  Filmed f;
  f.times = frameTimes(150, 30.0);
  f.centres = synthesizeFrames(defaultRealModel().mean, 2 * std::numbers::pi * test::kFilmedStrideHz, 0.2, f.times);
  MatrixXd detected = f.centres;
  const auto col = [](Joint j) { return 3 * index(j); };
  detected.middleCols<3>(col(Joint::Sternum)) =
      0.5 * (f.centres.middleCols<3>(col(Joint::RShoulder)) + f.centres.middleCols<3>(col(Joint::LShoulder)));
  const MatrixXd px = projectWalk(detected, f.times, test::crossingPinhole(1500, 5.0));
  KeypointOptions k;
  k.fps = 30.0;
  f.trial = trialFromJoints(px, MatrixXd::Ones(px.rows(), kJointCount), "detector", "test", k);
  f.trial.sternumFromShoulders = true;
  const CameraFit fit = reconstructDetectedWalker(defaultRealModel(), f.trial, knownFocal());
  f.trial.sternumFromShoulders = false;
  const CameraFit naive = reconstructDetectedWalker(defaultRealModel(), f.trial, knownFocal());
  const auto headError = [&](const CameraFit& c) { return std::abs(c.headHeightMm / walkerHeadHeightMm(defaultRealModel().mean) - 1.0); };
  std::cout << "allowed for: max error " << maxErrorMm(fit, f) << " mm, head height " << 100 * headError(fit)
            << " %; taken for the sternum: " << maxErrorMm(naive, f) << " mm, " << 100 * headError(naive) << " %\n";
  // Measured: 0.40 mm and 0.007 % allowed for; 21.3 mm and 1.54 % (the stride's bias in the
  // camera experiment, docs/RESULTS.md) taken for the sternum.
  EXPECT_LT(maxErrorMm(fit, f), 2.0);
  EXPECT_LT(headError(fit), 0.001);
  EXPECT_GT(headError(naive), 0.01);
}

// The readers say which layouts make the sternum from the shoulders; none with the offsets off.
TEST(DetectorOffsets, ReadersMarkASternumMadeFromTheShoulders) {
  const std::filesystem::path dir = test::makeTempDir("sternum_layouts");
  test::writeFilmedOpenPose(dir / "body25", test::crossingPinhole(1500, 3.0), 90, 30.0);
  KeypointOptions k;
  k.fps = 30.0;
  EXPECT_TRUE(readKeypointTrial(dir / "body25", k).sternumFromShoulders);
  k.detectorOffsets = false;
  EXPECT_FALSE(readKeypointTrial(dir / "body25", k).sternumFromShoulders);
}

TEST(DetectorOffsets, ModelAndWalkerMoveByTheOffsets) {
  const JointOffsetsMm o = hipsApart(12.0, -5.0);
  const EigenwalkerModel& m = defaultRealModel();
  const EigenwalkerModel moved = modelAsDetected(m, o);
  EXPECT_DOUBLE_EQ(moved.mean[3 * index(Joint::RHip)] - m.mean[3 * index(Joint::RHip)], 12.0);
  EXPECT_DOUBLE_EQ(moved.mean[3 * index(Joint::LHip) + 2] - m.mean[3 * index(Joint::LHip) + 2], -5.0);
  EXPECT_EQ(moved.mean.tail(m.mean.size() - 45), m.mean.tail(m.mean.size() - 45));  // harmonics untouched
  VectorXd w = moved.mean;
  removeOffsets(w, o);
  EXPECT_LT((w - m.mean).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_THROW(lateralHipOffsetMm(m, 0.0, 400.0), Error);
  EXPECT_THROW(lateralHipOffsetMm(m, 200.0, std::nan("")), Error);
}

// Every detector table states the same hips: out by what the Pose2Sim trial shows, no
// vertical offset; the tracker's own joints and a --no-detector-offsets read have none.
TEST(DetectorOffsets, DetectorTablesCarryTheHipOffset) {
  for (const char* name : {"BODY_25", "BODY_25B", "COCO-18", "COCO-17", "Halpe-26", "MediaPipe-33"}) {
    const KeypointLayout& l = keypointLayoutNamed(name);
    EXPECT_TRUE(anyOffset(l.detectorOffsetMm)) << name;
    const auto& r = l.detectorOffsetMm[static_cast<std::size_t>(index(Joint::RHip))];
    const auto& left = l.detectorOffsetMm[static_cast<std::size_t>(index(Joint::LHip))];
    EXPECT_GT(r[0], 0.0) << name;
    EXPECT_EQ(left[0], -r[0]) << name;
    EXPECT_FALSE(l.detectorOffsetSource.empty()) << name;
  }
  const Filmed f = filmedByDetector({});
  EXPECT_FALSE(anyOffset(f.trial.detectorOffsetMm));
}

TEST(DetectorOffsets, MalformedOffsetsNameTheKey) {
  const std::string base = R"({"name": "T", "points": ["a", "b"], "joints": {"pelvis": [["a"]]}, )";
  for (const char* offsets : {R"("detector_offsets_mm": [1, 2])", R"("detector_offsets_mm": {"r_hip": [1, 2]})",
                              R"("detector_offsets_mm": {"r_hip": [1, 2, 900]})",
                              R"("detector_offsets_mm": {"nose": [1, 2, 3]})"}) {
    try {
      parseKeypointLayout(base + offsets + "}", "t.json");
      ADD_FAILURE() << offsets;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("detector_offsets_mm"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("t.json"), std::string::npos) << e.what();
    }
  }
}

// The number in the tables, learnt again: the Pose2Sim balancing trial's keypoints
// triangulated from its four cameras (BODY_25B, OpenPose) give the detector's hip width and
// shank; the default model's walkers give the hip width such a shank goes with.
TEST(DetectorOffsets, TheTablesOffsetIsLearntFromPose2SimAgainstTheModel) {
  EW_REQUIRE_SHARED_DATA();
  const RawTrial t = readTrc(test::sharedDataDir() / "pose2sim-balancing/pose-3d/S00_P00_T01_BalancingTrial_0-100.trc");
  const auto column = [&](const std::string& label) {
    for (int i = 0; i < t.pointCount(); ++i)
      if (t.labels[static_cast<std::size_t>(i)] == label) return 3 * i;
    ADD_FAILURE() << "no " << label;
    return 0;
  };
  const auto distance = [&](Eigen::Index f, const std::string& a, const std::string& b) {
    return (t.positionsMm.row(f).segment<3>(column(a)) - t.positionsMm.row(f).segment<3>(column(b))).norm();
  };
  double width = 0.0, shank = 0.0;
  for (Eigen::Index f = 0; f < t.frameCount(); ++f) {
    width += distance(f, "RHip", "LHip");
    shank += 0.5 * (distance(f, "RKnee", "RAnkle") + distance(f, "LKnee", "LAnkle"));
  }
  width /= t.frameCount();
  shank /= t.frameCount();
  const double learnt = lateralHipOffsetMm(defaultRealModel(), width, shank);
  std::printf("Pose2Sim BODY_25B: hip width %.1f mm, shank %.1f mm; lateral hip offset learnt %.2f mm\n", width, shank,
              learnt);
  const auto& r = keypointLayoutNamed("BODY_25B").detectorOffsetMm[static_cast<std::size_t>(index(Joint::RHip))];
  EXPECT_NEAR(r[0], learnt, 0.05);
}

}  // namespace
}  // namespace ew
