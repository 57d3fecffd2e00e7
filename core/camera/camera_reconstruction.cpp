#include "core/camera/camera_reconstruction.h"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "core/camera/focal_length.h"
#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/common/statistics.h"
#include "core/eigenwalker/fourier.h"
#include "core/gait/body_size.h"
#include "core/gait/fourier_walker_gait.h"
#include "core/gait/gait_cycles.h"
#include "core/eigenwalker/joint_completion.h"
#include "core/eigenwalker/projection.h"
#include "core/gait/gaps.h"
#include "core/gait/missing_joints.h"
#include "core/keypoints/image_gait.h"

namespace ew {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// Elevations each view-angle start is tried at: the orthographic search cannot see the
// camera's tilt, and a tilted view of a walker coming closer misleads a level start.
constexpr double kStartElevationsDeg[] = {5.0, 25.0};
// An orthographic image cannot tell α from −α (depth reversed), 180° − α (mirror) or
// α + 180° (both); perspective and the direction of walking can, so each is a start.
constexpr double kRelatedOffsetsDeg[] = {0.0, 180.0};
// Every start runs this many iterations; the best few then run to convergence.
constexpr int kScreeningIterations = 12;
constexpr int kRefinedStarts = 5;
// Elevations outside this range are no camera filming a walk: a steep penalty.
constexpr double kMinElevationDeg = -30.0, kMaxElevationDeg = 80.0;
constexpr double kStartDistanceMm = 5000.0;
// Starts closer than this in α are one start (the minima of a profile often come in pairs).
constexpr double kSameStartDeg = 5.0;
constexpr double kScreeningFramesPerStride = 8.0;
constexpr double kMaxRmsOfHeight = 0.10;
// Above this share of the walker's height, the fit looks for a better basin from a grid of
// azimuths (good fits: 1-3 %; 7 % for a 140 px walker at 5 px noise).
constexpr double kRetryRmsOfHeight = 0.08;
// A fit whose stride ends further than this from the image's strikes' (a share) is tried again
// from starts with the stride held at the strikes' (then freed), and the better kept. On the
// camera experiment's clips at 2 px the fit reads the stride within 0.3 % (95th percentile) and
// the strikes within 11 %, but 7 fits of 564 read it a third or more off, in worse basins
// (SM2014019's: 28.4 px reprojection RMS at 1.25 Hz, 6.6 px at 0.92 Hz from the held start);
// with the retry 1 of 564 does (docs/RESULTS.md, issue 55).
constexpr double kStrideDriftFromHint = 0.15;
// A fit striding outside kMinStrideHz–kMaxStrideHz (METHOD §3's ω range) runs backwards in
// time or its legs faster than anyone walks: a wrong basin however well it fits.
// Candidates finished on every frame before the fit gives up on a start list.
constexpr int kFinishedCandidates = 3;
// Detector glitches (a swapped limb, a jump to another person; withoutOutliers) are rejected
// rather than averaged in; two rounds at most. A glitch jumps away from the joint's misses in
// the neighbouring frames; a systematic miss (a detector's neck is not the sternum, a head
// built from face points: up to 60 px at a 10 s clip's ends, drifting smoothly) does not. On
// that clean clip, 4 median misses as the limit alone rejected 5.7 % of the samples.
constexpr double kOutlierFactor = 4.0, kOutlierShareOfHeight = 0.08, kFarShareOfHeight = 0.3;
constexpr Eigen::Index kGlitchWindow = 3;
constexpr double kGlitchShareToRefit = 0.05;
constexpr int kOutlierRounds = 2;

[[noreturn]] void badData(const std::string& file, const std::string& what) {
  throw Error(ErrorKind::BadData, file, "", "camera reconstruction: " + what);
}

// [SECTION] Parameters ----------------------------------------------------------------------

// θ = [k (N), α°, ε°, log scale (orthography: s px/mm; pinhole: D mm), c_x, c_y, v mm/s,
//      ω, φ, (pinhole:) h mm, y0 mm, (focal unknown:) log f px].
struct Layout {
  int n = 0;
  bool pinhole = false;
  bool focalFree = false;  // pinhole whose focal length is estimated
  bool alphaFixed = false, elevationFixed = false;  // held at their start values
  bool omegaFixed = false;                          // held at the stride hint
  bool speedFixed = false;                          // held at zero: walking in place
  int alpha() const { return n; }
  int elevation() const { return n + 1; }
  int logScale() const { return n + 2; }
  int cx() const { return n + 3; }
  int cy() const { return n + 4; }
  int speed() const { return n + 5; }
  int omega() const { return n + 6; }
  int phase() const { return n + 7; }
  int height() const { return n + 8; }
  int offset() const { return n + 9; }
  int logFocal() const { return n + 10; }
  int size() const { return n + (pinhole ? (focalFree ? 11 : 10) : 8); }
  bool fixed(Eigen::Index i) const {
    return (alphaFixed && i == alpha()) || (elevationFixed && i == elevation()) || (omegaFixed && i == omega()) ||
           (speedFixed && i == speed());
  }
};

struct Problem {
  const EigenwalkerModel& model;
  Layout layout;
  double focalPx = 0.0;
  MatrixXd observed;        // T × 30
  VectorXd timesS;
  double mmPerPx = 1.0;     // fixed weighting of the data term (from the start)
  double dataWeight = 1.0;  // 1 / sqrt(seen samples / 2): a mean over joint-frames
  VectorXd priorWeight;     // sqrt(σ² / λ_n) for MAP, empty for LSQ
  std::vector<int> seen;    // indices into observed (column-major) of seen samples
  // The principal point's prior: sqrt(σ²) / SD per pixel off it (zero: none), and where it is.
  double principalPointWeight = 0.0;
  Eigen::Vector2d principalPointPx = Eigen::Vector2d::Zero();
  // Without the image, the framing's prior on c_y (kFramingSdOfHeight): weight and centre.
  double framingWeight = 0.0, framingCyPx = 0.0;
  // The scene's horizon as a prior (CameraFitOptions::horizonRowPx): weight per degree, row.
  double horizonWeight = 0.0, horizonRowPx = 0.0;
};

// Where a camera filming a walker is expected to point when its image is not known: the row of
// the walker's pelvis at mid-clip, with an SD in px (docs/CAMERA.md, "Framing").
struct Framing {
  double cyPx = 0.0, sdPx = 0.0;
};

// The problem on every `stride`-th frame: the seen samples, the data weight and the prior.
Problem makeProblem(const EigenwalkerModel& model, Layout layout, const CameraFitOptions& o, const MatrixXd& px,
                    const VectorXd& times, double mmPerPx, int stride, const Framing& framing) {
  const auto rows = (px.rows() + stride - 1) / stride;
  MatrixXd observed(rows, px.cols());
  VectorXd t(rows);
  for (Eigen::Index i = 0; i < rows; ++i) observed.row(i) = px.row(i * stride), t[i] = times[i * stride];
  Problem p{model, layout, o.focalPx.value_or(0.0), observed, t, mmPerPx, 1.0, {}, {}};
  for (Eigen::Index i = 0; i < observed.size(); ++i)
    if (std::isfinite(observed.data()[i])) p.seen.push_back(static_cast<int>(i));
  p.dataWeight = 1.0 / std::sqrt(std::max(1.0, 0.5 * static_cast<double>(p.seen.size()) / kJointCount));
  if (o.estimator.estimator == Estimator::Map)
    p.priorWeight = (o.estimator.sigma2Mm2 / model.eigenvalues.cwiseMax(1e-12).array()).sqrt().matrix();
  // In the currency of the coefficients' prior: a principal point one SD off costs what a
  // coefficient one SD from the mean does. Orthography has no principal point.
  if (o.imageSizePx && layout.pinhole) {
    p.principalPointWeight = std::sqrt(o.estimator.sigma2Mm2) / (kPrincipalPointSdShare * o.imageSizePx->maxCoeff());
    p.principalPointPx = o.principalPointPx.value_or(0.5 * *o.imageSizePx);
  } else if (layout.pinhole && o.framingPrior && framing.sdPx > 0.0) {
    p.framingWeight = std::sqrt(o.estimator.sigma2Mm2) / framing.sdPx;
    p.framingCyPx = framing.cyPx;
  }
  if (o.horizonRowPx && layout.pinhole) {
    p.horizonWeight = std::sqrt(o.estimator.sigma2Mm2) / kHorizonSdDeg;
    p.horizonRowPx = *o.horizonRowPx;
  }
  return p;
}

WalkCamera cameraOf(const Problem& p, const VectorXd& t) {
  const Layout& l = p.layout;
  WalkCamera c;
  c.model = l.pinhole ? CameraModel::Pinhole : CameraModel::ScaledOrthographic;
  c.alphaDeg = t[l.alpha()];
  c.elevationDeg = t[l.elevation()];
  if (l.pinhole) {
    c.focalPx = l.focalFree ? std::exp(t[l.logFocal()]) : p.focalPx;
    c.distanceMm = std::exp(t[l.logScale()]);
    c.lookAtHeightMm = t[l.height()];
    c.startOffsetMm = t[l.offset()];
  } else {
    c.pxPerMm = std::exp(t[l.logScale()]);
  }
  c.cxPx = t[l.cx()];
  c.cyPx = t[l.cy()];
  c.speedMmS = t[l.speed()];
  return c;
}

VectorXd walkerOf(const Problem& p, const VectorXd& t) {
  return p.model.mean + p.model.eigenwalkers * t.head(p.layout.n);
}

MatrixXd framesOf(const Problem& p, const VectorXd& t) {
  return synthesizeFrames(walkerOf(p, t), t[p.layout.omega()], t[p.layout.phase()], p.timesS);
}

MatrixXd imageOf(const Problem& p, const VectorXd& t) { return projectWalk(framesOf(p, t), p.timesS, cameraOf(p, t)); }

// Data residuals in mm (pixels × mmPerPx, weighted to a mean) of the walker's frames seen
// by the camera of θ, then the priors' and the elevation bound's.
VectorXd residualsOfFrames(const Problem& p, const MatrixXd& frames, const VectorXd& t) {
  const WalkCamera camera = cameraOf(p, t);
  const MatrixXd image = projectWalk(frames, p.timesS, camera);
  VectorXd r(static_cast<Eigen::Index>(p.seen.size()) + p.priorWeight.size() + 5);
  for (std::size_t i = 0; i < p.seen.size(); ++i) {
    const double d = image.data()[p.seen[i]] - p.observed.data()[p.seen[i]];
    // A point behind a pinhole camera: a large, smooth penalty rather than NaN.
    r[static_cast<Eigen::Index>(i)] = std::isfinite(d) ? p.dataWeight * p.mmPerPx * d : 1e6;
  }
  if (p.priorWeight.size() > 0)
    r.segment(static_cast<Eigen::Index>(p.seen.size()), p.priorWeight.size()) =
        p.priorWeight.cwiseProduct(t.head(p.layout.n));
  const Eigen::Vector2d c(t[p.layout.cx()], t[p.layout.cy()]);
  r.segment<2>(r.size() - 5) = p.principalPointWeight * (c - p.principalPointPx);
  r[r.size() - 3] = p.framingWeight * (c.y() - p.framingCyPx);
  r[r.size() - 2] = p.horizonWeight > 0.0 ? p.horizonWeight * horizonOffDeg(camera, p.horizonRowPx) : 0.0;
  const double e = t[p.layout.elevation()];
  r[r.size() - 1] = 1e3 * (std::max(0.0, e - kMaxElevationDeg) + std::max(0.0, kMinElevationDeg - e));
  return r;
}

VectorXd residuals(const Problem& p, const VectorXd& t) { return residualsOfFrames(p, framesOf(p, t), t); }

// [SECTION] Levenberg-Marquardt ---------------------------------------------------------------

VectorXd stepSizes(const Problem& p, const VectorXd& t) {
  VectorXd h = (t.cwiseAbs().array() * 1e-6 + 1e-6).matrix();
  h.head(p.layout.n) = (p.model.eigenvalues.cwiseMax(1.0).cwiseSqrt() * 1e-5);
  h[p.layout.alpha()] = h[p.layout.elevation()] = 1e-5;
  h[p.layout.logScale()] = 1e-7;
  if (p.layout.focalFree) h[p.layout.logFocal()] = 1e-7;
  h[p.layout.phase()] = 1e-6;
  h[p.layout.omega()] = 1e-7;
  return h;
}

// The residuals' derivative, into `col`, for a move `dFrames` (T × 45, per unit of a parameter)
// of the walk's frames before the camera sees them: each seen pixel moves by the projection's
// gradient (the other rows do not move). `image` is scratch space shaped as p.observed.
void framesMoveColumn(const Problem& p, const WalkImageGradient& g, const MatrixXd& dFrames, MatrixXd& image,
                      Eigen::Ref<VectorXd> col) {
  for (int j = 0; j < kJointCount; ++j) {
    image.col(2 * j) = (g.du.middleCols<3>(3 * j).array() * dFrames.middleCols<3>(3 * j).array()).rowwise().sum();
    image.col(2 * j + 1) = (g.dv.middleCols<3>(3 * j).array() * dFrames.middleCols<3>(3 * j).array()).rowwise().sum();
  }
  col.setZero();
  const double weight = p.dataWeight * p.mmPerPx;
  for (std::size_t s = 0; s < p.seen.size(); ++s) col[static_cast<Eigen::Index>(s)] = weight * image.data()[p.seen[s]];
}

// What framesMove needs to say how a parameter that is not the camera's moves the frames the
// camera sees: the coefficients and the walk's timing move them through the Fourier synthesis,
// the progression and the look-at point through walkInCameraFrame's (x, y + y0 + v·t, z − h).
struct FramesMoves {
  MatrixXd basis, phaseBasis, walkerBlocks;  // fourierBasis, its φ derivative, w as 45 × 5
};

// The frames' move for parameter i (T × 45) into `out`; false for a parameter of the camera.
bool framesMove(const Problem& p, const FramesMoves& m, Eigen::Index i, MatrixXd& out) {
  const Layout& l = p.layout;
  if (i < l.n) {
    const Eigen::Map<const MatrixXd> blocks(p.model.eigenwalkers.col(i).data(), out.cols(), kFourierBlocks);
    out.noalias() = m.basis * blocks.transpose();
  } else if (i == l.phase() || i == l.omega()) {
    out.noalias() = m.phaseBasis * m.walkerBlocks.transpose();
    if (i == l.omega()) out = p.timesS.asDiagonal() * out;
  } else if (i == l.speed() || (l.pinhole && (i == l.offset() || i == l.height()))) {
    out.setZero();
    for (int j = 0; j < kJointCount; ++j) {
      if (i == l.height()) out.col(3 * j + 2).setConstant(-1.0);
      else if (i == l.offset()) out.col(3 * j + 1).setOnes();
      else out.col(3 * j + 1) = p.timesS;
    }
  } else {
    return false;
  }
  return true;
}

// Every parameter that moves the walk's frames by the chain rule (above; exact, and a
// projection's work for all of them): the coefficients (whose prior rows move by their
// weights), ω, φ, the speed and the look-at point. Forward differences for the camera's own
// (the steps are small enough for Levenberg-Marquardt, and each saves a projection); they
// reproject the same frames.
MatrixXd jacobian(const Problem& p, const VectorXd& t, const VectorXd& r0) {
  const VectorXd h = stepSizes(p, t);
  const VectorXd w = walkerOf(p, t);
  const double omega = t[p.layout.omega()], phase = t[p.layout.phase()];
  const MatrixXd frames = synthesizeFrames(w, omega, phase, p.timesS);
  const WalkImageGradient gradient = projectWalkGradient(frames, p.timesS, cameraOf(p, t));
  const FramesMoves moves{fourierBasis(omega, phase, p.timesS), fourierBasisPhaseDerivative(omega, phase, p.timesS),
                          Eigen::Map<const MatrixXd>(w.data(), frames.cols(), kFourierBlocks)};
  MatrixXd moved(frames.rows(), frames.cols()), image(p.observed.rows(), p.observed.cols());
  MatrixXd jac(r0.size(), t.size());
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    if (p.layout.fixed(i)) {
      jac.col(i).setZero();
    } else if (framesMove(p, moves, i, moved)) {
      framesMoveColumn(p, gradient, moved, image, jac.col(i));
      if (i < p.layout.n && p.priorWeight.size() > 0)
        jac(static_cast<Eigen::Index>(p.seen.size()) + i, i) = p.priorWeight[i];
    } else {
      VectorXd tp = t;
      tp[i] += h[i];
      jac.col(i) = (residualsOfFrames(p, frames, tp) - r0) / h[i];
    }
  }
  return jac;
}

