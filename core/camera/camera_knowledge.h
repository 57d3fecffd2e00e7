#pragma once
// What is known of the camera, resolved once for every program: from what the user gave — a
// focal length, a calibration file, the image's size, a held azimuth or elevation, scaled
// orthography — to the camera the fit uses and where each value came from. The CLI's
// `reconstruct --unknown-camera`, the skeleton engine's eigenwalker guide, the viewer's
// keypoint clip, the experiments and the studies all build their CameraFitOptions here
// (cameraFitOptions), so that a rule (the focal length's range, a calibration's image size
// standing in for a MediaPipe CSV's, its principal point as the fit's prior) holds everywhere.

#include <filesystem>
#include <optional>
#include <string>

#include "core/camera/calibration_file.h"
#include "core/camera/camera_reconstruction.h"
#include "core/keypoints/keypoint_frames.h"

namespace ew {

struct KeypointTrial;

// What the user gave; each field unset when not given.
struct CameraGivens {
  std::optional<double> focalPx;
  std::filesystem::path calibrationFile;          // empty: none
  std::optional<std::string> calibrationCamera;   // which camera of a file with several
  std::optional<KeypointImageSize> imageSize;     // the image's size in px
  std::optional<double> alphaDeg, elevationDeg;   // held instead of estimated
  bool orthographic = false;                      // no focal known: scaled orthography, not estimated
  std::optional<double> statureMm;                // the walker's: the scale (known_stature.h)
  // How the program names each given in errors and sources (the CLI's options by default;
  // the viewer passes its fields' names).
  struct Names {
    std::string focal = "--focal-px", calibration = "--camera", imageSize = "--image-size";
    std::string alpha = "--angle", elevation = "--elevation", stature = "--stature";
  } names;
};

// The camera as the fit will see it, and where each value came from (reports and the viewer's
// header say it).
struct CameraKnowledge {
  std::optional<CalibratedCamera> calibration;  // read once: its lens is undone with it
  std::optional<double> focalPx;                // known focal length: a pinhole with one unknown less
  bool estimateFocal = true;                    // unknown focal: estimated, else scaled orthography
  std::string focalSource;                      // "given (--focal-px)", "calibration file (cam01)", "estimated", …
  std::optional<KeypointImageSize> imageSize;   // given, else the calibration's
  std::string imageSizeSource;                  // "" when neither gave it (the keypoints or a video may)
  bool imageSizeFromCalibration = false;
  std::optional<Eigen::Vector2d> principalPointPx;  // the calibration's
  std::optional<double> alphaDeg, elevationDeg;
  std::string alphaSource, elevationSource;     // "given (--angle)" or "estimated"
  // The walker's stature when given: the fit is scaled to it (known_stature.h); else the scale
  // is the model's prior on body size.
  std::optional<double> statureMm;
  std::string statureSource;                    // "given (--stature)" or "the model's prior"
  // The horizon's row (px) read off the footage's own level lines (video/scene_horizon.h),
  // when the program read it: the fit's prior on its camera's height (CameraFitOptions).
  std::optional<double> horizonRowPx;
};

// Reads the calibration file (readCalibratedCamera's errors) and checks what was given:
// Error(BadArgument) naming the given for a focal length no camera has (focal_length.h), for
// a focal length and a calibration both given, and for a stature no person has.
CameraKnowledge resolveCameraKnowledge(const CameraGivens& given);

// The one construction site of the camera fit's options: the knowledge, the estimator and the
// file named in errors. Everything else (the stride hint, walking in place) is the fit's own
// reading of the clip (clip_reconstruction.h).
// The estimator's default is the fit's own (CameraFitOptions: MAP at σ² = 1000 mm²).
CameraFitOptions cameraFitOptions(const CameraKnowledge& camera,
                                  const EstimatorOptions& estimator = CameraFitOptions().estimator,
                                  const std::string& file = "");
// Nothing known of the camera: every value estimated (the experiments, the studies).
CameraFitOptions cameraFitOptions(const EstimatorOptions& estimator, const std::string& file);

// Where the fit expected the principal point, for reports.
std::string principalPointPrior(const CameraFitOptions& options, const KeypointTrial& trial);

// A calibrated camera's lens distortion taken out of the trial's points (lens_distortion.h):
// the points lost, or nullopt when the camera is not calibrated or its lens has no distortion.
std::optional<int> undistortKeypoints(const CameraKnowledge& camera, KeypointTrial& trial);

}  // namespace ew
