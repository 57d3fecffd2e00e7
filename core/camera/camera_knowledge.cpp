#include "core/camera/camera_knowledge.h"

#include <sstream>

#include "core/camera/focal_length.h"
#include "core/camera/known_stature.h"
#include "core/camera/lens_distortion.h"
#include "core/common/errors.h"
#include "core/keypoints/keypoint_trial.h"

namespace ew {

namespace {

std::string givenBy(const std::string& name) { return "given (" + name + ")"; }

std::optional<CalibratedCamera> calibrationOf(const CameraGivens& g) {
  if (g.calibrationFile.empty()) return std::nullopt;
  if (g.focalPx)
    throw Error(ErrorKind::BadArgument, g.names.calibration, "",
                "give " + g.names.focal + " or " + g.names.calibration + ", not both");
  return readCalibratedCamera(g.calibrationFile, g.calibrationCamera);
}

void resolveFocal(const CameraGivens& g, CameraKnowledge& k) {
  if (g.focalPx && !isPlausibleFocalPx(*g.focalPx))
    throw Error(ErrorKind::BadArgument, g.names.focal, "", focalLengthProblem(*g.focalPx));
  k.estimateFocal = !g.orthographic;
  if (k.calibration) {
    k.focalPx = k.calibration->focalPx();
    k.focalSource = "calibration file (" + k.calibration->name + ")";
  } else {
    k.focalPx = g.focalPx;
    k.focalSource = g.focalPx ? givenBy(g.names.focal) : "estimated";
  }
}

// The image's size: given, else the calibration's (what a MediaPipe CSV's fractions are of),
// with the calibration's principal point as the fit's prior.
void resolveImage(const CameraGivens& g, CameraKnowledge& k) {
  const CalibratedCamera* c = k.calibration ? &*k.calibration : nullptr;
  if (c && c->widthPx > 0 && c->heightPx > 0) k.principalPointPx = Eigen::Vector2d(c->cxPx, c->cyPx);
  if (g.imageSize) {
    k.imageSize = g.imageSize;
    k.imageSizeSource = givenBy(g.names.imageSize);
  } else if (c && c->widthPx > 0) {
    k.imageSize = KeypointImageSize{static_cast<int>(c->widthPx), static_cast<int>(c->heightPx)};
    k.imageSizeSource = "the calibration file (" + g.calibrationFile.string() + ")";
    k.imageSizeFromCalibration = true;
  }
}

}  // namespace

CameraKnowledge resolveCameraKnowledge(const CameraGivens& given) {
  CameraKnowledge k;
  k.calibration = calibrationOf(given);
  resolveFocal(given, k);
  resolveImage(given, k);
  k.alphaDeg = given.alphaDeg;
  k.elevationDeg = given.elevationDeg;
  k.alphaSource = given.alphaDeg ? givenBy(given.names.alpha) : "estimated";
  k.elevationSource = given.elevationDeg ? givenBy(given.names.elevation) : "estimated";
  if (given.statureMm && !(*given.statureMm >= 1000.0 * kMinStatureM && *given.statureMm <= 1000.0 * kMaxStatureM)) {
    std::ostringstream problem;
    problem << *given.statureMm / 1000.0 << " m is not a person's stature (" << kMinStatureM << "-" << kMaxStatureM
            << " m)";
    throw Error(ErrorKind::BadArgument, given.names.stature, "", problem.str());
  }
  k.statureMm = given.statureMm;
  k.statureSource = given.statureMm ? givenBy(given.names.stature) : "the model's prior";
  return k;
}

CameraFitOptions cameraFitOptions(const CameraKnowledge& camera, const EstimatorOptions& estimator,
                                  const std::string& file) {
  CameraFitOptions o;
  o.estimator = estimator;
  o.focalPx = camera.focalPx;
  o.estimateFocal = camera.estimateFocal;
  o.alphaDeg = camera.alphaDeg;
  o.elevationDeg = camera.elevationDeg;
  o.horizonRowPx = camera.horizonRowPx;
  o.file = file;
  // A calibration's principal point is the prior's centre, over its image.
  if (camera.principalPointPx && camera.calibration) {
    o.imageSizePx = Eigen::Vector2d(camera.calibration->widthPx, camera.calibration->heightPx);
    o.principalPointPx = camera.principalPointPx;
  }
  return o;
}

CameraFitOptions cameraFitOptions(const EstimatorOptions& estimator, const std::string& file) {
  return cameraFitOptions(CameraKnowledge{}, estimator, file);
}

std::string principalPointPrior(const CameraFitOptions& o, const KeypointTrial& t) {
  if (!o.focalPx && !o.estimateFocal) return "none (scaled orthography has no principal point)";
  if (o.principalPointPx) return "the calibration's";
  if (o.imageSizePx || t.imageSize) return "the image's centre";
  if (!o.framingPrior) return "none (the image's size unknown: --image-size gives it, or a video beside the keypoints)";
  return "the walker's row (the image's size unknown: --image-size gives it, or a video beside the keypoints)";
}

std::optional<int> undistortKeypoints(const CameraKnowledge& camera, KeypointTrial& trial) {
  if (!camera.calibration || !hasDistortion(*camera.calibration)) return std::nullopt;
  return undistortTrial(*camera.calibration, trial);
}

}  // namespace ew
