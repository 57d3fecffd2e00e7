#include "core/camera/clip_reconstruction.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>

#include "core/camera/detector_offsets.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/projection.h"

namespace ew {

namespace {

std::array<double, kJointCount> residualRms(const Eigen::MatrixXd& reprojected,
                                            const Eigen::MatrixXd& observed) {
  std::array<double, kJointCount> rms{};
  for (int j = 0; j < kJointCount; ++j) {
    double sum = 0.0;
    int n = 0;
    for (Eigen::Index f = 0; f < observed.rows(); ++f) {
      const double du = reprojected(f, 2 * j) - observed(f, 2 * j);
      const double dv = reprojected(f, 2 * j + 1) - observed(f, 2 * j + 1);
      if (!std::isfinite(du) || !std::isfinite(dv)) continue;
      sum += du * du + dv * dv;
      ++n;
    }
    rms[static_cast<std::size_t>(j)] =
        n > 0 ? std::sqrt(sum / n) : std::numeric_limits<double>::quiet_NaN();
  }
  return rms;
}

}  // namespace

ClipReconstruction reconstructKeypointClip(const EigenwalkerModel& model,
                                           const std::filesystem::path& input,
                                           const KeypointOptions& keypointOptions,
                                           CameraFitOptions fitOptions) {
  if (fitOptions.file.empty()) fitOptions.file = input.string();
  return reconstructKeypointTrial(model, readKeypointTrial(input, keypointOptions),
                                  std::move(fitOptions));
}

namespace {

std::string strideText(double hz) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << hz << " Hz";
  return s.str();
}

}  // namespace

namespace {

ImageGait gaitAndStride(const KeypointTrial& trial, CameraFitOptions& fitOptions, std::string& source) {
  if (fitOptions.strideHzHint) {
    source = !fitOptions.strideHintSource.empty() ? fitOptions.strideHintSource
             : fitOptions.holdStrideHz                ? "held by the caller"
                                                      : "the caller's hint";
    return imageGaitCycles(trial, fitOptions.holdStrideHz ? fitOptions.strideHzHint : std::nullopt);
  }
  const std::optional<double> bob = trunkBobStrideHz(trial);
  // With the bob held the walking checks still run, and the strikes are read beside it.
  const ImageGait g = imageGaitCycles(trial, bob);
  const bool feetAgree =
      bob && std::abs(g.strikesStrideHz - *bob) <= kFeetDisagreeWithTheBobShare * *bob;
  if (!bob || feetAgree) {
    source = "foot strikes";
    ImageGait feet = bob ? imageGaitCycles(trial) : g;
    fitOptions.strideHzHint = feet.strideHz;
    return feet;
  }
  source = "trunk's bob (the foot strikes read " +
           (g.strikesStrideHz > 0.0 ? strideText(g.strikesStrideHz) : std::string("none")) + ")";
  fitOptions.strideHzHint = bob;
  fitOptions.holdStrideHz = true;
  return g;
}

}  // namespace

ImageGait gaitForTheFit(const KeypointTrial& trial, CameraFitOptions& fitOptions, std::string& source) {
  ImageGait g = gaitAndStride(trial, fitOptions, source);
  fitOptions.inPlace = g.inPlace;
  return g;
}

ClipReconstruction reconstructKeypointTrial(const EigenwalkerModel& model, KeypointTrial trial,
                                            CameraFitOptions fitOptions) {
  ClipReconstruction c;
  c.trial = std::move(trial);
  c.gait = gaitForTheFit(c.trial, fitOptions, c.strideSource);
  if (fitOptions.file.empty()) fitOptions.file = c.trial.file;
  c.fit = reconstructDetectedWalker(model, c.trial, fitOptions);
  c.timesS = frameTimes(c.trial.frameCount, c.trial.rateHz);
  c.framesMm = synthesizeFrames(c.fit.w, c.fit.omegaRadS, c.fit.phaseRad, c.timesS);
  c.reprojectedPx = projectWalk(c.framesMm, c.timesS, c.fit.camera);
  c.residualRmsPx = residualRms(c.reprojectedPx, c.trial.jointsPx);
  c.feet = liftFeetOntoSagittalPlanes(c.trial.feetPx, c.framesMm, c.timesS, c.fit.camera);
  FitGivens given{fitOptions.alphaDeg.has_value(), fitOptions.focalPx.has_value(), std::nullopt};
  if (fitOptions.imageSizePx)
    given.imageSizePx = fitOptions.imageSizePx;
  else if (c.trial.imageSize && c.trial.imageSize->width > 0 && c.trial.imageSize->height > 0)
    given.imageSizePx = Eigen::Vector2d(c.trial.imageSize->width, c.trial.imageSize->height);
  c.cautions = cameraFitCautions(c.fit, given);
  return c;
}

bool holdTheTrunksStride(const KeypointTrial& trial, CameraFitOptions& fitOptions) {
  const std::optional<double> bob = trunkBobStrideHz(trial);
  if (!bob) return false;
  fitOptions.strideHzHint = bob;
  fitOptions.holdStrideHz = true;
  fitOptions.strideHintSource = "trunk's bob (a track's, held)";
  return true;
}

Eigen::Vector3d walkerOriginFromLookAt(const WalkCamera& camera, double timeS) {
  if (camera.model == CameraModel::ScaledOrthographic) return {0.0, camera.speedMmS * timeS, 0.0};
  return {0.0, camera.startOffsetMm + camera.speedMmS * timeS, -camera.lookAtHeightMm};
}

Eigen::Vector3d cameraFromLookAt(const WalkCamera& camera, double orthographicDistanceMm) {
  const double d =
      camera.model == CameraModel::Pinhole ? camera.distanceMm : orthographicDistanceMm;
  const double a = degToRad(camera.alphaDeg), e = degToRad(camera.elevationDeg);
  // The camera looks along the depth axis (−sin α, cos α, 0) tilted down by ε: it stands at
  // depth −D cos ε and height D sin ε from the look-at point (docs/CAMERA.md).
  const Eigen::Vector3d depth(-std::sin(a), std::cos(a), 0.0);
  return -d * std::cos(e) * depth + Eigen::Vector3d(0.0, 0.0, d * std::sin(e));
}

}  // namespace ew
