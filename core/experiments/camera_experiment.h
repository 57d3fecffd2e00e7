#pragma once
// Experiment "camera" (issue 13): each held-out walker filmed by random real cameras and
// reconstructed with everything unknown, through the whole user path — the clip is written
// as OpenPose BODY_25 JSON (or AlphaPose COCO-17: options.layout), read back, cleaned
// (core/keypoints) and reconstructed (core/camera/camera_reconstruction.h) with the fold's
// model (docs/CAMERA.md).
//
// Cameras: azimuth uniform over the circle, elevation 0-30°, focal 800-3000 px, distance
// 3.5-8 m (further when the walker would not fit the 1080 px height), 1920 × 1080 image,
// looking at 1 m height where the walker passes mid-clip; the walker crosses at 1.1-1.5 m/s
// and the clip is the longest run of frames with its pelvis in the image (at least 1.5
// strides). Keypoints: Gaussian pixel noise per level, a share of joint samples given low
// confidence (dropped by the reader), and in a share of clips a person standing still.
// Errors: MPJPE over the clip's frames after removing the mean translation (mm), |α̂ − α|,
// |ε̂ − ε| (degrees), focal length and head-height relative errors.
//
// Beside it, on the same keypoints read back, the other two engines, which need more than
// the eigenwalker does — they are given the true camera (intrinsics and pose, a
// calibration: calibrationOf):
//   skeleton  the walker's own bone lengths (the median over the clip's true frames, as the
//             paper measures its performer); pelvis depth from the bone bound; result in
//             the world, the known progression subtracted (core/skeleton/skeleton_camera.h).
//             Then with each bone's branch taken from the eigenwalker's fit of the clip (its
//             walker in its own estimated camera frame: skeleton_solve.h's guide). And with
//             bone lengths a user without a 3D reference has (core/skeleton/bone_sources.h):
//             Zou et al.'s Table 2 scaled to the walker's stature (its head-to-ankles
//             distance / 0.87; the paper's branch rule), and the eigenwalker's own walker
//             (its bones and its guide: nothing known of the walker but the camera).
//   snippet   it takes an orthographic view in mm, so it is given the rays made level (the
//             elevation turned out) and scaled at the pelvis depth the skeleton engine
//             found — weak perspective — and the camera's azimuth as the known view; its
//             prior is learnt per fold from the other subjects' walkers at 1.3 m/s.
// Each scored like the eigenwalker: MPJPE over the clip after removing the mean translation.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/experiments/gait_agreement.h"
#include "core/experiments/leave_one_out.h"

