#pragma once
// A pose estimator's clip to a 3D walker and the camera that filmed it: read and clean the
// keypoints (core/keypoints/keypoint_trial.h), find the gait cycles in the image
// (image_gait.h), fit walker and camera (camera_reconstruction.h), and draw the result back
// through the camera. What `reconstruct --unknown-camera` writes and the viewer shows.

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "core/camera/camera_reconstruction.h"
#include "core/camera/lifted_feet.h"
#include "core/keypoints/image_gait.h"
#include "core/keypoints/keypoint_trial.h"

namespace ew {

struct ClipReconstruction {
  KeypointTrial trial;
  ImageGait gait;
  CameraFit fit;
  Eigen::VectorXd timesS;    // T: each input frame's time
  Eigen::MatrixXd framesMm;  // T × 45: the walker at each input frame (METHOD §2 canonical frame)
  Eigen::MatrixXd reprojectedPx;  // T × 30: the 3D walker through the camera, pixels, y down
  // Per joint, RMS over the frames that see it of |reprojected − input| (px); NaN if never seen.
  std::array<double, kJointCount> residualRmsPx{};
  // The image's heels and toes lifted into framesMm's frame (lifted_feet.h): empty feetMm for
  // a layout without feet, an orthographic fit's or an end-on view's.
  LiftedFeet feet;
  // Where the stride frequency came from: "foot strikes", "trunk's bob (the foot strikes read
  // … Hz)" (gaitForTheFit below), "trunk's bob (a track's, held)" (holdTheTrunksStride), or the
  // caller's own hint.
  std::string strideSource;
  // Why the fit may not be trusted, as sentences (cameraFitCautions): a weak azimuth in place,
  // a stride people do not walk, a fisheye's field of view. Empty for a fit that looks sound.
  std::vector<std::string> cautions;
};

// The trunk's bob stands for the feet's strikes when it is clear and the strikes read a stride
// more than this share away from it, or none. Seen from the front or from behind the ankles'
// lead along the image's progression is short and the strikes come irregularly (measured on
// synthetic footage of held-out walkers: 1.18 and 1.72 Hz for strides of 0.82 and 0.96 Hz from
// behind, no stride from the front), where the bob reads within 1 % in every view
// (docs/TRACKING_DESIGN.md); in a side view the two agree within a few per cent.
inline constexpr double kFeetDisagreeWithTheBobShare = 0.15;

// The camera fit's options are completed here: the stride hint from the image's foot strikes
// unless the caller gives one (the model loop's trunk bob) or the trunk's bob disagrees with
// them (kFeetDisagreeWithTheBobShare, then held at the bob); `fitOptions.file` names
// the input in errors when left empty. Throws what the reader, the gait finder and the fit
// throw (typed errors naming the file).
ClipReconstruction reconstructKeypointClip(const EigenwalkerModel& model,
                                           const std::filesystem::path& input,
                                           const KeypointOptions& keypointOptions,
                                           CameraFitOptions fitOptions);
// The same from a trial already read (a joint tracker's, core/keypoints trialFromJoints).
ClipReconstruction reconstructKeypointTrial(const EigenwalkerModel& model, KeypointTrial trial,
                                            CameraFitOptions fitOptions);

// The image's gait cycles, and the stride the fit starts from or holds, set in `fitOptions`: the
// caller's hint when it gives one; else the foot strikes' stride as a hint; else, when the
// trunk's bob is clear and the strikes read none or one more than kFeetDisagreeWithTheBobShare
// away, the bob, held. `source` says which ("foot strikes", "trunk's bob (…)", the options'
// strideHintSource, "held by the caller", "the caller's hint"). A walker walking in place (a
// treadmill) sets fitOptions.inPlace. Throws what imageGaitCycles throws.
ImageGait gaitForTheFit(const KeypointTrial& trial, CameraFitOptions& fitOptions,
                        std::string& source);

// For a joint tracker's output: the stride frequency from the trunk's bob, held
// (core/keypoints/image_gait.h trunkBobStrideHz). A tracker keeps the trunk where it loses
// the crossing feet, whose strikes can read as twice the steps or none; with no clear bob the
// options are left as they are (the feet's strikes). Returns whether it held a stride.
bool holdTheTrunksStride(const KeypointTrial& trial, CameraFitOptions& fitOptions);

// Where the walker's canonical origin stands at time t relative to the camera's look-at point
// (docs/CAMERA.md): (0, y0 + v t, −h); orthography has no y0 or h (zero).
Eigen::Vector3d walkerOriginFromLookAt(const WalkCamera& camera, double timeS);
// The camera's centre relative to its look-at point, canonical axes, mm: distance D back along
// the viewing direction (azimuth α), D sin ε up. Scaled orthography has no distance:
// `orthographicDistanceMm` stands in for it.
Eigen::Vector3d cameraFromLookAt(const WalkCamera& camera, double orthographicDistanceMm = 5000.0);

}  // namespace ew
