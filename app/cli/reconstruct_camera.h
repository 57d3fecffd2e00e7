#pragma once
// `reconstruct --unknown-camera`: a pose estimator's keypoints (OpenPose, AlphaPose, MMPose
// JSON) through an unknown real camera to the walker's 3D joints, one row per input frame,
// and the camera, with the walk's metric measures (docs/CAMERA.md).

#include <optional>
#include <string>

#include "core/engine/model.h"
#include "core/keypoints/keypoint_trial.h"

namespace ew::cli {

struct CameraArgs {
  std::string input, out, layout, method = "map", modelName, mapping, imageSize;
  std::optional<double> fps, focalPx, sigma2Mm2;
  std::optional<double> alphaDeg, elevationDeg;  // known: held, not estimated
  std::string camera, cameraName;                // a calibration file and its camera
  bool json = false;
  bool orthographic = false;     // scaled orthography instead of estimating the focal length
  bool detectorOffsets = true;   // allow for the layout's detector offsets (KeypointLayout)
  bool strideFromTrunk = false;  // a tracker's joints: hold the trunk's bob as the stride
  std::string detectModel = "full";  // a video's input: the built-in detector's model
  // Rounds of the model loop on the detections' confidences (core/camera/detection_loop.h);
  // unset: 1 for a video, 0 for keypoint files.
  std::optional<int> modelLoop;
  // A keyframe file of corrections to the keypoints (core/tracking/corrected_track.h).
  std::string corrections;
  std::optional<int> person;  // 1-based: the person to fit instead of the one who walks
};

int runReconstructCamera(const EigenwalkerModel& model, const CameraArgs& args);

// The same for joints already in hand (a joint tracker's track, read as the viewer reads it):
// args.input only names them in the report; layout, mapping and detector offsets do not apply.
int runReconstructCamera(const EigenwalkerModel& model, const CameraArgs& args,
                         KeypointTrial joints);

}  // namespace ew::cli