namespace ew {

// How the simulated detector's clip is written (openpose_writer.h).
enum class ClipLayout { Body25, Coco17 };  // OpenPose BODY_25 JSON, AlphaPose COCO-17 JSON

struct CameraExperimentOptions {
  int camerasPerWalker = 3;
  std::vector<double> noisePx{0.0, 2.0, 5.0};
  double dropShare = 0.03;
  double bystanderShare = 1.0 / 3.0;
  unsigned seed = 2026;
  double sigma2Mm2 = 1000.0;
  double fps = 30.0;
  int threads = 1;
  bool skeleton = true;    // score the skeleton engine beside the eigenwalker
  bool snippet = true;     // and the snippet engine (needs the skeleton engine's depth)
  // Measure the gait of every engine's reconstruction beside the walker's own
  // (gait_agreement.h; setting "camera", noise in px): CameraRow::gait.
  bool gait = false;
  // The simulated detector puts each hip this far out from its joint centre (mm; the pelvis
  // between them): unset, the BODY_25 table's offset, the one the reader allows for
  // (docs/KEYPOINTS.md, "Detector hips"). The truth stays the joint centres.
  std::optional<double> detectorHipOffsetMm;
  bool allowForDetectorOffsets = true;  // false: the reader takes the hips for centres
  // The widened experiment's factors (issue 55); each default is the clip described above.
  // The clip cut to this many strides around the middle of the walker's run in the image
  // (a camera is drawn again until the run holds them); unset: the whole run (≥ 1.5 strides).
  std::optional<double> clipStrides;
  // The camera's focal length and image (and so its principal point) scaled, after the draw,
  // so that the walker's head-to-ankles height in the image is this (median over the clip):
  // a lower-resolution camera seeing the same scene; unset: as drawn (about 200-900 px).
  std::optional<double> walkerHeightPx;
  double minSpeedMps = 1.1, maxSpeedMps = 1.5;  // the walker's progression, uniform
  // The walker's stride frequency scaled by (speed / 1.3 m/s)^exponent: 0 keeps each walker's
  // own (the stride lengthens with the speed alone); 0.5 shares a faster speed between the
  // cadence and the stride, as people walking faster do.
  double cadenceSpeedExponent = 0.0;
  ClipLayout layout = ClipLayout::Body25;
  double minElevationDeg = 0.0, maxElevationDeg = 30.0;  // the camera's tilt, uniform
  // The reader told the image's size (as a video's is known): the fit then holds the principal
  // point near its centre (docs/CAMERA.md); false, bare keypoint files, the hardest case.
  bool imageSizeKnown = false;
  // The fit given the camera's focal length (a calibration, a phone's metadata, `--focal-px`):
  // the distance then rests on the walker's size instead of on the perspective.
  bool focalKnown = false;
  // A real detector reports no point off its picture: such points (after the noise) are then
  // written with confidence 0, which the reader takes as missing. false: every point is written,
  // off the picture or not, as the experiment has always done.
  bool offPictureDropped = false;
  // The height of the point the camera looks at (where the walker passes mid-clip), uniform
  // (mm); equal, no draw: the clip above, aimed at 1 m (about the walker's pelvis).
  double minLookAtHeightMm = 1000.0, maxLookAtHeightMm = 1000.0;
  // The scene's horizon read off the footage's level lines (video/scene_horizon.h) and given to
  // the fit as its prior (CameraFitOptions::horizonRowPx): the true camera's horizon, read with a
  // Gaussian error of this SD and this bias (degrees as the camera sees them; the bias stands
  // for lines that are not level, a ramp's). Unset: no horizon, as for a keypoint file.
  std::optional<double> horizonReadSdDeg;
  double horizonReadBiasDeg = 0.0;
  // Each clip's keypoint file(s) kept in this folder, as SUBJECT_cameraK_Npx/ (the camera
  // 0-based, the noise level in px), for a user to open a clip the experiment scored; unset:
  // written to a temporary folder and removed.
  std::optional<std::filesystem::path> keepClipsDir;
};

// Another engine's result on a clip: NaN MPJPE and the reason when it gave none.
struct EngineClipScore {
  double mpjpeMm = 0.0;
  int clampedBoneFrames = 0;  // skeleton only
  std::string error;
  double seconds = 0.0;       // the engine's wall time on the clip (the snippet engine's
                              // excludes the skeleton engine's depth it is given)
};

struct CameraRow {
  std::string subject, walker;
  int camera = 0;           // 0 … camerasPerWalker − 1 (the same camera at every noise level)
  double noisePx = 0.0;
  bool bystander = false;
  int frames = 0;
  double trueAlphaDeg = 0, trueElevationDeg = 0, trueFocalPx = 0, trueDistanceM = 0;
  double alphaDeg = 0, elevationDeg = 0, focalPx = 0, distanceM = 0;
  double alphaErrorDeg = 0, elevationErrorDeg = 0, focalRelError = 0, heightRelError = 0;
  double mpjpeMm = 0, reprojectionRmsPx = 0;
  // The camera's distance from the walker's pelvis, mean over the clip (m): true, the fit's
  // (in its own camera) and the relative error; what a user reads as "how far away".
  double trueWalkerDistanceM = 0, walkerDistanceM = 0, distanceRelError = 0;
  double walkerHeightPx = 0;  // head to ankles in the image, median over the clip
  // The angle below the horizontal at which the camera sees the walker's pelvis, mean over the
  // clip (°): true, the fit's, and the error. The walker's image fixes this angle; the camera's
  // own tilt also needs the row of its principal point (docs/CAMERA.md, "Framing").
  double trueViewElevationDeg = 0, viewElevationDeg = 0, viewElevationErrorDeg = 0;
  // The true principal point's row below the walker's pelvis at mid-clip, in the walker's
  // heights in the image: what the framing prior, without the image, takes to be 0 ± 0.5.
  double framingOffsetOfHeight = 0;
  // The fit's stature, speed and stride length, each with the SD the fit gives it
  // (CameraFit::sd, NaN where it gives none), beside the truth.
  double trueStatureM = 0, statureM = 0, statureSdM = 0;
  double trueSpeedMps = 0, speedMps = 0, speedSdMps = 0;
  double trueStrideLengthM = 0, strideLengthM = 0, strideLengthSdM = 0;
  // The fit's stride and SD had the true stature been given (scaleToStature's).
  double strideGivenStatureM = 0, strideGivenStatureSdM = 0;
  // The SDs the fit gives its camera (CameraFit::sd): azimuth, elevation, focal length and the
  // walker's distance (walkerDistanceM), beside the errors above.
  double alphaSdDeg = 0, elevationSdDeg = 0, focalSdPx = 0, walkerDistanceSdM = 0;
  double strides = 0;         // the clip's length in the walker's strides
  double seconds = 0;       // the eigenwalker's wall time: fit through the unknown camera
  std::string error;        // empty: reconstructed; else why not (a failure)
  std::optional<EngineClipScore> skeleton, snippet;  // unset: not asked for
  std::optional<EngineClipScore> skeletonTable2;            // Table 2 × stature
  std::optional<EngineClipScore> skeletonEigenwalkerBones;  // the eigenwalker's bones and guide
  std::optional<EngineClipScore> skeletonGuided;  // own bones, branches from the eigenwalker's fit
  std::vector<GaitAgreementRow> gait;  // options.gait: per engine that answered, per measure
};

// The engine labels of CameraRow::gait, in the order of the columns of camera.csv.
extern const char* const kCameraEigenwalker;
// Its gait with the walker's stature given: the fit scaled to it (a pinhole's image is the same
// for a walker s times taller s times further away, so only a known size fixes the scale).
extern const char* const kCameraEigenwalkerStatureGiven;
extern const char* const kCameraSkeletonOwnBones;
extern const char* const kCameraSkeletonGuided;
extern const char* const kCameraSkeletonTable2;
extern const char* const kCameraSkeletonEigenwalkerBones;
extern const char* const kCameraSnippet;

// Error(BadArgument) "camera: …" for no cameras, a negative or non-finite noise level, a
// share outside [0, 1], σ² negative, a frame rate outside 1-240, or folds not of `walkers`.
std::vector<CameraRow> cameraErrors(const std::vector<ExperimentWalker>& walkers, const std::vector<Fold>& folds,
                                    const CameraExperimentOptions& options);

// Per noise level: mean MPJPE, medians of |α error|, |elevation error|, focal relative
// error, share of heights within 5 %, failures.
struct CameraSummary {
  double noisePx = 0;
  int clips = 0, failures = 0;
  double meanMpjpeMm = 0, medianAlphaErrorDeg = 0, medianElevationErrorDeg = 0, medianFocalRelError = 0;
  double medianHeightRelError = 0, heightWithin5Share = 0;
  // The other engines over the clips they were asked for (0 clips: not asked).
  struct Other {
    int clips = 0, failures = 0;
    double meanMpjpeMm = 0;
  };
  Other skeleton, skeletonGuided, skeletonTable2, skeletonEigenwalkerBones, snippet;
};
std::vector<CameraSummary> summarizeCamera(const std::vector<CameraRow>& rows);

// [SECTION] The widened experiment (issue 55: "camera-wide")
//
// The eigenwalker alone (no other engine) on clips made as above at one noise level (2 px),
// one factor changed at a time from the clip above (the "base" level of every factor) — the
// clip's length in strides, the walker's height in pixels, the walking speed, the layout
// written, the frame rate, the camera's elevation — and a condition with every factor at
// its hardest level at once. Each condition draws the same cameras (the same seed).

struct CameraWideCondition {
  std::string factor, level;        // "length (strides)", "1.2"; the base is factor "base"
  CameraExperimentOptions options;  // the clip's options for this condition
};

// The conditions over `base` (its seed, noise, threads, σ² …): the base, then per factor its
// levels (length 3 / 2 / 1.5 / 1.2 strides; height 400 / 240 / 160 / 120 px; speed
// 1.5-2.0 m/s with the cadence taking half; COCO-17; 25 fps; elevation 0-35° and 20-35°;
// the image's size known; the camera aimed 0-2 m high; the focal length known; points off the
// picture dropped), then "all hardest" (1.2 strides, 120 px, 1.5-2.0 m/s, COCO-17, 25 fps,
// 0-35°, image unknown; and with the image, the focal length, the edge or the scene's horizon);
// the scene's horizon read within 0.5° (and read 3° off) is factor "horizon". `factors` keeps
// only the factors named (their first word: "length", "height", "speed", "layout", "fps",
// "elevation", "image", "aim", "focal", "edge", "horizon", "hardest");
// empty: all. Error(BadArgument) naming an unknown factor.
std::vector<CameraWideCondition> cameraWideConditions(const CameraExperimentOptions& base,
                                                      const std::vector<std::string>& factors = {});

struct CameraWideRow {
  std::string factor, level;
  CameraRow clip;
};

std::vector<CameraWideRow> cameraWideErrors(const std::vector<ExperimentWalker>& walkers,
                                            const std::vector<Fold>& folds,
                                            const std::vector<CameraWideCondition>& conditions);

// Per condition (in the order of the rows): refusals, mean and median MPJPE, medians of
// |α error|, |elevation error|, |view elevation error| and the distance's relative error, the share of clips whose
// elevation is more than 5° off and whose distance is more than 20 % off.
struct CameraWideSummary {
  std::string factor, level;
  int clips = 0, refusals = 0;
  double meanMpjpeMm = 0, medianMpjpeMm = 0, medianAlphaErrorDeg = 0, medianElevationErrorDeg = 0;
  double medianViewElevationErrorDeg = 0;
  // Shares of the clips whose stature, speed or stride length is within 1.96 SD of the truth.
  double statureWithin2SdShare = 0, speedWithin2SdShare = 0, strideWithin2SdShare = 0;
  double strideGivenStatureWithin2SdShare = 0;
  // The same for the camera: azimuth, elevation, focal length, the walker's distance.
  double alphaWithin2SdShare = 0, elevationWithin2SdShare = 0, focalWithin2SdShare = 0, distanceWithin2SdShare = 0;
  double medianDistanceRelError = 0, elevationOver5Share = 0, distanceOver20Share = 0;
  double medianWalkerHeightPx = 0, medianStrides = 0;
};
std::vector<CameraWideSummary> summarizeCameraWide(const std::vector<CameraWideRow>& rows);

}  // namespace ew