struct LmResult {
  VectorXd theta;
  double cost = 0.0;
  int iterations = 0;
};

LmResult levenbergMarquardt(const Problem& p, VectorXd t, int maxIterations) {
  VectorXd r = residuals(p, t);
  double cost = r.squaredNorm(), mu = 1e-3;
  int it = 0;
  for (; it < maxIterations; ++it) {
    const MatrixXd jac = jacobian(p, t, r);
    MatrixXd jtj = MatrixXd::Zero(t.size(), t.size());
    jtj.selfadjointView<Eigen::Lower>().rankUpdate(jac.transpose());
    jtj.triangularView<Eigen::StrictlyUpper>() = jtj.transpose();
    // A fixed parameter's column is zero: a unit pivot keeps its step at zero.
    for (Eigen::Index i = 0; i < t.size(); ++i)
      if (p.layout.fixed(i)) jtj(i, i) = 1.0;
    const VectorXd g = jac.transpose() * r;
    bool improved = false;
    for (int tries = 0; tries < 12 && !improved; ++tries) {
      MatrixXd a = jtj;
      a.diagonal() += mu * jtj.diagonal().cwiseMax(1e-12);
      const VectorXd step = a.ldlt().solve(-g);
      const VectorXd tNew = t + step;
      const VectorXd rNew = residuals(p, tNew);
      const double costNew = rNew.squaredNorm();
      if (std::isfinite(costNew) && costNew < cost) {
        const double gain = (cost - costNew) / std::max(cost, 1e-300);
        t = tNew, r = rNew, cost = costNew, mu = std::max(mu / 3.0, 1e-12);
        improved = true;
        if (gain < 1e-13 || step.norm() < 1e-12 * (1.0 + t.norm())) return {t, cost, it + 1};
      } else {
        mu *= 4.0;
      }
    }
    if (!improved) break;
  }
  return {t, cost, it};
}

}  // namespace

