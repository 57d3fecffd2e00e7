#pragma once
// A camera filming an overground walk (docs/CAMERA.md has the equations). The walker is
// the periodic 15-joint motion X(t) of the canonical frame (METHOD §2: x right, y forward,
// z up, mm, progression removed), carried forward along y at `speedMmS`:
//   P(t) = X(t) + (0, y0 + v·t, −h)                  (relative to the look-at point)
// seen from azimuth α (METHOD §5: u = x cos α + y sin α, d = −x sin α + y cos α) by a camera
// tilted down by the elevation ε:
//   X_c = u,   Y_c = −(d sin ε + z cos ε),   Z_c = D + d cos ε − z sin ε
// and imaged in pixels, y down:
//   pinhole (focal f px known):      u_px = c_x + f X_c / Z_c,  v_px = c_y + f Y_c / Z_c
//   scaled orthography (f unknown):  u_px = c_x + s X_c,        v_px = c_y + s Y_c
// At α = 0 the camera looks along the walker's forward direction (it films the back).

#include <Eigen/Core>

#include "core/camera/calibration_file.h"

namespace ew {

enum class CameraModel { Pinhole, ScaledOrthographic };

struct WalkCamera {
  CameraModel model = CameraModel::ScaledOrthographic;
  double alphaDeg = 0.0;      // azimuth, METHOD §5
  double elevationDeg = 0.0;  // camera looking down by this much
  double focalPx = 1000.0;    // pinhole only
  double distanceMm = 5000.0; // pinhole: camera to the look-at point
  double pxPerMm = 0.5;       // orthographic only
  double cxPx = 0.0, cyPx = 0.0;  // where the look-at point is imaged
  double lookAtHeightMm = 0.0;    // h (pinhole; orthography absorbs it in c_y)
  double startOffsetMm = 0.0;     // y0 (pinhole; orthography absorbs it in c_x, c_y)
  double speedMmS = 0.0;          // v, the walker's progression
};

// framesX45: T × 45 canonical frames (periodic, progression removed); timesS: T.
// Returns T × 30 pixel coordinates (u, v per joint, METHOD §1 order). A point at or behind
// the pinhole (Z_c ≤ 1 mm) is NaN.
Eigen::MatrixXd projectWalk(const Eigen::Ref<const Eigen::MatrixXd>& framesX45,
                            const Eigen::Ref<const Eigen::VectorXd>& timesS, const WalkCamera& camera);

// The derivatives of projectWalk's pixels with respect to the frames' joint coordinates:
// du(f, 3j + c) = ∂u_px(f, j) / ∂framesX45(f, 3j + c), dv likewise for v_px; T × 45 each, zero
// where the point is at or behind the pinhole or at infinity. The camera fit's Jacobian takes the
// columns of the walk's own parameters (k, ω, φ, the progression) from these by the chain rule
// instead of projecting once per column.
struct WalkImageGradient {
  Eigen::MatrixXd du, dv;
};
WalkImageGradient projectWalkGradient(const Eigen::Ref<const Eigen::MatrixXd>& framesX45,
                                      const Eigen::Ref<const Eigen::VectorXd>& timesS, const WalkCamera& camera);

// The walk in the camera's frame (x right, y down, z forward; mm): T × 45, X_c, Y_c, Z_c of
// the equations above per joint (Z_c is D + d cos ε − z sin ε for either model).
Eigen::MatrixXd walkInCameraFrame(const Eigen::Ref<const Eigen::MatrixXd>& framesX45,
                                  const Eigen::Ref<const Eigen::VectorXd>& timesS, const WalkCamera& camera);

// The angle below the horizontal at which a camera tilted down by elevationDeg sees the pelvis
// of a walk in its frame (walkInCameraFrame's), mean over the frames (°). A walker's image fixes
// this angle; the camera's tilt is it plus the pelvis's angle above the optical axis, which also
// needs the principal point (docs/CAMERA.md, "Framing").
double viewElevationDeg(const Eigen::Ref<const Eigen::MatrixXd>& inCamera, double elevationDeg);

// The row of a pinhole's horizon (px): where level lines run to, c_y − f tan ε for a camera with
// no roll. NaN for scaled orthography, whose rays are all parallel. Compared with the horizon the
// scene's own lines give (video/scene_horizon.h), it checks the camera's height over the walker.
double horizonRowPx(const WalkCamera& camera);
// How far (degrees, as the camera sees it) the pinhole's horizon lies from a row read off the
// scene: atan((c_y − row) / f) − ε, the angle between level and the ray to that row. Positive
// when the camera's horizon lies below the scene's in the picture (the camera's eye too low
// over the walker). NaN for orthography.
double horizonOffDeg(const WalkCamera& camera, double sceneRowPx);

// A pinhole WalkCamera as a calibration (OpenCV's x_cam = R x_world + t, no distortion,
// `widthPx` × `heightPx`), the world being the walker's canonical frame with its progression
// put back: W(t) = X(t) + (0, y0 + v·t, 0). Then R = E(ε) R₀(α) and t = (0, 0, D) − R (0, 0, h),
// R₀'s rows (cos α, sin α, 0), (0, 0, −1), (−sin α, cos α, 0) (a level camera at azimuth α),
// E(ε) the tilt about the camera's x axis. Throws Error(BadArgument) for a scaled
// orthographic camera (it has no calibration of this kind).
CalibratedCamera calibrationOf(const WalkCamera& camera, double widthPx, double heightPx);

}  // namespace ew
