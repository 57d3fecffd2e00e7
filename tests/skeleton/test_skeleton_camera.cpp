// The skeleton engine through a calibrated camera (core/skeleton/skeleton_camera.h): the lens
// distortion is taken out exactly, a rigid walker seen through a known camera with
// extrinsics comes back in the world frame, the scoring finds the reference's axes, and on
// the real balancing trial (four calibrated cameras, OpenPose 2D, triangulated 3D) each
// camera's reconstruction is scored.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <iostream>

#include "core/common/errors.h"
#include "core/io/trc_reader.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/mapping/joint_mapping.h"
#include "core/camera/lens_distortion.h"
#include "core/skeleton/skeleton_camera.h"
#include "tests/common/test_support.h"
#include "tests/skeleton/synthetic_camera.h"

namespace ew {
namespace {

// The calibration of the synthetic camera: intrinsics, distortion, world → camera.
CalibratedCamera calibrationOf(const Camera& c, const std::array<double, 4>& distortions) {
  CalibratedCamera k;
  k.name = "synthetic";
  k.fxPx = c.intrinsics.fxPx, k.fyPx = c.intrinsics.fyPx, k.cxPx = c.intrinsics.cxPx, k.cyPx = c.intrinsics.cyPx;
  k.distortions = distortions;
  const Eigen::AngleAxisd aa(c.worldToCamera);
  const Eigen::Vector3d r = aa.angle() * aa.axis(), t = -(c.worldToCamera * c.centre);
  k.rotation = {r.x(), r.y(), r.z()};
  k.translationMm = {t.x(), t.y(), t.z()};
  k.hasExtrinsics = true;
  return k;
}

// OpenCV's forward model: normalised coordinates to distorted pixels.
Eigen::RowVectorXd distort(const Eigen::RowVectorXd& uv, const CalibratedCamera& k) {
  const auto [k1, k2, p1, p2] = k.distortions;
  Eigen::RowVectorXd out = uv;
  for (Eigen::Index j = 0; j + 1 < uv.size(); j += 2) {
    const double x = (uv(j) - k.cxPx) / k.fxPx, y = (uv(j + 1) - k.cyPx) / k.fyPx, r2 = x * x + y * y;
    const double radial = 1.0 + k1 * r2 + k2 * r2 * r2;
    out(j) = k.fxPx * (x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x)) + k.cxPx;
    out(j + 1) = k.fyPx * (y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y) + k.cyPx;
  }
  return out;
}

struct SyntheticView {
  Eigen::MatrixXd pixels;  // T × 30, distorted
  CalibratedCamera calibration;
};

SyntheticView syntheticView(double azimuthDeg, const std::array<double, 4>& distortions) {
  const RigidWalk& w = rigidWalk();
  const Camera c = cameraAt(w.framesMm, azimuthDeg);
  SyntheticView v{Eigen::MatrixXd(w.framesMm.rows(), kDims2), calibrationOf(c, distortions)};
  for (Eigen::Index f = 0; f < w.framesMm.rows(); ++f) v.pixels.row(f) = distort(pixels(c, inCamera(c, w.framesMm, f)), v.calibration);
  return v;
}

constexpr std::array<double, 4> kLens = {-0.25, 0.08, 0.001, -0.0005};  // a wide lens's barrel distortion

TEST(SkeletonCamera, UndistortInvertsOpenCvsDistortion) {
  const SyntheticView v = syntheticView(35.0, kLens);
  const RigidWalk& w = rigidWalk();
  const Camera c = cameraAt(w.framesMm, 35.0);
  for (Eigen::Index f = 0; f < v.pixels.rows(); f += 7) {
    const Eigen::RowVectorXd ideal = pixels(c, inCamera(c, w.framesMm, f));
    EXPECT_GT((v.pixels.row(f) - ideal).cwiseAbs().maxCoeff(), 1.0);  // the distortion is visible
    Eigen::MatrixXd undistorted = v.pixels.row(f);
    EXPECT_EQ(undistortPixels(v.calibration, undistorted), 0);
    EXPECT_LT((undistorted.row(0) - ideal).cwiseAbs().maxCoeff(), 1e-6);
  }
}

TEST(SkeletonCamera, RigidWalkerComesBackInTheWorldFrame) {
  const RigidWalk& w = rigidWalk();
  for (double azimuth : {0.0, 35.0, 70.0}) {
    const SyntheticView v = syntheticView(azimuth, kLens);
    const SkeletonCameraResult r = reconstructThroughCamera(v.pixels, v.calibration, w.bones, 30.0, "synthetic");
    ASSERT_EQ(r.worldMm.rows(), w.framesMm.rows());
    const ReferenceComparison c = compareWithReference(r.worldMm, w.framesMm, "synthetic");
    EXPECT_TRUE(c.referenceToWorld.isIdentity()) << azimuth;
    // Noise-free, the error is the pelvis depth's: the tightest bone bound overestimates it
    // by 1/cos of the most parallel bone's tilt (a few per cent of 4.5 m), and every joint
    // placed from a root at the wrong depth is off in scale and in its roots. Measured
    // 54 / 59 / 80 mm without the mean translation, 45 / 50 / 63 mm after Procrustes at
    // 0° / 35° / 70°; with the true depth the placement is exact (test_skeleton_solve).
    EXPECT_LT(c.meanTranslationMm, 100.0) << azimuth;
    EXPECT_LT(c.procrustesMm, 80.0) << azimuth;
    EXPECT_LT(c.procrustesMm, c.rawMm) << azimuth;
    // The bound is on each bone's parent, a few hundred mm around the pelvis: within 10 %.
    const Camera cam = cameraAt(w.framesMm, azimuth);
    for (Eigen::Index f = 0; f < w.framesMm.rows(); ++f) {
      const double truth = inCamera(cam, w.framesMm, f).col(index(Joint::Pelvis)).norm();
      EXPECT_NEAR(r.rootDistanceMm[static_cast<size_t>(f)], truth, 0.1 * truth) << azimuth << " frame " << f;
    }
    std::cout << azimuth << "°: " << c.rawMm << " mm as is, " << c.meanTranslationMm << " without the mean translation, "
              << c.procrustesMm << " after Procrustes, " << r.sequence.clampedBoneFrames << " clamped\n";
  }
}

TEST(SkeletonCamera, ScoringFindsTheReferencesAxes) {
  const RigidWalk& w = rigidWalk();
  // Pose2Sim's TRC is Y-up: (x, y, z)_trc = (y, z, x)_world.
  Eigen::MatrixXd yUp(w.framesMm.rows(), 45);
  for (int j = 0; j < kJointCount; ++j) {
    yUp.col(3 * j) = w.framesMm.col(3 * j + 1);
    yUp.col(3 * j + 1) = w.framesMm.col(3 * j + 2);
    yUp.col(3 * j + 2) = w.framesMm.col(3 * j);
  }
  const Eigen::MatrixXd shifted = w.framesMm.array() + 250.0;
  const ReferenceComparison c = compareWithReference(shifted, yUp, "yup");
  Eigen::Matrix3d expected;
  expected << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  EXPECT_TRUE(c.referenceToWorld.isApprox(expected));
  EXPECT_NEAR(c.meanTranslationMm, 0.0, 1e-9);
  EXPECT_NEAR(c.procrustesMm, 0.0, 1e-6);
  EXPECT_NEAR(c.rawMm, 250.0 * std::sqrt(3.0), 1e-9);
}

TEST(SkeletonCamera, AJointNeverSeenIsNamed) {
  SyntheticView v = syntheticView(35.0, {});
  v.pixels.col(2 * index(Joint::LWrist)).setConstant(std::nan(""));
  v.pixels.col(2 * index(Joint::LWrist) + 1).setConstant(std::nan(""));
  try {
    reconstructThroughCamera(v.pixels, v.calibration, rigidWalk().bones, 30.0, "clip.json");
    ADD_FAILURE() << "reconstructed";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("clip.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("seen in no frame"), std::string::npos) << e.what();
  }
  // A gap is interpolated and counted.
  v = syntheticView(35.0, {});
  v.pixels.block(10, 0, 3, 2).setConstant(std::nan(""));
  EXPECT_EQ(reconstructThroughCamera(v.pixels, v.calibration, rigidWalk().bones, 30.0, "clip.json").filledPoints, 3);
}

// The real balancing trial (not walking): each camera's OpenPose 2D with its calibration
// against the 3D triangulated from all four. Measured (reconstruct --engine skeleton,
// docs/RESULTS.md): 111–178 mm after Procrustes; the bound leaves room for the detector's
// run-to-run differences, and fails if the extrinsics or the axes were read wrongly (then
// every frame is metres off).
TEST(SkeletonCamera, BalancingTrialPerCamera) {
  EW_REQUIRE_SHARED_DATA();
  const auto dir = test::sharedDataDir() / "pose2sim-balancing";
  const JointTrial truth = mapMarkerSet(readTrc(dir / "pose-3d/S00_P00_T01_BalancingTrial_0-100.trc"));
  const BoneLengths bones = boneLengthsFromFrames(truth.positionsMm, "trc");
  Eigen::Matrix3d pose2simAxes;
  pose2simAxes << 0, 0, 1, 1, 0, 0, 0, 1, 0;
  for (int cam = 1; cam <= 4; ++cam) {
    const std::string name = "cam0" + std::to_string(cam);
    KeypointOptions ko;
    ko.fps = 60.0;
    const KeypointTrial kt = readKeypointTrial(dir / "pose" / (name + "_json"), ko);
    const CalibratedCamera cc = readCalibratedCamera(dir / "Calib_qualisys.toml", "cam_0" + std::to_string(cam));
    ASSERT_TRUE(cc.hasExtrinsics);
    const SkeletonCameraResult r = reconstructThroughCamera(kt.jointsPx, cc, bones, 60.0, name);
    const ReferenceComparison c = compareWithReference(r.worldMm, truth.positionsMm, name);
    EXPECT_EQ(c.frames, 100) << name;
    EXPECT_TRUE(c.referenceToWorld.isApprox(pose2simAxes)) << name;
    EXPECT_LT(c.procrustesMm, 220.0) << name;
    EXPECT_LT(c.meanTranslationMm, 350.0) << name;
  }
}

}  // namespace
}  // namespace ew