bool inPlaceAzimuthIsWeak(const CameraFit& fit, bool azimuthGiven) {
  const double fromEnd = std::min(std::abs(wrapDeg(fit.camera.alphaDeg)), 180.0 - std::abs(wrapDeg(fit.camera.alphaDeg)));
  return !azimuthGiven && fit.inPlace && std::abs(fit.camera.elevationDeg) < kLevelCameraElevationDeg &&
         fromEnd > kEndOnViewDeg;
}

std::string inPlaceAzimuthCaution(const CameraFit& fit, bool azimuthGiven) {
  if (!inPlaceAzimuthIsWeak(fit, azimuthGiven)) return "";
  char text[320];
  std::snprintf(text, sizeof text,
                "walking in place, seen from the side or obliquely by a level camera (elevation %.1f°): the azimuth "
                "rests on the body's shape alone and may be tens of degrees off; a camera looking down on the "
                "walker, or a given azimuth, pins it",
                fit.camera.elevationDeg);
  return text;
}

bool strideIsImplausible(const CameraFit& fit) {
  const double statureM = fit.statureMm / 1000.0;
  if (!(std::isfinite(fit.strideLengthM) && statureM > 0.0)) return false;
  const double ratio = fit.strideLengthM / statureM;
  return ratio < kMinStrideToStature || ratio > kMaxStrideToStature;
}

std::string implausibleStrideCaution(const CameraFit& fit) {
  if (!strideIsImplausible(fit)) return "";
  const double statureM = fit.statureMm / 1000.0;
  const double ratio = fit.strideLengthM / statureM;
  char text[320];
  std::snprintf(text, sizeof text,
                "the fitted walk strides %.2f m for a stature of %.2f m (%.2f times it), where people walk at "
                "%.2f–%.2f times their stature: the camera fit is likely wrong (keypoints or a track that lost the "
                "legs, or not a walk)",
                fit.strideLengthM, statureM, ratio, kMinStrideToStature, kMaxStrideToStature);
  return text;
}

std::string implausibleFocalCaution(const CameraFit& fit, bool focalGiven, std::optional<double> imageWidthPx) {
  if (focalGiven || !imageWidthPx || fit.camera.model != CameraModel::Pinhole || !(fit.camera.focalPx > 0.0))
    return "";
  const double fovDeg = 2.0 * std::atan(0.5 * *imageWidthPx / fit.camera.focalPx) * 180.0 / std::numbers::pi;
  if (fovDeg <= kMaxFieldOfViewDeg) return "";
  char text[320];
  std::snprintf(text, sizeof text,
                "the estimated focal length, %.0f px, gives the %.0f px wide picture a %.0f° field of view, wider than "
                "any lens but a fisheye: the camera fit is likely wrong (give the focal length, or a calibration)",
                fit.camera.focalPx, *imageWidthPx, fovDeg);
  return text;
}

