// One reconstruction request (core/engines/request.h): which knowledge each engine accepts is
// a table the request is checked against, with an error naming the engine; an orthographic
// request is the engine's own path; through a camera the eigenwalker is the camera fit and
// the skeleton engine the rays through the pinhole.
#include <gtest/gtest.h>

#include <numbers>

#include "core/camera/clip_reconstruction.h"
#include "core/common/errors.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"
#include "core/engines/request.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/skeleton/bone_sources.h"
#include "tests/camera/filmed_walk.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

using Kind = CameraKnowledgeKind;

// The default model's mean walker, 2 s at 30 Hz, seen orthographically at 40°.
ViewInput meanWalkerView(std::optional<double> alphaDeg) {
  const Eigen::VectorXd t = frameTimes(60, 30.0);
  ViewInput in;
  in.uvMm = projectFramesToView(synthesizeFrames(defaultRealModel().mean, 2 * std::numbers::pi * 0.95, 0.2, t), 40.0);
  in.rateHz = 30.0;
  in.alphaDeg = alphaDeg;
  in.inPlace = true;
  in.name = "mean.csv";
  return in;
}

// The filmed walk (tests/camera/filmed_walk.h) read back as a pose estimator's keypoints.
KeypointTrial filmedKeypoints() {
  const auto folder = test::makeTempDir("request") / "filmed";
  test::writeFilmedOpenPose(folder, test::crossingPinhole(1400, 3.0), 90, 30.0);
  KeypointOptions k;
  k.fps = 30.0;
  return readKeypointTrial(folder, k);
}

TEST(ReconstructionRequest, TheTableSaysWhatEachEngineTakes) {
  for (Kind k : {Kind::OrthographicKnownView, Kind::OrthographicUnknownView}) {
    EXPECT_TRUE(engineAccepts(EngineKind::Eigenwalker, k));
    EXPECT_TRUE(engineAccepts(EngineKind::Snippet, k));
    EXPECT_TRUE(engineAccepts(EngineKind::Skeleton, k));
  }
  for (Kind k : {Kind::CameraUnknownFocal, Kind::CameraKnownFocal, Kind::CameraCalibration, Kind::CameraLensDistortion,
                 Kind::CameraScaledOrthography}) {
    EXPECT_TRUE(engineAccepts(EngineKind::Eigenwalker, k)) << describe(k);
    EXPECT_FALSE(engineAccepts(EngineKind::Snippet, k)) << describe(k);
  }
  EXPECT_TRUE(engineAccepts(EngineKind::Skeleton, Kind::CameraKnownFocal));
  EXPECT_TRUE(engineAccepts(EngineKind::Skeleton, Kind::CameraCalibration));
  EXPECT_FALSE(engineAccepts(EngineKind::Skeleton, Kind::CameraUnknownFocal));
  EXPECT_FALSE(engineAccepts(EngineKind::Skeleton, Kind::CameraScaledOrthography));
}

TEST(ReconstructionRequest, KnowledgeIsReadOffTheRequest) {
  EXPECT_EQ(knowledgeOf({meanWalkerView(30.0)}), std::vector<Kind>{Kind::OrthographicKnownView});
  EXPECT_EQ(knowledgeOf({meanWalkerView(std::nullopt)}), std::vector<Kind>{Kind::OrthographicUnknownView});
  CameraView v;
  EXPECT_EQ(knowledgeOf({v}), std::vector<Kind>{Kind::CameraUnknownFocal});
  v.camera.estimateFocal = false;
  EXPECT_EQ(knowledgeOf({v}), std::vector<Kind>{Kind::CameraScaledOrthography});
  v.camera.focalPx = 1400.0;
  EXPECT_EQ(knowledgeOf({v}), std::vector<Kind>{Kind::CameraKnownFocal});
}

