#include "core/camera/detection_loop.h"

#include <cmath>

namespace ew {

double reprojectionRmsWhereSure(const ClipReconstruction& clip, const Eigen::MatrixXd& detectedPx,
                                const Eigen::MatrixXd& confidence, double minConfidence) {
  double sum = 0.0;
  long n = 0;
  const Eigen::Index frames = std::min({clip.reprojectedPx.rows(), detectedPx.rows(), confidence.rows()});
  for (Eigen::Index f = 0; f < frames; ++f)
    for (int j = 0; j < kJointCount; ++j) {
      const double c = confidence(f, j);
      const double du = clip.reprojectedPx(f, 2 * j) - detectedPx(f, 2 * j);
      const double dv = clip.reprojectedPx(f, 2 * j + 1) - detectedPx(f, 2 * j + 1);
      if (!(c >= minConfidence) || !std::isfinite(du) || !std::isfinite(dv)) continue;
      sum += du * du + dv * dv;
      ++n;
    }
  return n ? std::sqrt(sum / static_cast<double>(n)) : std::nan("");
}

namespace {

// The detections with each unsure joint pulled towards the fitted walker's reprojection.
Eigen::MatrixXd reweighted(const Eigen::MatrixXd& detectedPx, const Eigen::MatrixXd& confidence,
                           const Eigen::MatrixXd& reprojectedPx, double sure, int& unsure) {
  Eigen::MatrixXd out = detectedPx;
  unsure = 0;
  for (Eigen::Index f = 0; f < out.rows(); ++f)
    for (int j = 0; j < kJointCount; ++j) {
      const double c = confidence(f, j);
      if (!std::isfinite(c) || c >= sure || !std::isfinite(out(f, 2 * j))) continue;
      const Eigen::Vector2d model = reprojectedPx.row(f).segment<2>(2 * j).transpose();
      if (!model.allFinite()) continue;
      const double keep = std::clamp(c / sure, 0.0, 1.0);
      out.row(f).segment<2>(2 * j) = (keep * out.row(f).segment<2>(2 * j).transpose() + (1.0 - keep) * model).transpose();
      ++unsure;
    }
  return out;
}

}  // namespace

DetectionLoop reconstructWithDetectionLoop(const EigenwalkerModel& model, const KeypointTrial& trial,
                                           const CameraFitOptions& fitOptions, const DetectionLoopOptions& options) {
  DetectionLoop loop;
  loop.first = reconstructKeypointTrial(model, trial, fitOptions);
  loop.last = loop.first;
  const Eigen::MatrixXd& detected = trial.jointsPx;
  const Eigen::MatrixXd& confidence = trial.jointConfidence;
  const bool hasConfidence = confidence.rows() == detected.rows() && confidence.cols() == kJointCount;
  if (!hasConfidence) return loop;
  loop.firstRmsOnSurePx = reprojectionRmsWhereSure(loop.first, detected, confidence, options.sureConfidence);
  loop.lastRmsOnSurePx = loop.firstRmsOnSurePx;
  for (int round = 0; round < options.rounds; ++round) {
    int unsure = 0;
    KeypointTrial pulled = trial;
    pulled.jointsPx = reweighted(detected, confidence, loop.last.reprojectedPx, options.sureConfidence, unsure);
    loop.unsureJointFrames = unsure;
    if (unsure == 0) break;
    loop.last = reconstructKeypointTrial(model, std::move(pulled), fitOptions);
    loop.lastRmsOnSurePx = reprojectionRmsWhereSure(loop.last, detected, confidence, options.sureConfidence);
  }
  return loop;
}

}  // namespace ew