std::string principalPointOffThePictureCaution(const CameraFit& fit, std::optional<Eigen::Vector2d> imageSizePx) {
  if (!imageSizePx || fit.camera.model != CameraModel::Pinhole) return "";
  const double w = imageSizePx->x(), h = imageSizePx->y(), cx = fit.camera.cxPx, cy = fit.camera.cyPx;
  const double offPx = std::hypot(cx - 0.5 * w, cy - 0.5 * h);
  const double limitPx = kPrincipalPointCautionSds * kPrincipalPointSdShare * std::max(w, h);
  if (!(w > 0.0 && h > 0.0 && std::isfinite(offPx)) || offPx <= limitPx) return "";  // nothing to measure
  char text[400];
  std::snprintf(text, sizeof text,
                "the fitted camera's principal point, (%.0f, %.0f) px, lies %.0f px from the %.0fx%.0f px picture's "
                "centre, where a camera's lies near it: its tilt (the elevation, %.1f°) is likely wrong, and with it "
                "the walker's depth (a track that lost the legs, or keypoints of another motion)",
                cx, cy, offPx, w, h, fit.camera.elevationDeg);
  return text;
}

std::string sceneHorizonCaution(const CameraFit& fit, double sceneRowPx, bool heldToIt) {
  if (fit.camera.model != CameraModel::Pinhole) return "";
  const double offDeg = horizonOffDeg(fit.camera, sceneRowPx);
  if (!(std::abs(offDeg) > kSceneHorizonCautionDeg)) return "";
  char text[480];
  std::snprintf(text, sizeof text,
                "the scene's level lines put the horizon at row %.0f px, the fitted camera at row %.0f px: the camera's "
                "height over the walker, and so its elevation, are %.1f deg off the scene's%s (docs/CAMERA.md, \"The "
                "scene's horizon\")",
                sceneRowPx, horizonRowPx(fit.camera), std::abs(offDeg),
                heldToIt ? " although the fit was held to it: the walker's image disagrees (lines that are not level, a "
                           "ramp or stairs, or joints the detector misplaced)"
                         : "");
  return text;
}

std::vector<std::string> cameraFitCautions(const CameraFit& fit, const FitGivens& given) {
  std::vector<std::string> out;
  const std::optional<double> imageWidthPx =
      given.imageSizePx ? std::optional<double>(given.imageSizePx->x()) : std::nullopt;
  for (std::string c : {inPlaceAzimuthCaution(fit, given.azimuth), implausibleStrideCaution(fit),
                        implausibleFocalCaution(fit, given.focal, imageWidthPx),
                        principalPointOffThePictureCaution(fit, given.imageSizePx)})
    if (!c.empty()) out.push_back(std::move(c));
  return out;
}

double walkerHeadHeightMm(const VectorXd& w) {
  const MatrixXd f = synthesizeFrames(w, 2 * std::numbers::pi, 0.0, frameTimes(50, 50.0));
  const VectorXd ankles = 0.5 * (f.col(3 * index(Joint::LAnkle) + 2) + f.col(3 * index(Joint::RAnkle) + 2));
  return (f.col(3 * index(Joint::Head) + 2) - ankles).mean();
}

namespace {

// [SECTION] Start: the orthographic view-angle search --------------------------------------------

// How the walker's image grows or shrinks and moves along the clip. A pinhole images a walker
// at depth Z(t) at a size ∝ 1/Z(t), and a straight walk at a steady speed has Z linear in t: a
// line through the inverse heights, and the pelvis at (a + b t) / Z(t) — a walker leaving the
// camera from a metre to ten shrinks tenfold, which a line through the heights cannot follow
// (it crossed zero, and the start's walk was noise). Where that line would not stay positive
// over the clip (heights too noisy to tell), the heights and the pelvis get straight lines.
struct ImageTrend {
  Eigen::Vector2d depth{0.0, 0.0};  // 1 / height px, as p0 + p1 t; zero: the linear fallback
  Eigen::Vector2d height{0.0, 0.0}, pelvisU{0.0, 0.0}, pelvisV{0.0, 0.0};  // numerators, or lines

