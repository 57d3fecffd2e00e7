#pragma once
// 3D walker and camera from a walker's joints in a real image (pixels, y down), the camera
// unknown (docs/CAMERA.md): azimuth α over the whole circle, elevation, scale (or distance
// for a known focal length), image translation and the walker's progression, with the
// eigenwalker coefficients, stride frequency and phase. Levenberg-Marquardt on the
// reprojection error of every frame (plus the MAP prior), started from the orthographic
// view-angle search of core/eigenwalker/reconstruction.h at each of its best minima.

#include <Eigen/Core>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "core/camera/walk_camera.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/reconstruction.h"

namespace ew {

struct CameraFitOptions {
  EstimatorOptions estimator{Estimator::Map, 1000.0};
  std::optional<double> focalPx;        // known: a pinhole with this focal length
  bool estimateFocal = true;            // focal unknown: a pinhole estimating it, else scaled orthography
  // Known view: held at these values instead of estimated (the viewer's "fix" controls).
  std::optional<double> alphaDeg;       // azimuth, METHOD §5
  std::optional<double> elevationDeg;   // camera looking down by this much
  // The image the joints were found in (width, height px), when known. A pinhole's c_x, c_y
  // are its principal point, which trades against the tilt when perspective is weak: a
  // Gaussian prior holds it near principalPointPx (a calibration's), else the image's centre,
  // with an SD of kPrincipalPointSdShare of the image's longer side (docs/CAMERA.md).
  std::optional<Eigen::Vector2d> imageSizePx;
  std::optional<Eigen::Vector2d> principalPointPx;
  // Without the image: a Gaussian prior on c_y alone, centred on the row of the walker's
  // pelvis at mid-clip with an SD of kFramingSdOfHeight of the walker's height in the image
  // (a camera filming a walker points at them; docs/CAMERA.md, "Framing"). false: none.
  bool framingPrior = true;
  // The row of the horizon (px) where the scene's own level lines run to (video/scene_horizon.h),
  // when read: a Gaussian prior on the fitted pinhole's horizon (horizonRowPx), kHorizonSdDeg as
  // the camera sees it. It holds the camera's height over the walker, which the walker's image
  // barely shows from afar (docs/CAMERA.md, "The scene's horizon").
  std::optional<double> horizonRowPx;
  std::optional<double> strideHzHint;   // from the image's foot strikes (image_gait.h)
  // Hold the stride frequency at the hint instead of refining it: a hint more trustworthy than
  // the image's limbs (the model loop's trunk bob, when the tracker has lost the feet).
  bool holdStrideHz = false;
  std::string strideHintSource;         // where a given hint came from, for reports ("" unsaid)
  // Walking in place (a treadmill; image_gait.h): the walker's progression held at zero. Its
  // speed is then the stance feet's, read off the fitted walk (CameraFit::speedMps).
  bool inPlace = false;
  int startCount = 4;                   // view-angle minima tried as starts
  int maxIterations = 300;
  std::string file;                     // named in errors
};

// A real camera's principal point lies near its image's centre (within a few percent); this
// looser SD also lets the fit's camera, whose axis must cross the walking line and which has
// no roll, stand for one that does not quite.
inline constexpr double kPrincipalPointSdShare = 0.25;
// Without the image, the principal point's row is expected within this share of the walker's
// head-to-ankles height of the walker's pelvis at mid-clip (one SD): whoever films a walker
// frames them, and c_y otherwise trades against the tilt in a clip too short for perspective.
inline constexpr double kFramingSdOfHeight = 0.5;
// One SD of the scene's horizon as a prior, in degrees of the camera's view: the reading itself
// is within 0.3° on calibrated cameras, and the fit's camera has no roll.
inline constexpr double kHorizonSdDeg = 1.0;

struct CameraStart {
  double startAlphaDeg = 0.0, alphaDeg = 0.0, elevationDeg = 0.0;
  double objective = 0.0, reprojectionRmsPx = 0.0, speedMmS = 0.0;
  int iterations = 0;
};

// One standard deviation of what the fit measures, from the curvature of its objective at the
// optimum: a Laplace approximation of the MAP posterior, in which the coefficients' prior (which
// holds the walker's size) bounds the scale an unknown camera leaves open. NaN where the fit
// cannot say: least squares (no prior, so no scale), or walking in place for the speed and the
// stride (the speed is then the stance feet's, not a fitted parameter). How often ±1.96 SD
// holds the truth is measured in the widened camera experiment (docs/CAMERA.md, "How sure the
// fit is").
// Given the stature (scaleToStature), the scale is no longer open: the speed's and the stride's
// SDs become those of the posterior conditioned on the stature, and the stature's is zero.
struct FitUncertainty {
  double statureMm = std::numeric_limits<double>::quiet_NaN();
  double speedMps = std::numeric_limits<double>::quiet_NaN();
  double strideLengthM = std::numeric_limits<double>::quiet_NaN();
  // The same two conditioned on the fit's own stature, as shares of the speed and the stride
  // (scaleToStature scales the walk and takes these).
  double speedShareGivenStature = std::numeric_limits<double>::quiet_NaN();
  double strideShareGivenStature = std::numeric_limits<double>::quiet_NaN();
  // The camera: its azimuth and elevation (0 when given), its focal length (pinhole; 0 when
  // given) and the walker's distance from it (pinhole: CameraFit::walkerDistanceM; the share is
  // the distance's SD given the stature, as a share of the distance).
  double alphaDeg = std::numeric_limits<double>::quiet_NaN();
  double elevationDeg = std::numeric_limits<double>::quiet_NaN();
  double focalPx = std::numeric_limits<double>::quiet_NaN();
  double walkerDistanceM = std::numeric_limits<double>::quiet_NaN();
  double walkerDistanceShareGivenStature = std::numeric_limits<double>::quiet_NaN();
};

// The stature's SD from the curvature alone is too narrow for a walker the model has not seen:
// on the widened camera experiment's clip-length and all-hardest levels (8 levels of 72
// held-out clips) its error divided by that SD had an SD of 1.36-1.44, and ±1.96 SD held 86 %
// of the truths. The reported SD is widened by this factor (after it: 0.94-1.10 and 92-93 % on
// every level). The speed's and the stride's need none (0.61-0.94: wide enough).
inline constexpr double kStatureSdWidening = 1.45;

struct CameraFit {
  WalkCamera camera;
  Eigen::VectorXd k, w;           // coefficients and the 3D walker (225, canonical frame)
  double omegaRadS = 0.0, phaseRad = 0.0;
  double objective = 0.0;         // mean squared reprojection error in mm (+ prior)
  double reprojectionRmsPx = 0.0; // over every seen joint sample the fit kept
  int outlierSamples = 0;         // seen samples rejected as detector glitches (far off the fit)
  // The angle below the horizontal at which the camera sees the walker's pelvis, mean over the
  // clip: what the walker's image fixes, where the camera's elevation also rests on where its
  // principal point is (docs/CAMERA.md, "Framing").
  double viewElevationDeg = 0.0;
  // How far the walker's pelvis is from a pinhole camera, mean over the clip, and at the clip's
  // ends (m; NaN for scaled orthography). What a user means by "how far away": the camera's own
  // distance is to its look-at point on the walk's line, which a walk along the line of sight
  // barely fixes.
  double walkerDistanceM = std::numeric_limits<double>::quiet_NaN();
  double walkerDistanceFirstM = std::numeric_limits<double>::quiet_NaN();
  double walkerDistanceLastM = std::numeric_limits<double>::quiet_NaN();
  double headHeightMm = 0.0;      // head centre above the mean of the two ankles, cycle mean
  double statureMm = 0.0;         // the stature that head height implies (core/gait/body_size.h)
  double strideHz = 0.0, speedMps = 0.0, strideLengthM = 0.0, cadenceStepsPerMin = 0.0;
  // Fitted walking in place (CameraFitOptions::inPlace): the camera's speed is zero and
  // speedMps, strideLengthM are the belt's, from the stance feet of the fitted walk (NaN
  // when no full stride of it could be measured).
  bool inPlace = false;
  FitUncertainty sd;                // 1 SD of the measures and the camera
  std::vector<CameraStart> starts;  // every start, best first
  std::vector<int> unseenJoints;    // joints with no image data (estimated by the model)
};

// Walking in place, a level camera and a side or oblique view: the azimuth then rests on the
// body's shape alone, and a walker the model does not hold is drawn as well by a longer stride
// seen more obliquely (docs/TRACKING_DESIGN.md, "On a treadmill": up to 26° off from the true
// joints with the camera level, within 6° from 3 m up). Limits of that study's views.
inline constexpr double kLevelCameraElevationDeg = 10.0;   // below this the feet's depth barely shows
inline constexpr double kEndOnViewDeg = 30.0;              // within this of the front or back: pinned
// A sentence for the report when the fitted azimuth is that weak (the fit estimated it, walking
// in place, the camera within kLevelCameraElevationDeg of level, the view more than
// kEndOnViewDeg from the front and the back); "" otherwise.
std::string inPlaceAzimuthCaution(const CameraFit& fit, bool azimuthGiven);
bool inPlaceAzimuthIsWeak(const CameraFit& fit, bool azimuthGiven);  // the same test, no sentence

// A fitted walk people do not walk, or a lens few cameras have: the camera fit is then likely
// wrong (a track that lost the legs, keypoints of another motion), whatever its residual says.
// The stride against the stature: the default model's 24 real walkers stride 0.61–0.99 times
// their stature at 0.79–1.62 m/s; a very slow walk's is about 0.35 of it, a very fast one's
// about 1.2.
inline constexpr double kMinStrideToStature = 0.35, kMaxStrideToStature = 1.25;
// A horizontal field of view wider than this is a fisheye's, which a pinhole does not model.
inline constexpr double kMaxFieldOfViewDeg = 120.0;
// "" when the stride is within those bounds of the stature (or either is not measured).
std::string implausibleStrideCaution(const CameraFit& fit);
bool strideIsImplausible(const CameraFit& fit);  // the same test, no sentence
// "" when the focal length was given, the image's width is unknown, or the field of view
// it gives the picture is at most kMaxFieldOfViewDeg.
std::string implausibleFocalCaution(const CameraFit& fit, bool focalGiven, std::optional<double> imageWidthPx);

// A fitted principal point this many of its prior's SDs (kPrincipalPointSdShare) from the
// picture's centre (half the picture's longer side; a 16:9 picture's corners are beyond) is a
// tilt the walker's image could not pin down. On the widened camera experiment (2016 fits),
// the fits that put it there were all fitted without the image's size, each 13–27° off in
// azimuth and 0.4 or 2.4–5.5 times the distance; with the size known none went past 0.9 SD.
// The sports2d demo's sound track fit puts it 1.65 SDs off, its unflattened track's 3–4
// (docs/CAMERA.md, "Outputs").
inline constexpr double kPrincipalPointCautionSds = 2.0;
// "" when the image's size is unknown or the fitted principal point lies within
// kPrincipalPointCautionSds of the picture's centre.
std::string principalPointOffThePictureCaution(const CameraFit& fit, std::optional<Eigen::Vector2d> imageSizePx);

// The fitted camera's horizon this far from the scene's (horizonOffDeg, core/camera/walk_camera.h)
// makes the camera's height over the walker unsure: on the widened experiment's clean clips the
// fit reads the angle it sees the walker from within 0.5–1° (median; docs/CAMERA.md).
inline constexpr double kSceneHorizonCautionDeg = 2.0;
// "" for scaled orthography or a fit within kSceneHorizonCautionDeg of the scene's horizon
// (`sceneRowPx`, video/scene_horizon.h); `heldToIt`: the fit had it as a prior, so the walker's
// image itself disagrees.
std::string sceneHorizonCaution(const CameraFit& fit, double sceneRowPx, bool heldToIt);

// What the fit was given, for its cautions.
struct FitGivens {
  bool azimuth = false, focal = false;
  std::optional<Eigen::Vector2d> imageSizePx;  // width, height
};
// Every caution above that applies, in that order: the report's `cautions`.
std::vector<std::string> cameraFitCautions(const CameraFit& fit, const FitGivens& given);

// A 3D walker's head centre above its ankles (the mean of the two), cycle mean, mm: the
// "height" the fit reports, and its truth in the experiment.
double walkerHeadHeightMm(const Eigen::VectorXd& w);

// jointsPx: T × 30 (u, v per joint, METHOD §1 order), NaN = not seen. Throws Error(BadData)
// naming options.file when fewer than 8 frames or no start converges to a walker moving
// forward, Error(BadArgument) for a focal length that is not a camera's (focal_length.h) or a fixed
// azimuth or elevation that is not finite (or an elevation outside −30…80°).
CameraFit reconstructUnknownCamera(const EigenwalkerModel& model, const Eigen::MatrixXd& jointsPx,
                                   double rateHz, const CameraFitOptions& options = {});

}  // namespace ew
