#pragma once
// The walker model closes the loop on a detector's keypoints (issue 52; Howe, Leventon &
// Freeman 1999: the 3D estimate feeds back into the 2D one). A detector says how sure it is of
// each point (BlazePose's visibility): where it is unsure — the far leg behind the near one, an
// arm behind the trunk — the fitted walker drawn back through the estimated camera is the
// prior. Each unsure joint is pulled towards it in proportion to the doubt, and the walker and
// camera are fitted again. docs/DETECTOR.md, "The model loop", says what it adds.
#include "core/camera/clip_reconstruction.h"

namespace ew {

struct DetectionLoopOptions {
  // A joint at or above this confidence is taken as detected; below, its detection keeps the
  // share confidence / sureConfidence and the fitted walker's reprojection the rest.
  double sureConfidence = 0.8;
  int rounds = 1;
};

struct DetectionLoop {
  ClipReconstruction first;  // the fit to the detections as they are
  ClipReconstruction last;   // after the rounds (first when no joint was unsure)
  int unsureJointFrames = 0;  // joint-frames re-weighted in each round
  // The reprojection RMS over the sure joint-frames only (what the detector is sure of), of the
  // first fit and of the last: whether the loop made the walker meet what is seen better.
  double firstRmsOnSurePx = 0.0, lastRmsOnSurePx = 0.0;
};

// Fits, then re-weights and refits `options.rounds` times. A trial without joint confidences
// (a tracker's) is fitted once. Throws what reconstructKeypointTrial throws.
DetectionLoop reconstructWithDetectionLoop(const EigenwalkerModel& model, const KeypointTrial& trial,
                                           const CameraFitOptions& fitOptions, const DetectionLoopOptions& options = {});

// The RMS of |reprojected − detected| over the joint-frames with confidence ≥ minConfidence
// (NaN when there are none).
double reprojectionRmsWhereSure(const ClipReconstruction& clip, const Eigen::MatrixXd& detectedPx,
                                const Eigen::MatrixXd& confidence, double minConfidence);

}  // namespace ew