  bool perspective() const { return depth[0] != 0.0 || depth[1] != 0.0; }
  double heightPxAt(double t) const {
    return perspective() ? 1.0 / (depth[0] + depth[1] * t) : std::max(height[0] + height[1] * t, 1e-6);
  }
  Eigen::Vector2d pelvisPxAt(double t) const {
    const double d = perspective() ? depth[0] + depth[1] * t : 1.0;
    return {(pelvisU[0] + pelvisU[1] * t) / d, (pelvisV[0] + pelvisV[1] * t) / d};
  }
};

ImageTrend imageTrendOf(const MatrixXd& px, const VectorXd& times) {
  ImageTrend trend;
  VectorXd u = px.col(2 * index(Joint::Pelvis)), v = px.col(2 * index(Joint::Pelvis) + 1);
  if (const std::optional<Eigen::Vector2d> depth = imageDepthLine(px, times)) {
    trend.depth = *depth;
    for (Eigen::Index f = 0; f < u.size(); ++f) {
      const double d = trend.depth[0] + trend.depth[1] * times[f];
      u[f] *= d;
      v[f] *= d;
    }
  } else {
    trend.height = lineThroughFinite(imageHeightsPx(px), times);
  }
  trend.pelvisU = lineThroughFinite(u, times);
  trend.pelvisV = lineThroughFinite(v, times);
  return trend;
}

struct OrthoStart {
  FourierFit fit;
  ModelGram gram;                    // the model with the unseen joints dropped
  ViewSearch search;
  double pxPerMm = 0.0;              // at mid-clip
  Eigen::Vector2d pelvisU, pelvisV;  // a + b t of the pelvis in the image
};

OrthoStart orthographicStart(const EigenwalkerModel& model, const MatrixXd& px, const VectorXd& times,
                             const JointMask& unseen, const CameraFitOptions& o) {
  OrthoStart s;
  // The walker's image size along the clip and its progression (the pelvis's track) are taken
  // out, leaving a near-orthographic view of the walk in model millimetres.
  const double modelHeight = walkerHeadHeightMm(model.mean);
  const ImageTrend trend = imageTrendOf(px, times);
  const double midT = 0.5 * (times[0] + times[times.size() - 1]);
  s.pxPerMm = trend.heightPxAt(midT) / modelHeight;
  if (!(s.pxPerMm > 0) || !std::isfinite(s.pxPerMm))
    badData(o.file, "the walker's head-to-ankle height in the image cannot be measured");
  s.pelvisU = lineThroughFinite(px.col(2 * index(Joint::Pelvis)), times);
  s.pelvisV = lineThroughFinite(px.col(2 * index(Joint::Pelvis) + 1), times);
  MatrixXd mm(px.rows(), px.cols());
  for (Eigen::Index f = 0; f < px.rows(); ++f) {
    const double scale = trend.heightPxAt(times[f]) / modelHeight;
    const Eigen::Vector2d pelvis = trend.pelvisPxAt(times[f]);
    for (int j = 0; j < kJointCount; ++j) {
      mm(f, 2 * j) = (px(f, 2 * j) - pelvis.x()) / scale;
      mm(f, 2 * j + 1) = -(px(f, 2 * j + 1) - pelvis.y()) / scale;
    }
  }
  // Every sample filled for the start's Fourier fit (it drops any frame with a gap).
  MatrixXd seen = mm;
  for (Eigen::Index c = 0; c < seen.cols(); ++c) fillAllGapsLinearly(seen.col(c));
  for (int j = 0; j < kJointCount; ++j) {
    if (unseen[static_cast<std::size_t>(j)]) seen.middleCols<2>(2 * j).setConstant(kNaN);
  }
  FourierFitOptions f;
  // The image's foot strikes fix the start's frequency: the detrended image keeps slow
  // drifts (perspective, sway) that a scan could take for the gait.
  // A clip of a stride and a bit whose strikes read it under one cycle starts from one cycle
  // over the clip (the Fourier fit needs one; the refinement frees ω).
  const double rate = 1.0 / (times[1] - times[0]);
  const double oneCycleHz = rate / static_cast<double>(std::max<Eigen::Index>(px.rows() - 1, 1));
  if (o.strideHzHint) f.omegaFixedRadS = 2 * std::numbers::pi * std::max(*o.strideHzHint, oneCycleHz);
  f.file = o.file;
  s.fit = fitFourierMeasured(seen, rate, unseen, f);
  std::vector<int> missing;
  for (int j = 0; j < kJointCount; ++j)
    if (unseen[static_cast<std::size_t>(j)]) missing.push_back(j);
  s.gram = precomputeModelGram(model, missing);
  s.search = searchViewAngle(s.gram, s.fit.w, o.estimator);
  return s;
}

// θ from a view-angle minimum: the walker at α, elevation 0, its image scale, and the
// pelvis line of the image (c_x, c_y and v).
VectorXd startTheta(const Problem& p, const OrthoStart& s, const Reconstruction& rec, double elevationDeg) {
  const Layout& l = p.layout;
  VectorXd t = VectorXd::Zero(l.size());
  t.head(l.n) = rec.k;
  t[l.alpha()] = rec.alphaDeg;
  t[l.elevation()] = elevationDeg;
  t[l.omega()] = s.fit.omegaRadS;
  t[l.phase()] = s.fit.phaseRad;
  const double sinA = std::sin(degToRad(rec.alphaDeg));
  // The pelvis moves across the image at s·v·sin α px/s; a walker seen from ahead or
  // behind barely moves across it, so its speed starts at a usual 1.3 m/s.
  const double speed = l.speedFixed            ? 0.0
                       : std::abs(sinA) > 0.3 ? s.pelvisU[1] / (s.pxPerMm * sinA)
                                              : 1300.0;
  t[l.speed()] = speed;
  const VectorXd w = walkerOf(p, t);
  const double pelvisZ = w[3 * index(Joint::Pelvis) + 2];
  const double midT = 0.5 * (p.timesS[0] + p.timesS[p.timesS.size() - 1]);
  if (l.pinhole) {
    // An unknown focal length starts as the one that puts the walker kStartDistanceMm away.
    const double focal = l.focalFree ? s.pxPerMm * kStartDistanceMm : p.focalPx;
    if (l.focalFree) t[l.logFocal()] = std::log(focal);
    t[l.logScale()] = std::log(focal / s.pxPerMm);
    t[l.height()] = pelvisZ;
    t[l.offset()] = -speed * midT;  // the walker passes the look-at point mid-clip
    t[l.cx()] = s.pelvisU[0] + s.pelvisU[1] * midT;
    t[l.cy()] = s.pelvisV[0] + s.pelvisV[1] * midT;
  } else {
    t[l.logScale()] = std::log(s.pxPerMm);
    t[l.cx()] = s.pelvisU[0];
    t[l.cy()] = s.pelvisV[0] + s.pxPerMm * pelvisZ;
  }
  return t;
}

// The pelvis's distance from the camera in each frame of a walk in the camera's frame, mm.
VectorXd pelvisDistancesMm(const MatrixXd& inCamera) {
  return inCamera.middleCols<3>(3 * index(Joint::Pelvis)).rowwise().norm();
}

void fillOutputs(const Problem& p, const VectorXd& t, CameraFit& fit) {
  fit.camera = cameraOf(p, t);
  fit.k = t.head(p.layout.n);
  fit.w = walkerOf(p, t);
  fit.omegaRadS = t[p.layout.omega()];
  fit.phaseRad = t[p.layout.phase()];
  const MatrixXd frames = framesOf(p, t);
  const MatrixXd image = projectWalk(frames, p.timesS, fit.camera);
  double sq = 0.0;
  for (int i : p.seen) sq += std::pow(image.data()[i] - p.observed.data()[i], 2);
  fit.reprojectionRmsPx = std::sqrt(sq / static_cast<double>(p.seen.size()));
  const MatrixXd inCamera = walkInCameraFrame(frames, p.timesS, fit.camera);
  fit.viewElevationDeg = viewElevationDeg(inCamera, fit.camera.elevationDeg);
  if (p.layout.pinhole) {
    const VectorXd pelvis = pelvisDistancesMm(inCamera);
    fit.walkerDistanceM = pelvis.mean() / 1000.0;
    fit.walkerDistanceFirstM = pelvis[0] / 1000.0;
    fit.walkerDistanceLastM = pelvis[pelvis.size() - 1] / 1000.0;
  }
  fit.headHeightMm = walkerHeadHeightMm(fit.w);
  fit.statureMm = statureFromHeadAboveAnklesMm(fit.headHeightMm);
  fit.strideHz = fit.omegaRadS / (2 * std::numbers::pi);
  fit.speedMps = fit.camera.speedMmS / 1000.0;
  fit.strideLengthM = fit.strideHz > 0 ? fit.speedMps / fit.strideHz : 0.0;
  fit.cadenceStepsPerMin = 120.0 * fit.strideHz;
}

// The azimuths the fit starts from: the given one, or each of the orthographic search's best
// minima with its depth-reversed, turned-around and mirrored readings.
std::vector<double> startAngles(const ViewSearch& search, const CameraFitOptions& o) {
  if (o.alphaDeg) return {*o.alphaDeg};
  std::vector<double> angles;
  const int minima = std::min<int>(o.startCount, static_cast<int>(search.minima.size()));
  for (int m = 0; m < minima; ++m) {
    const double found = search.minima[static_cast<std::size_t>(m)].alphaDeg;
    for (double alpha : {found, -found}) {
      for (double offset : kRelatedOffsetsDeg) {
        const double a = wrapDeg(alpha + offset);
        const bool tried = std::any_of(angles.begin(), angles.end(),
                                       [&](double b) { return std::abs(wrapDeg(a - b)) < kSameStartDeg; });
        if (!tried) angles.push_back(a);
      }
    }
  }
  return angles;
}

void checkOptions(const CameraFitOptions& o) {
  if (o.focalPx && !isPlausibleFocalPx(*o.focalPx))
    throw Error(ErrorKind::BadArgument, o.file, "--focal-px", focalLengthProblem(*o.focalPx));
  if (o.imageSizePx && !(o.imageSizePx->allFinite() && o.imageSizePx->minCoeff() > 0))
    throw Error(ErrorKind::BadArgument, o.file, "image size", "the image's width and height must be positive");
  if (o.principalPointPx && !o.principalPointPx->allFinite())
    throw Error(ErrorKind::BadArgument, o.file, "principal point", "the principal point must be finite");
  if (o.alphaDeg && !std::isfinite(*o.alphaDeg))
    throw Error(ErrorKind::BadArgument, o.file, "azimuth", "a fixed azimuth must be finite");
  if (o.horizonRowPx && !std::isfinite(*o.horizonRowPx))
    throw Error(ErrorKind::BadArgument, o.file, "horizon", "the scene's horizon must be a finite row");
  if (o.elevationDeg && !(*o.elevationDeg >= kMinElevationDeg && *o.elevationDeg <= kMaxElevationDeg))
    throw Error(ErrorKind::BadArgument, o.file, "elevation",
                "a fixed elevation must lie between " + std::to_string(static_cast<int>(kMinElevationDeg)) + " and " +
                    std::to_string(static_cast<int>(kMaxElevationDeg)) + " degrees");
}

}  // namespace

