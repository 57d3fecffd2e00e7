#include "core/camera/detector_offsets.h"

#include <cmath>
#include <numbers>

#include "core/common/errors.h"
#include "core/eigenwalker/fourier.h"
#include "core/keypoints/keypoint_trial.h"

namespace ew {

EigenwalkerModel modelAsDetected(const EigenwalkerModel& model, const JointOffsetsMm& offsets) {
  EigenwalkerModel moved = model;
  // p0 is the first block of w: joint-major, then x, y, z (METHOD §3).
  for (int j = 0; j < kJointCount; ++j)
    for (int c = 0; c < 3; ++c) moved.mean[3 * j + c] += offsets[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)];
  return moved;
}

void removeOffsets(Eigen::VectorXd& w, const JointOffsetsMm& offsets) {
  for (int j = 0; j < kJointCount; ++j)
    for (int c = 0; c < 3; ++c) w[3 * j + c] -= offsets[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)];
}

void addOffsets(Eigen::MatrixXd& framesMm, const JointOffsetsMm& offsets) {
  for (int j = 0; j < kJointCount; ++j)
    for (int c = 0; c < 3; ++c) framesMm.col(3 * j + c).array() += offsets[static_cast<std::size_t>(j)][static_cast<std::size_t>(c)];
}

Eigen::Vector3d sternumAsShouldersMidpointOffsetMm(const EigenwalkerModel& model) {
  const auto at = [&](Joint j) { return model.mean.segment<3>(3 * index(j)); };
  return 0.5 * (at(Joint::RShoulder) + at(Joint::LShoulder)) - at(Joint::Sternum);
}

CameraFit reconstructDetectedWalker(const EigenwalkerModel& model, const KeypointTrial& trial,
                                    CameraFitOptions options) {
  if (!options.imageSizePx && trial.imageSize)
    options.imageSizePx = Eigen::Vector2d(trial.imageSize->width, trial.imageSize->height);
  JointOffsetsMm offsets = trial.detectorOffsetMm;
  if (trial.sternumFromShoulders) {
    const Eigen::Vector3d sternum = sternumAsShouldersMidpointOffsetMm(model);
    for (int c = 0; c < 3; ++c) offsets[static_cast<std::size_t>(index(Joint::Sternum))][static_cast<std::size_t>(c)] += sternum[c];
  }
  if (!anyOffset(offsets)) return reconstructUnknownCamera(model, trial.jointsPx, trial.rateHz, options);
  CameraFit fit = reconstructUnknownCamera(modelAsDetected(model, offsets), trial.jointsPx, trial.rateHz, options);
  removeOffsets(fit.w, offsets);
  return fit;
}

namespace {

double distanceMm(const Eigen::MatrixXd& frames, Eigen::Index row, Joint a, Joint b) {
  return (frames.row(row).segment<3>(3 * index(a)) - frames.row(row).segment<3>(3 * index(b))).norm();
}

// A walker's hip width over its shank length, each the mean over one cycle.
double hipWidthPerShank(const Eigen::VectorXd& w) {
  constexpr int kSamples = 24;
  const Eigen::MatrixXd frames = synthesizeFrames(w, 2 * std::numbers::pi, 0.0, frameTimes(kSamples, kSamples));
  double width = 0.0, shank = 0.0;
  for (Eigen::Index f = 0; f < frames.rows(); ++f) {
    width += distanceMm(frames, f, Joint::RHip, Joint::LHip);
    shank += 0.5 * (distanceMm(frames, f, Joint::RKnee, Joint::RAnkle) + distanceMm(frames, f, Joint::LKnee, Joint::LAnkle));
  }
  return width / shank;
}

}  // namespace

double lateralHipOffsetMm(const EigenwalkerModel& model, double detectorHipWidthMm, double detectorShankMm) {
  if (!(detectorHipWidthMm > 0.0) || !(detectorShankMm > 0.0) || !std::isfinite(detectorHipWidthMm) ||
      !std::isfinite(detectorShankMm))
    throw Error(ErrorKind::BadArgument, "", "", "detector offsets: hip width and shank must be positive lengths");
  if (model.coefficients.cols() == 0) throw Error(ErrorKind::BadArgument, "", "", "detector offsets: the model has no walkers");
  double ratio = 0.0;
  for (Eigen::Index r = 0; r < model.coefficients.cols(); ++r)
    ratio += hipWidthPerShank(model.mean + model.eigenwalkers * model.coefficients.col(r));
  ratio /= static_cast<double>(model.coefficients.cols());
  return 0.5 * (detectorHipWidthMm - ratio * detectorShankMm);
}

}  // namespace ew
