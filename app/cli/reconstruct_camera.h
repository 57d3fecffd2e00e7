#pragma once
// `reconstruct --unknown-camera`: a pose estimator's keypoints (OpenPose, AlphaPose, MMPose
// JSON) through an unknown real camera to the walker's 3D joints, one row per input frame,
// and the camera, with the walk's metric measures (docs/CAMERA.md).

#include <optional>
#include <string>

#include "core/eigenwalker/model.h"
#include "core/camera/camera_reconstruction.h"
#include "core/keypoints/keypoint_trial.h"
#include "app/cli/reconstruct_args.h"

namespace ew::cli {

// fitOut: when given, the camera fit written (its speed and stride for `gait V.mp4`).
int runReconstructCamera(const EigenwalkerModel& model, const CameraArgs& args, CameraFit* fitOut = nullptr);

// The same for joints already in hand (a joint tracker's track, read as the viewer reads it):
// args.input only names them in the report; layout, mapping and detector offsets do not apply.
int runReconstructCamera(const EigenwalkerModel& model, const CameraArgs& args,
                         KeypointTrial joints);

}  // namespace ew::cli