namespace {

using Candidate = std::pair<VectorXd, CameraStart>;

// A walker moving forward (or walking in place) at a stride frequency people walk at.
bool plausibleWalk(const Problem& p, const VectorXd& theta) {
  const double strideHz = theta[p.layout.omega()] / (2 * std::numbers::pi);
  return (p.layout.speedFixed || theta[p.layout.speed()] > 0) && strideHz >= kMinStrideHz && strideHz <= kMaxStrideHz;
}

// Every start (azimuth × elevation) screened for a few iterations on the coarse frames, the
// best few refined there; sorted with walkers moving forward first (a walker walking
// backwards is the reflected reading of the image), then by cost.
std::vector<Candidate> tryStarts(const Problem& p, const Problem& coarse, const OrthoStart& start,
                                 const std::vector<double>& angles, const std::vector<double>& elevations,
                                 const CameraFitOptions& o) {
  std::vector<std::pair<LmResult, double>> screened;  // (short run, start α)
  for (double a : angles) {
    const Reconstruction rec = reconstructKnownView(start.gram, start.fit.w, a, o.estimator);
    for (double elevation : elevations)
      screened.emplace_back(levenbergMarquardt(coarse, startTheta(coarse, start, rec, elevation), kScreeningIterations),
                            rec.alphaDeg);
  }
  std::stable_sort(screened.begin(), screened.end(),
                   [](const auto& a, const auto& b) { return a.first.cost < b.first.cost; });
  std::vector<Candidate> results;
  for (std::size_t i = 0; i < screened.size(); ++i) {
    const bool refine = static_cast<int>(i) < kRefinedStarts;
    const LmResult lm = refine ? levenbergMarquardt(coarse, screened[i].first.theta, o.maxIterations) : screened[i].first;
    CameraFit trial;
    fillOutputs(p, lm.theta, trial);
    results.emplace_back(lm.theta, CameraStart{screened[i].second, wrapDeg(trial.camera.alphaDeg),
                                               trial.camera.elevationDeg, lm.cost, trial.reprojectionRmsPx,
                                               trial.camera.speedMmS, lm.iterations + (refine ? kScreeningIterations : 0)});
  }
  std::stable_sort(results.begin(), results.end(), [&p](const auto& a, const auto& b) {
    const bool fa = plausibleWalk(p, a.first), fb = plausibleWalk(p, b.first);
    return fa != fb ? fa : a.second.objective < b.second.objective;
  });
  return results;
}

// The best candidate (a forward walker) finished on every frame, in place; false if none.
bool finishBest(const Problem& p, std::vector<Candidate>& results, const CameraFitOptions& o, CameraFit& fit) {
  const int tries = std::min(static_cast<int>(results.size()), kFinishedCandidates);
  for (int i = 0; i < tries; ++i) {
    Candidate& c = results[static_cast<std::size_t>(i)];
    if (!plausibleWalk(p, c.first)) return false;  // sorted: the plausible ones come first
    const LmResult best = levenbergMarquardt(p, c.first, o.maxIterations);
    c.first = best.theta;
    c.second.objective = best.cost;
    c.second.iterations += best.iterations;
    if (!plausibleWalk(p, best.theta)) continue;
    fillOutputs(p, best.theta, fit);
    c.second.reprojectionRmsPx = fit.reprojectionRmsPx;
    c.second.alphaDeg = wrapDeg(fit.camera.alphaDeg);
    c.second.elevationDeg = fit.camera.elevationDeg;
    c.second.speedMmS = fit.camera.speedMmS;
    std::rotate(results.begin(), results.begin() + i, results.begin() + i + 1);  // the finished fit first
    return true;
  }
  return false;
}

// `px` with the detector's glitches set to NaN; `rejected` counts them. A glitch jumps: its
// miss (reprojection − input) departs from the same joint's misses in the frames around it
// (median of ±kGlitchWindow frames) by kOutlierFactor times the joint's median departure and
// by kOutlierShareOfHeight of the walker's height; or it misses by far
// (kFarShareOfHeight), however long it lasts.
struct Glitches {
  MatrixXd kept;              // the input without them
  int count = 0;
  double shareOfSquares = 0;  // their share of the fit's summed squared miss
};

Glitches withoutOutliers(const MatrixXd& px, const MatrixXd& image, double heightPx) {
  Glitches out{px, 0, 0.0};
  double all = 0.0, glitches = 0.0;
  const Eigen::Index frames = px.rows();
  for (int j = 0; j < kJointCount; ++j) {
    MatrixXd miss(frames, 2);
    miss.col(0) = image.col(2 * j) - px.col(2 * j);
    miss.col(1) = image.col(2 * j + 1) - px.col(2 * j + 1);
    VectorXd jump = VectorXd::Constant(frames, kNaN);
    std::vector<double> jumps;
    for (Eigen::Index f = 0; f < frames; ++f) {
      if (!std::isfinite(miss(f, 0)) || !std::isfinite(miss(f, 1))) continue;
      std::vector<double> u, v;
      for (Eigen::Index g = std::max<Eigen::Index>(0, f - kGlitchWindow); g <= std::min(frames - 1, f + kGlitchWindow); ++g) {
        if (g == f || !std::isfinite(miss(g, 0)) || !std::isfinite(miss(g, 1))) continue;
        u.push_back(miss(g, 0));
        v.push_back(miss(g, 1));
      }
      if (u.size() < 2) continue;
      jump[f] = std::hypot(miss(f, 0) - median(u), miss(f, 1) - median(v));
      jumps.push_back(jump[f]);
    }
    if (jumps.size() < 8) continue;
    const double jumpLimit = std::max(kOutlierFactor * median(jumps), kOutlierShareOfHeight * heightPx);
    for (Eigen::Index f = 0; f < frames; ++f) {
      const double far = std::hypot(miss(f, 0), miss(f, 1));
      if (!std::isfinite(far)) continue;
      all += far * far;
      const bool glitch = (std::isfinite(jump[f]) && jump[f] > jumpLimit) || far > kFarShareOfHeight * heightPx;
      if (!glitch) continue;
      glitches += far * far;
      out.kept(f, 2 * j) = out.kept(f, 2 * j + 1) = kNaN;
      ++out.count;
    }
  }
  out.shareOfSquares = all > 0.0 ? glitches / all : 0.0;
  return out;
}

// Walking in place: the speed the belt carries the stance feet back at, read off the fitted
// walk as a gait report reads a reconstruction's (core/gait/fourier_walker_gait.h).
void setBeltSpeed(CameraFit& fit) {
  fit.inPlace = true;
  const FourierWalkerGait g = measureFourierWalker(fit.w, fit.strideHz, std::nullopt, "walking in place");
  fit.speedMps = g.measures ? g.measures->speedMps : kNaN;
  fit.strideLengthM = g.measures ? g.measures->strideLengthM : kNaN;
}

// Azimuths every 30°: the wide net cast when the view-angle search's minima lead nowhere.
std::vector<double> gridAngles() {
  std::vector<double> a;
  for (int d = -165; d < 180; d += 30) a.push_back(d);
  return a;
}

}  // namespace