TEST(ReconstructionRequest, AnEngineRefusesWhatItDoesNotTakeNamingBoth) {
  CameraView v;
  v.name = "clip.json";
  try {
    checkEngineAccepts(EngineKind::Snippet, {v}, "--engine");
    FAIL() << "the snippet engine took pixels through a camera";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadArgument);
    const std::string what = e.what();
    EXPECT_NE(what.find("--engine"), std::string::npos) << what;
    EXPECT_NE(what.find("snippet"), std::string::npos) << what;
    EXPECT_NE(what.find("unknown focal length"), std::string::npos) << what;
  }
  EXPECT_THROW(reconstruct(SkeletonEngine{}, {v}), Error);
  EXPECT_NO_THROW(checkEngineAccepts(EngineKind::Eigenwalker, {v}, "--engine"));
}

// The request adds no step of its own: an orthographic view is the engine's interface's answer.
TEST(ReconstructionRequest, AnOrthographicViewIsTheEnginesOwnAnswer) {
  const EigenwalkerEngine engine{defaultRealModel(), {Estimator::Map, 70.0}, {}};
  for (std::optional<double> alpha : {std::optional<double>(40.0), std::optional<double>()}) {
    const ViewInput view = meanWalkerView(alpha);
    const ReconstructionResult r = reconstruct(engine, {view});
    const EngineResult direct = reconstructWithEngine(engine, view);
    EXPECT_EQ(r.engine.alphaDeg, direct.alphaDeg);
    EXPECT_EQ((r.engine.framesMm - direct.framesMm).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_FALSE(r.camera.eigenwalker);
  }
}

TEST(ReconstructionRequest, ThroughACameraTheEigenwalkerIsTheCameraFit) {
  CameraView v;
  v.keypoints = filmedKeypoints();
  v.camera.focalPx = 1400.0;
  const EigenwalkerEngine engine{defaultRealModel(), {Estimator::Map, 1000.0}, {}};
  const ReconstructionResult r = reconstruct(engine, {v});
  ASSERT_TRUE(r.camera.eigenwalker);
  const ClipReconstruction direct =
      reconstructKeypointTrial(defaultRealModel(), v.keypoints, cameraFitOptions(v.camera, engine.estimator, v.keypoints.file));
  EXPECT_EQ(r.camera.eigenwalker->last.fit.camera.alphaDeg, direct.fit.camera.alphaDeg);
  EXPECT_EQ((r.engine.framesMm - direct.framesMm).cwiseAbs().maxCoeff(), 0.0);
  // The filmed camera: azimuth 40° (the fit's error on this clip is a few degrees at most).
  EXPECT_NEAR(r.engine.alphaDeg, 40.0, 5.0);
}

TEST(ReconstructionRequest, ThroughACameraTheSkeletonSeesTheKnownPinhole) {
  CameraView v;
  v.keypoints = filmedKeypoints();
  v.camera.focalPx = 1400.0;
  v.camera.imageSize = KeypointImageSize{1920, 1080};
  const CalibratedCamera pinhole = skeletonPinhole(v);
  EXPECT_EQ(pinhole.fxPx, 1400.0);
  EXPECT_EQ(pinhole.cxPx, 960.0);
  EXPECT_FALSE(pinhole.hasExtrinsics);
  const SkeletonEngine engine{boneLengthsFromZouTable2(1700.0, "stature"), {}};
  const ReconstructionResult r = reconstruct(engine, {v});
  ASSERT_TRUE(r.camera.skeleton);
  EXPECT_FALSE(r.worldFrame);
  EXPECT_EQ(r.engine.framesMm.rows(), v.keypoints.jointsPx.rows());
  // Without a focal length or the image's size there is no pinhole to see through.
  CameraView unsized;
  unsized.keypoints = v.keypoints;
  unsized.keypoints.imageSize.reset();
  unsized.camera.focalPx = 1400.0;
  EXPECT_THROW(skeletonPinhole(unsized), Error);
}

}  // namespace
}  // namespace ew