namespace {

// The starts again with the stride held at the image's strikes, the best finished on every
// frame, then freed (the full problem `p`): for a fit whose stride drifted from the strikes'
// (kStrideDriftFromHint) into another basin. Its candidate and fit, or nothing when no held
// start finishes as a walk.
std::optional<Candidate> startsAtTheHintedStride(const EigenwalkerModel& model, Layout layout,
                                                 const CameraFitOptions& o, const MatrixXd& jointsPx,
                                                 const VectorXd& times, const OrthoStart& start, const Framing& framing,
                                                 int stride, const std::vector<double>& elevations, const Problem& p,
                                                 CameraFit& fit) {
  layout.omegaFixed = true;
  const Problem held = makeProblem(model, layout, o, jointsPx, times, 1.0 / start.pxPerMm, 1, framing);
  const Problem coarse = makeProblem(model, layout, o, jointsPx, times, 1.0 / start.pxPerMm, stride, framing);
  std::vector<double> angles = startAngles(start.search, o);
  for (double a : gridAngles()) angles.push_back(a);
  std::vector<Candidate> results = tryStarts(held, coarse, start, angles, elevations, o);
  CameraFit heldFit;
  if (!finishBest(held, results, o, heldFit)) return std::nullopt;
  const LmResult freed = levenbergMarquardt(p, results.front().first, o.maxIterations);
  if (!plausibleWalk(p, freed.theta)) return std::nullopt;
  Candidate c = results.front();
  c.first = freed.theta;
  c.second.objective = freed.cost;
  c.second.iterations += freed.iterations;
  fillOutputs(p, freed.theta, fit);
  c.second.reprojectionRmsPx = fit.reprojectionRmsPx;
  c.second.alphaDeg = wrapDeg(fit.camera.alphaDeg);
  return c;
}

// [SECTION] How sure the fit is ------------------------------------------------------------------

// The objective is Σ r² = w² Σ d² + σ² Σ k²/λ (d the reprojection misses in mm, w the data
// weight), which is 2σ² times the negative log of a posterior with the coefficients' prior; its
// Gauss-Newton Hessian JᵀJ / σ² gives the Laplace covariance σ² (JᵀJ)⁻¹ over the free
// parameters, and a measure m(θ) gets the SD sqrt(gᵀ Σ g), g = ∂m/∂θ.
std::optional<MatrixXd> laplaceCovariance(const Problem& p, const VectorXd& theta, double sigma2Mm2) {
  const VectorXd r = residuals(p, theta);
  const MatrixXd jac = jacobian(p, theta, r);
  MatrixXd jtj = jac.transpose() * jac;
  for (Eigen::Index i = 0; i < theta.size(); ++i)
    if (p.layout.fixed(i)) jtj.row(i).setZero(), jtj.col(i).setZero(), jtj(i, i) = 1.0;
  const Eigen::LDLT<MatrixXd> ldlt(jtj);
  if (ldlt.info() != Eigen::Success || !ldlt.isPositive()) return std::nullopt;
  MatrixXd cov = sigma2Mm2 * ldlt.solve(MatrixXd::Identity(theta.size(), theta.size()));
  for (Eigen::Index i = 0; i < theta.size(); ++i)
    if (p.layout.fixed(i)) cov.row(i).setZero(), cov.col(i).setZero();
  if (!cov.allFinite() || (cov.diagonal().array() < 0.0).any()) return std::nullopt;
  return cov;
}

double sdOf(const MatrixXd& cov, const VectorXd& gradient) {
  return std::sqrt(std::max(0.0, gradient.dot(cov * gradient)));
}

// The covariance of a Gaussian given the linear measure gᵀθ (a known stature).
MatrixXd conditionedOn(const MatrixXd& cov, const VectorXd& g) {
  const VectorXd cg = cov * g;
  const double var = g.dot(cg);
  return var > 0.0 ? MatrixXd(cov - cg * cg.transpose() / var) : cov;
}

// The walker's distance from a pinhole (its pelvis's, mean over the clip, mm) at θ.
double walkerDistanceMm(const Problem& p, const VectorXd& theta) {
  return pelvisDistancesMm(walkInCameraFrame(framesOf(p, theta), p.timesS, cameraOf(p, theta))).mean();
}

// Its gradient over θ by central differences over every free parameter (the coefficients move
// the pelvis a little too).
VectorXd walkerDistanceGradient(const Problem& p, const VectorXd& theta) {
  const VectorXd h = stepSizes(p, theta);
  VectorXd g = VectorXd::Zero(theta.size());
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    if (p.layout.fixed(i)) continue;
    VectorXd up = theta, down = theta;
    up[i] += h[i];
    down[i] -= h[i];
    g[i] = (walkerDistanceMm(p, up) - walkerDistanceMm(p, down)) / (2.0 * h[i]);
  }
  return g;
}

// The camera's SDs: the angles and the focal length are parameters, the walker's distance a
// function of them all. `statureGradient`: the stature's over θ.
void cameraUncertainty(const Problem& p, const VectorXd& theta, const MatrixXd& cov, const VectorXd& statureGradient,
                       FitUncertainty& u) {
  const Layout& l = p.layout;
  u.alphaDeg = std::sqrt(std::max(0.0, cov(l.alpha(), l.alpha())));  // θ holds α and ε in degrees
  u.elevationDeg = std::sqrt(std::max(0.0, cov(l.elevation(), l.elevation())));
  if (!l.pinhole) return;
  u.focalPx = l.focalFree ? std::exp(theta[l.logFocal()]) * std::sqrt(std::max(0.0, cov(l.logFocal(), l.logFocal()))) : 0.0;
  const VectorXd g = walkerDistanceGradient(p, theta);
  // The part of the distance's variance that its stature explains (the scale) is widened as the
  // stature's SD is (kStatureSdWidening); the rest, mostly the focal length's, is not.
  const double givenStature = sdOf(conditionedOn(cov, statureGradient), g);
  const double scalePart = std::max(0.0, std::pow(sdOf(cov, g), 2) - givenStature * givenStature);
  u.walkerDistanceM = std::sqrt(givenStature * givenStature + kStatureSdWidening * kStatureSdWidening * scalePart) / 1000.0;
  u.walkerDistanceShareGivenStature = givenStature / walkerDistanceMm(p, theta);
}

FitUncertainty fitUncertainty(const Problem& p, const VectorXd& theta, const CameraFitOptions& o) {
  FitUncertainty u;
  if (p.priorWeight.size() == 0) return u;  // least squares: nothing bounds the scale
  const std::optional<MatrixXd> cov = laplaceCovariance(p, theta, o.estimator.sigma2Mm2);
  if (!cov) return u;
  const Layout& l = p.layout;
  // The stature depends on the coefficients alone (and linearly: a central difference is exact).
  VectorXd g = VectorXd::Zero(theta.size());
  for (int i = 0; i < l.n; ++i) {
    const double h = std::sqrt(std::max(p.model.eigenvalues[i], 1.0)) * 1e-3;
    VectorXd up = theta, down = theta;
    up[i] += h;
    down[i] -= h;
    g[i] = (statureFromHeadAboveAnklesMm(walkerHeadHeightMm(walkerOf(p, up))) -
            statureFromHeadAboveAnklesMm(walkerHeadHeightMm(walkerOf(p, down)))) / (2.0 * h);
  }
  u.statureMm = kStatureSdWidening * sdOf(*cov, g);
  cameraUncertainty(p, theta, *cov, g, u);
  if (l.speedFixed) return u;
  const MatrixXd givenStature = conditionedOn(*cov, g);
  const double omega = theta[l.omega()], speed = theta[l.speed()];
  const double strideM = 2.0 * std::numbers::pi * speed / omega * 1e-3;
  VectorXd v = VectorXd::Zero(theta.size());
  v[l.speed()] = 1e-3;
  u.speedMps = sdOf(*cov, v);
  u.speedShareGivenStature = sdOf(givenStature, v) / std::abs(speed * 1e-3);
  // stride = 2π v / ω
  VectorXd s = VectorXd::Zero(theta.size());
  s[l.speed()] = 2.0 * std::numbers::pi / omega * 1e-3;
  s[l.omega()] = -strideM / omega;
  u.strideLengthM = sdOf(*cov, s);
  u.strideShareGivenStature = sdOf(givenStature, s) / std::abs(strideM);
  return u;
}


}  // namespace

CameraFit reconstructUnknownCamera(const EigenwalkerModel& model, const MatrixXd& jointsPx, double rateHz,
                                   const CameraFitOptions& o) {
  if (jointsPx.cols() != 2 * kJointCount) badData(o.file, "need 30 columns (u, v of 15 joints)");
  if (jointsPx.rows() < 8) badData(o.file, "fewer than 8 frames");
  checkOptions(o);
  const VectorXd times = frameTimes(static_cast<int>(jointsPx.rows()), rateHz);
  JointMask unseen{};
  std::vector<int> unseenJoints;
  for (int j = 0; j < kJointCount; ++j) {
    unseen[static_cast<std::size_t>(j)] = !jointsPx.col(2 * j).array().isFinite().any();
    if (unseen[static_cast<std::size_t>(j)]) unseenJoints.push_back(j);
  }
  const OrthoStart start = orthographicStart(model, jointsPx, times, unseen, o);
  const bool pinhole = o.focalPx.has_value() || o.estimateFocal;
  const Layout layout{static_cast<int>(model.eigenvalues.size()), pinhole, pinhole && !o.focalPx,
                      o.alphaDeg.has_value(), o.elevationDeg.has_value(), o.holdStrideHz && o.strideHzHint.has_value(),
                      o.inPlace};
  const double midT = 0.5 * (times[0] + times[times.size() - 1]);
  const Framing framing{start.pelvisV[0] + start.pelvisV[1] * midT,
                        kFramingSdOfHeight * start.pxPerMm * walkerHeadHeightMm(model.mean)};
  const Problem p = makeProblem(model, layout, o, jointsPx, times, 1.0 / start.pxPerMm, 1, framing);
  // Screening sees every few frames (the walk is smooth; ~8 frames a stride are plenty).
  const int stride = std::max(1, static_cast<int>(rateHz / (kScreeningFramesPerStride * start.fit.omegaRadS / (2 * std::numbers::pi))));
  const Problem coarse = makeProblem(model, layout, o, jointsPx, times, 1.0 / start.pxPerMm, stride, framing);
  const std::vector<double> elevations =
      o.elevationDeg ? std::vector<double>{*o.elevationDeg}
                     : std::vector<double>(std::begin(kStartElevationsDeg), std::end(kStartElevationsDeg));
  std::vector<Candidate> results = tryStarts(p, coarse, start, startAngles(start.search, o), elevations, o);
  CameraFit fit;
  bool found = finishBest(p, results, o, fit);
  const double heightPx = start.pxPerMm * walkerHeadHeightMm(model.mean);
  // Off the minima's basins (a walker coming diagonally towards the camera can mislead the
  // orthographic search): starts from every 30° too, and the better finished fit is kept.
  if (!o.alphaDeg && (!found || fit.reprojectionRmsPx > kRetryRmsOfHeight * heightPx)) {
    std::vector<Candidate> wide = tryStarts(p, coarse, start, gridAngles(), elevations, o);
    CameraFit wideFit;
    if (finishBest(p, wide, o, wideFit) && (!found || wide.front().second.objective < results.front().second.objective)) {
      fit = wideFit;
      found = true;
      wide.insert(wide.end(), results.begin(), results.end());
      results = std::move(wide);
    } else {
      results.insert(results.end(), wide.begin(), wide.end());
    }
  }
  if (found && o.strideHzHint && !o.holdStrideHz &&
      std::abs(fit.strideHz / *o.strideHzHint - 1.0) > kStrideDriftFromHint) {
    CameraFit heldFit;
    if (std::optional<Candidate> held = startsAtTheHintedStride(model, layout, o, jointsPx, times, start, framing,
                                                                 stride, elevations, p, heldFit);
        held && held->second.objective < results.front().second.objective) {
      fit = heldFit;
      results.insert(results.begin(), *held);
    }
  }
  if (!found) badData(o.file, "no start converged to a walker moving forward");
  // Glitches out, the fit finished again on what is left.
  VectorXd theta = results.front().first;
  MatrixXd kept = jointsPx;
  for (int round = 0; round < kOutlierRounds; ++round) {
    const Glitches g = withoutOutliers(kept, imageOf(p, theta), heightPx);
    // A few glitches that hardly weigh in the fit are left in: a refit would not move it.
    if (g.count == 0 || g.shareOfSquares < kGlitchShareToRefit) break;
    kept = g.kept;
    fit.outlierSamples += g.count;
    const Problem robust = makeProblem(model, layout, o, kept, times, 1.0 / start.pxPerMm, 1, framing);
    const LmResult again = levenbergMarquardt(robust, theta, o.maxIterations);
    theta = again.theta;
    fillOutputs(robust, theta, fit);
    results.front().first = theta;
    results.front().second.objective = again.cost;
    results.front().second.reprojectionRmsPx = fit.reprojectionRmsPx;
  }
  // A fit that misses the image by more than a few percent of the walker's height is a
  // wrong basin, not an answer (good fits: 1-3 %, 7 % for a 140 px walker at 5 px noise; wrong basins 19-43 %).
  if (fit.reprojectionRmsPx > kMaxRmsOfHeight * heightPx)
    badData(o.file, "no start fits the image (best reprojection RMS " + std::to_string(fit.reprojectionRmsPx) +
                        " px, more than " + std::to_string(static_cast<int>(100 * kMaxRmsOfHeight)) +
                        " % of the walker's " + std::to_string(static_cast<int>(heightPx)) + " px height)");
  fit.unseenJoints = unseenJoints;
  fit.sd = fitUncertainty(makeProblem(model, layout, o, kept, times, 1.0 / start.pxPerMm, 1, framing), theta, o);
  if (o.inPlace) setBeltSpeed(fit);
  fit.camera.alphaDeg = wrapDeg(fit.camera.alphaDeg);
  fit.objective = results.front().second.objective;
  for (const auto& r : results) fit.starts.push_back(r.second);
  return fit;
}

}  // namespace ew
