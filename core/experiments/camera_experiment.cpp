#include "core/experiments/camera_experiment.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <numbers>
#include <numeric>
#include <random>
#include <tuple>
#include <unistd.h>

#include "core/engines/request.h"
#include "core/camera/camera_reconstruction.h"
#include "core/camera/clip_reconstruction.h"
#include "core/camera/detector_offsets.h"
#include "core/camera/walk_camera.h"
#include "core/common/errors.h"
#include "core/common/wall_time.h"
#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/fourier.h"
#include "core/engines/engine.h"
#include "core/experiments/engine_view_curves.h"
#include "core/eigenwalker/projection.h"
#include "core/keypoints/image_gait.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/keypoints/openpose_writer.h"
#include "core/gait/body_size.h"
#include "core/skeleton/bone_sources.h"
#include "core/skeleton/skeleton_camera.h"

namespace ew {

const char* const kCameraEigenwalker = "eigenwalker";
const char* const kCameraEigenwalkerStatureGiven = "eigenwalker, stature given";
const char* const kCameraSkeletonOwnBones = "skeleton (own bones)";
const char* const kCameraSkeletonGuided = "skeleton (own bones, eigenwalker's branches)";
const char* const kCameraSkeletonTable2 = "skeleton (Table 2 x stature)";
const char* const kCameraSkeletonEigenwalkerBones = "skeleton (eigenwalker's bones and branches)";
const char* const kCameraSnippet = "snippet (weak perspective)";

namespace {

namespace fs = std::filesystem;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kImageW = 1920, kImageH = 1080;
constexpr double kClipS = 10.0;            // filmed; the clip is the part in the image
constexpr double kMinStrides = 1.5;
constexpr double kWalkerFitHeightMm = 1900;  // head top plus margin must fit 85 % of the image
constexpr int kMaxCameraDraws = 50;

[[noreturn]] void badCameraOption(const std::string& what) { throw Error(ErrorKind::BadArgument, "", "", "camera: " + what); }

void checkOptions(const CameraExperimentOptions& o) {
  if (o.camerasPerWalker < 1) badCameraOption("at least one camera per walker");
  for (double n : o.noisePx)
    if (!(std::isfinite(n) && n >= 0)) badCameraOption("noise levels must be finite and >= 0");
  if (o.noisePx.empty()) badCameraOption("no noise level");
  if (!(o.dropShare >= 0 && o.dropShare <= 1) || !(o.bystanderShare >= 0 && o.bystanderShare <= 1))
    badCameraOption("shares must be within [0, 1]");
  if (!(std::isfinite(o.sigma2Mm2) && o.sigma2Mm2 >= 0)) badCameraOption("sigma2 must be finite and >= 0");
  if (!(o.fps >= 1 && o.fps <= 240)) badCameraOption("the frame rate must be 1-240 fps");
  if (o.detectorHipOffsetMm && !(std::abs(*o.detectorHipOffsetMm) <= kMaxDetectorOffsetMm))
    badCameraOption("the detector's hip offset must be within ±200 mm");
  if (o.clipStrides && !(*o.clipStrides >= 0.5 && *o.clipStrides <= 10)) badCameraOption("a clip must be 0.5-10 strides");
  if (o.walkerHeightPx && !(*o.walkerHeightPx >= 20 && *o.walkerHeightPx <= 5000))
    badCameraOption("the walker's height must be 20-5000 px");
  if (!(o.minSpeedMps > 0 && o.minSpeedMps <= o.maxSpeedMps && o.maxSpeedMps <= 5))
    badCameraOption("the speeds must be 0 < min <= max <= 5 m/s");
  if (!(std::abs(o.cadenceSpeedExponent) <= 2)) badCameraOption("the cadence's exponent must be within ±2");
  if (o.horizonReadSdDeg && !(*o.horizonReadSdDeg >= 0 && *o.horizonReadSdDeg <= 10))
    badCameraOption("the horizon's reading error must be 0-10 degrees");
  if (!(std::abs(o.horizonReadBiasDeg) <= 20)) badCameraOption("the horizon's reading bias must be within ±20 degrees");
  if (!(o.minElevationDeg >= -30 && o.minElevationDeg <= o.maxElevationDeg && o.maxElevationDeg <= 80))
    badCameraOption("the elevations must be -30 <= min <= max <= 80 degrees");
  if (!(o.minLookAtHeightMm >= -5000 && o.minLookAtHeightMm <= o.maxLookAtHeightMm && o.maxLookAtHeightMm <= 10000))
    badCameraOption("the look-at heights must be -5000 <= min <= max <= 10000 mm");
}

const char* layoutName(ClipLayout layout) { return layout == ClipLayout::Coco17 ? "COCO-17" : "BODY_25"; }

// Where the simulated detector puts its points relative to the joint centres.
JointOffsetsMm simulatedDetector(const CameraExperimentOptions& o) {
  const JointOffsetsMm table = keypointLayoutNamed(layoutName(o.layout)).detectorOffsetMm;
  if (!o.detectorHipOffsetMm) return table;
  JointOffsetsMm hips{};
  hips[static_cast<std::size_t>(index(Joint::RHip))] = {*o.detectorHipOffsetMm, 0.0, 0.0};
  hips[static_cast<std::size_t>(index(Joint::LHip))] = {-*o.detectorHipOffsetMm, 0.0, 0.0};
  return hips;
}

struct Clip {
  WalkCamera camera;
  VectorXd times;    // of the kept frames
  MatrixXd truth;    // T × 45 canonical frames of the walker
  MatrixXd px;       // T × 30 clean image positions, where the detector puts the points
  double imageW = kImageW, imageH = kImageH;
  double strides = 0;  // the clip's length in the walker's strides
  // The scene's horizon as read (CameraExperimentOptions::horizonReadSdDeg), when read.
  std::optional<double> horizonRowPx = std::nullopt;
};

// The true camera's horizon read with an error of `sd` and `bias` degrees (the error's draw from
// a generator of its own, so that the clips' other draws do not change).
double readHorizonRowPx(const WalkCamera& c, double sd, double bias, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> error(bias, sd);
  WalkCamera read = c;
  read.elevationDeg += error(rng);  // a horizon δ higher in the picture: the camera looks δ further down
  return horizonRowPx(read);
}

// Head to ankles in the image (px), median over the frames.
double medianHeightPx(const MatrixXd& px) {
  std::vector<double> h;
  for (Eigen::Index f = 0; f < px.rows(); ++f) {
    const double ankles = 0.5 * (px(f, 2 * index(Joint::LAnkle) + 1) + px(f, 2 * index(Joint::RAnkle) + 1));
    const double v = std::abs(ankles - px(f, 2 * index(Joint::Head) + 1));
    if (std::isfinite(v)) h.push_back(v);
  }
  if (h.empty()) return std::nan("");
  std::nth_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(h.size() / 2), h.end());
  return h[h.size() / 2];
}

// The longest run of frames whose pelvis is inside the image.
std::pair<Eigen::Index, Eigen::Index> longestInside(const MatrixXd& px) {
  std::pair<Eigen::Index, Eigen::Index> best{0, 0};
  Eigen::Index begin = -1;
  for (Eigen::Index f = 0; f <= px.rows(); ++f) {
    const bool in = f < px.rows() && px(f, 2 * index(Joint::Pelvis)) >= 0 && px(f, 2 * index(Joint::Pelvis)) < kImageW &&
                    px(f, 2 * index(Joint::Pelvis) + 1) >= 0 && px(f, 2 * index(Joint::Pelvis) + 1) < kImageH;
    if (in && begin < 0) begin = f;
    if (!in && begin >= 0) {
      if (f - begin > best.second - best.first) best = {begin, f};
      begin = -1;
    }
  }
  return best;
}

// A random camera filming the walker; redrawn until the clip holds kMinStrides strides (or
// the options' clipStrides, to which it is then cut), the options' factors applied.
Clip filmWalker(const ExperimentWalker& w, const CameraExperimentOptions& o, const JointOffsetsMm& detector,
                std::mt19937& rng) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const double fps = o.fps;
  const int n = static_cast<int>(kClipS * fps);
  const VectorXd all = frameTimes(n, fps);
  const double minStrides = o.clipStrides.value_or(kMinStrides);
  for (int draw = 0; draw < kMaxCameraDraws; ++draw) {
    WalkCamera c;
    c.model = CameraModel::Pinhole;
    c.alphaDeg = -180.0 + 360.0 * uni(rng);
    c.elevationDeg = o.minElevationDeg + (o.maxElevationDeg - o.minElevationDeg) * uni(rng);
    c.focalPx = 800.0 + 2200.0 * uni(rng);
    const double fitsMm = c.focalPx * kWalkerFitHeightMm / (0.85 * kImageH);
    const double lo = std::max(3500.0, fitsMm), hi = std::max(8000.0, lo + 1000.0);
    c.distanceMm = lo + (hi - lo) * uni(rng);
    c.cxPx = kImageW / 2;
    c.cyPx = kImageH / 2;
    c.lookAtHeightMm = o.minLookAtHeightMm;
    if (o.maxLookAtHeightMm > o.minLookAtHeightMm)  // no draw for the default: the same cameras
      c.lookAtHeightMm += (o.maxLookAtHeightMm - o.minLookAtHeightMm) * uni(rng);
    const double slowMmS = 1000.0 * o.minSpeedMps, fastMmS = 1000.0 * o.maxSpeedMps;
    c.speedMmS = slowMmS + (fastMmS - slowMmS) * uni(rng);
    c.startOffsetMm = -c.speedMmS * kClipS / 2;
    const double omega = w.fit.omegaRadS * std::pow(c.speedMmS / 1300.0, o.cadenceSpeedExponent);
    const MatrixXd frames = synthesizeFrames(w.fit.w, omega, 0.0, all);
    MatrixXd detected = frames;  // where the detector puts the points
    addOffsets(detected, detector);
    const double strideS = 2 * std::numbers::pi / omega;
    MatrixXd px = projectWalk(detected, all, c);
    auto [a, b] = longestInside(px);
    if (static_cast<double>(b - a) / fps < minStrides * strideS) continue;
    if (o.clipStrides) {  // the middle of the run, cut to the strides asked for
      const Eigen::Index keep = std::max<Eigen::Index>(2, std::lround(*o.clipStrides * strideS * fps));
      a += (b - a - keep) / 2;
      b = a + keep;
    }
    Clip clip{c, all.segment(a, b - a), frames.middleRows(a, b - a), px.middleRows(a, b - a)};
    clip.strides = static_cast<double>(b - a) / fps / strideS;
    if (o.walkerHeightPx) {  // the same scene through a camera of another resolution
      const double k = *o.walkerHeightPx / medianHeightPx(clip.px);
      clip.camera.focalPx *= k;
      clip.camera.cxPx *= k;
      clip.camera.cyPx *= k;
      clip.imageW *= k;
      clip.imageH *= k;
      clip.px *= k;
    }
    return clip;
  }
  throw Error(ErrorKind::BadData, w.id, "", "camera: no camera draw kept the walker in the image for " +
                                                std::to_string(minStrides) + " strides");
}

// A point off the picture is one no detector reports: its confidence set to 0 (missing).
void dropOffPicture(const MatrixXd& px, double imageW, double imageH, MatrixXd& confidence) {
  for (Eigen::Index f = 0; f < px.rows(); ++f)
    for (int j = 0; j < kJointCount; ++j) {
      const double u = px(f, 2 * j), v = px(f, 2 * j + 1);
      if (!(u >= 0.0 && u < imageW && v >= 0.0 && v < imageH)) confidence(f, j) = 0.0;
    }
}

// Someone standing still: the walker's first pose, smaller, elsewhere in the image.
MatrixXd bystander(const MatrixXd& px, double imageW, std::mt19937& rng) {
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  const Eigen::RowVectorXd pose = px.row(0);
  Eigen::RowVectorXd moved(pose.size());
  const double u0 = pose[2 * index(Joint::Pelvis)], v0 = pose[2 * index(Joint::Pelvis) + 1];
  const double u = (200 + (kImageW - 400) * uni(rng)) * (imageW / kImageW), scale = 0.7;
  for (int j = 0; j < kJointCount; ++j) {
    moved[2 * j] = u + scale * (pose[2 * j] - u0);
    moved[2 * j + 1] = v0 + scale * (pose[2 * j + 1] - v0);
  }
  return moved.replicate(px.rows(), 1);
}

// Where an engine's gait rows go when options.gait asks for them: beside the walker's own
// measures, both from frames in the walker's frame at the clip's rate. The truth walks over the
// floor at the clip's speed; `reconstructed` says what the engine knows of its own walk.
struct GaitSink {
  bool on;
  double fps;
  CameraRow& row;
  void add(const char* engine, const Clip& clip, const MatrixXd& truth, const MatrixXd& frames,
           const GaitSideWalk& reconstructed = {}) const {
    if (!on) return;
    const GaitSideWalk truthWalk{clip.camera.speedMmS / 1000.0, false, std::nullopt};
    for (auto& g : gaitAgreementRows(row.subject, engine, clip.camera.alphaDeg, truth, frames, fps, truthWalk,
                                     reconstructed)) {
      g.setting = "camera";
      g.noise = row.noisePx;
      g.camera = row.camera;
      row.gait.push_back(std::move(g));
    }
  }
};

fs::path clipFolder(int index) {
  return fs::temp_directory_path() /
         ("eigenwalker_camera_" + std::to_string(::getpid()) + "_" + std::to_string(index));
}

// How far below the walker's pelvis at mid-clip the clip's camera has its principal point, in
// the walker's image heights (positive: the walker is above the picture's centre).
double framingOffsetOfHeight(const Clip& clip) {
  const Eigen::Index mid = clip.px.rows() / 2;
  return (clip.camera.cyPx - clip.px(mid, 2 * index(Joint::Pelvis) + 1)) / medianHeightPx(clip.px);
}

// The fit's stature, speed and stride length beside the truth, each with the SD the fit gives
// it (CameraFit::sd): how often ±1.96 SD holds the truth is the summary's.
void scoreMeasuresAndTheirSds(const ExperimentWalker& w, const Clip& clip, const CameraExperimentOptions& o,
                              const CameraFit& fit, double trueHeadHeightMm, CameraRow& row) {
  const double trueOmega = w.fit.omegaRadS * std::pow(clip.camera.speedMmS / 1300.0, o.cadenceSpeedExponent);
  row.trueStatureM = statureFromHeadAboveAnklesMm(trueHeadHeightMm) / 1000;
  row.statureM = fit.statureMm / 1000;
  row.statureSdM = fit.sd.statureMm / 1000;
  row.trueSpeedMps = clip.camera.speedMmS / 1000;
  row.speedMps = fit.speedMps;
  row.speedSdMps = fit.sd.speedMps;
  row.trueStrideLengthM = row.trueSpeedMps * 2 * std::numbers::pi / trueOmega;
  row.strideLengthM = fit.strideLengthM;
  row.strideLengthSdM = fit.sd.strideLengthM;
  row.strideGivenStatureM = fit.strideLengthM * row.trueStatureM / row.statureM;
  row.strideGivenStatureSdM = fit.sd.strideShareGivenStature * std::abs(row.strideGivenStatureM);
  row.alphaSdDeg = fit.sd.alphaDeg;
  row.elevationSdDeg = fit.sd.elevationDeg;
  row.focalSdPx = fit.sd.focalPx;
  row.walkerDistanceSdM = fit.sd.walkerDistanceM;
}

// The eigenwalker with everything unknown (the experiment's subject).
// What the eigenwalker's fit gives the other engines: its walker, and that walker in the
// fit's own camera frame at every frame (a guide for the skeleton engine's branches).
struct EigenwalkerClip {
  VectorXd w;
  double omegaRadS = 0.0;
  std::vector<JointMatrix> guideMm;
};

EigenwalkerClip eigenwalkerOnClip(const Fold& fold, const ExperimentWalker& w, const Clip& clip,
                                              const KeypointTrial& t, const std::string& folder,
                                              const CameraExperimentOptions& o, CameraRow& row) {
  // Everything unknown, as `reconstruct --unknown-camera` fits keypoint files.
  CameraView view;
  view.keypoints = t;
  view.name = folder;
  if (o.focalKnown) {
    view.camera.focalPx = clip.camera.focalPx;
    view.camera.focalSource = "given";
  }
  view.camera.horizonRowPx = clip.horizonRowPx;
  const auto t0 = std::chrono::steady_clock::now();
  const ReconstructionResult r = reconstruct(EigenwalkerEngine{fold.model, {Estimator::Map, o.sigma2Mm2}, {}}, {std::move(view)});
  const CameraFit& fit = r.camera.eigenwalker->last.fit;
  row.seconds = secondsSince(t0);
  row.alphaDeg = fit.camera.alphaDeg;
  row.elevationDeg = fit.camera.elevationDeg;
  row.focalPx = fit.camera.focalPx;
  row.distanceM = fit.camera.distanceMm / 1000;
  row.alphaErrorDeg = std::abs(wrapDeg(fit.camera.alphaDeg - clip.camera.alphaDeg));
  row.elevationErrorDeg = std::abs(fit.camera.elevationDeg - clip.camera.elevationDeg);
  row.focalRelError = std::abs(fit.camera.focalPx - clip.camera.focalPx) / clip.camera.focalPx;
  const double height = walkerHeadHeightMm(w.fit.w);
  row.heightRelError = std::abs(fit.headHeightMm - height) / height;
  const MatrixXd trueCamera = walkInCameraFrame(clip.truth, clip.times, clip.camera);
  const VectorXd times = frameTimes(static_cast<int>(clip.times.size()), o.fps);
  const MatrixXd frames = synthesizeFrames(fit.w, fit.omegaRadS, fit.phaseRad, times);
  row.mpjpeMm = mpjpeWithoutTranslation(frames, clip.truth);
  row.reprojectionRmsPx = fit.reprojectionRmsPx;
  // The fit's walk over the floor is its camera's progression (walking in place: none, the
  // stance feet of its two-harmonic walker tell).
  // Its frames repeat at the fit's ω: one stride's events per cycle.
  const double strideHz = fit.omegaRadS / (2.0 * std::numbers::pi);
  const GaitSideWalk walked = fit.inPlace ? GaitSideWalk{std::nullopt, true, strideHz}
                                          : GaitSideWalk{fit.speedMps, false, strideHz};
  const GaitSink gait{o.gait, o.fps, row};
  gait.add(kCameraEigenwalker, clip, clip.truth, frames, walked);
  const double toStature = height / fit.headHeightMm;  // head height stands for the stature
  gait.add(kCameraEigenwalkerStatureGiven, clip, clip.truth, frames * toStature,
           {walked.progressionMps ? std::optional<double>(*walked.progressionMps * toStature) : std::nullopt,
            walked.twoHarmonicWalker, strideHz});
  EigenwalkerClip out{fit.w, fit.omegaRadS, {}};
  const MatrixXd camera = walkInCameraFrame(frames, times, fit.camera);
  row.trueWalkerDistanceM = trueCamera.middleCols<3>(3 * index(Joint::Pelvis)).rowwise().norm().mean() / 1000;
  row.walkerDistanceM = fit.walkerDistanceM;  // the fit's own, as reconstruct reports it
  row.distanceRelError = std::abs(row.walkerDistanceM - row.trueWalkerDistanceM) / row.trueWalkerDistanceM;
  scoreMeasuresAndTheirSds(w, clip, o, fit, height, row);
  row.trueViewElevationDeg = viewElevationDeg(trueCamera, clip.camera.elevationDeg);
  row.viewElevationDeg = fit.viewElevationDeg;
  row.viewElevationErrorDeg = std::abs(row.viewElevationDeg - row.trueViewElevationDeg);
  for (Eigen::Index frame = 0; frame < camera.rows(); ++frame)
    out.guideMm.push_back(Eigen::Map<const Eigen::Matrix<double, 3, kJointCount>>(camera.row(frame).eval().data()));
  return out;
}

// Frames in the walker's frame with the clip's progression added (sign +1) or taken out (−1).
MatrixXd shiftedByProgression(MatrixXd frames, const Clip& clip, double sign) {
  for (Eigen::Index f = 0; f < frames.rows(); ++f)
    for (int j = 0; j < kJointCount; ++j)
      frames(f, 3 * j + 1) += sign * (clip.camera.startOffsetMm + clip.camera.speedMmS * clip.times[f]);
  return frames;
}

// The snippet engine's orthographic view of a pinhole image (weak perspective): each ray
// turned level (the camera's tilt ε about its x axis taken out), met with the
// fronto-parallel plane through the pelvis at `pelvisCameraMm`'s depth; u right, v up (mm).
MatrixXd weakPerspectiveView(const MatrixXd& px, const WalkCamera& c, const MatrixXd& pelvisCameraMm) {
  const double ce = std::cos(degToRad(c.elevationDeg)), se = std::sin(degToRad(c.elevationDeg));
  Eigen::Matrix3d level;  // Eᵀ: camera frame → level camera frame
  level << 1, 0, 0, 0, ce, se, 0, -se, ce;
  MatrixXd uv(px.rows(), px.cols());
  for (Eigen::Index f = 0; f < px.rows(); ++f) {
    const double depth = (level * pelvisCameraMm.row(f).transpose()).z();
    const JointRays rays = pinholeRays(px.row(f), {c.focalPx, c.focalPx, c.cxPx, c.cyPx});
    for (int j = 0; j < kJointCount; ++j) {
      const Eigen::Vector3d ray = level * rays.direction.col(j);
      const bool seen = std::isfinite(ray.x()) && std::isfinite(ray.y()) && ray.z() > 1e-6;
      uv(f, 2 * j) = seen ? ray.x() * depth / ray.z() : std::nan("");
      uv(f, 2 * j + 1) = seen ? -ray.y() * depth / ray.z() : std::nan("");
    }
  }
  return uv;
}

// The skeleton engine (labelled `engine`) through the true camera with `bones`, scored;
// `keep` receives its result.
EngineClipScore skeletonOnClip(const Clip& clip, const KeypointTrial& t, const BoneLengths& bones,
                               const std::string& name, const char* engine, const GaitSink& gait,
                               const std::vector<JointMatrix>* guide = nullptr,
                               std::optional<SkeletonCameraResult>* keep = nullptr) {
  EngineClipScore score{std::nan(""), 0, ""};
  const auto t0 = std::chrono::steady_clock::now();
  try {
    SkeletonEngine skeleton{bones, {}};
    if (guide) skeleton.solve.guideMm = *guide;
    CameraView view;
    view.keypoints = t;
    view.camera.calibration = calibrationOf(clip.camera, clip.imageW, clip.imageH);
    view.camera.focalPx = view.camera.calibration->focalPx();
    view.name = name;
    SkeletonCameraResult r = std::move(*reconstruct(skeleton, {std::move(view)}).camera.skeleton);
    score.seconds = secondsSince(t0);
    const MatrixXd inPlace = shiftedByProgression(r.worldMm, clip, -1.0);
    score.mpjpeMm = mpjpeWithoutTranslation(inPlace, clip.truth);
    gait.add(engine, clip, clip.truth, inPlace);
    score.clampedBoneFrames = r.sequence.clampedBoneFrames;
    if (keep) *keep = std::move(r);
  } catch (const std::exception& e) {
    score.error = e.what();
    score.seconds = secondsSince(t0);
  }
  return score;
}

EngineClipScore snippetOnClip(const Clip& clip, const KeypointTrial& t, const SnippetEngine& snippet,
                              const SkeletonCameraResult& depthFrom, const std::string& name, const GaitSink& gait) {
  EngineClipScore score{std::nan(""), 0, ""};
  const auto t0 = std::chrono::steady_clock::now();
  try {
    ViewInput in;
    in.uvMm = weakPerspectiveView(t.jointsPx, clip.camera,
                                  depthFrom.sequence.framesMm.middleCols<3>(3 * index(Joint::Pelvis)));
    in.rateHz = t.rateHz;
    in.alphaDeg = clip.camera.alphaDeg;
    in.name = name;
    const EngineResult e = reconstruct(snippet, {in}).engine;
    score.seconds = secondsSince(t0);
    const MatrixXd truth = shiftedByProgression(clip.truth, clip, 1.0);
    score.mpjpeMm = mpjpeWithoutTranslation(e.framesMm, truth);
    gait.add(kCameraSnippet, clip, truth, e.framesMm);
  } catch (const std::exception& e) {
    score.error = e.what();
    score.seconds = secondsSince(t0);
  }
  return score;
}

EngineClipScore failed(const std::string& why) { return {std::nan(""), 0, why}; }

// Every other engine asked for gave no answer, for one reason.
void otherEnginesFailed(const CameraExperimentOptions& o, const std::string& why, CameraRow& row) {
  if (o.skeleton) row.skeleton = row.skeletonGuided = row.skeletonTable2 = row.skeletonEigenwalkerBones = failed(why);
  if (o.snippet) row.snippet = failed(why);
}

// The skeleton engine through the true camera with each source of bone lengths, and the
// snippet engine at the depth the skeleton engine (own bones) found.
void geometricEnginesOnClip(const Clip& clip, const KeypointTrial& t, const SnippetEngine* snippet,
                            const std::optional<EigenwalkerClip>& eigenwalker,
                            const CameraExperimentOptions& o, const std::string& name, CameraRow& row) {
  if (t.jointsPx.rows() != clip.truth.rows()) return otherEnginesFailed(o, name + ": frames lost reading back", row);
  BoneLengths ownBones;
  try {
    ownBones = boneLengthsFromFrames(clip.truth, name);
  } catch (const std::exception& e) {
    return otherEnginesFailed(o, e.what(), row);
  }
  const GaitSink gait{o.gait, o.fps, row};
  const GaitSink noGait{false, o.fps, row};  // the skeleton's depth for the snippet engine only
  std::optional<SkeletonCameraResult> own;
  const EngineClipScore ownScore =
      skeletonOnClip(clip, t, ownBones, name, kCameraSkeletonOwnBones, o.skeleton ? gait : noGait, nullptr, &own);
  if (o.snippet)
    row.snippet = own && snippet ? snippetOnClip(clip, t, *snippet, *own, name, gait) : failed(ownScore.error);
  if (!o.skeleton) return;
  row.skeleton = ownScore;
  try {
    if (!eigenwalker) throw Error(ErrorKind::BadData, name, "", "the eigenwalker gave no walker: " + row.error);
    row.skeletonGuided = skeletonOnClip(clip, t, ownBones, name, kCameraSkeletonGuided, gait, &eigenwalker->guideMm);
  } catch (const std::exception& e) {
    row.skeletonGuided = failed(e.what());
  }
  try {
    const auto size = measureBodySize(clip.truth);
    if (!size) throw Error(ErrorKind::BadData, name, "", "no head-to-ankles distance for a stature");
    row.skeletonTable2 =
        skeletonOnClip(clip, t, boneLengthsFromZouTable2(size->lengthMm / kHeadAboveAnklesPerStature, name), name,
                       kCameraSkeletonTable2, gait);
  } catch (const std::exception& e) {
    row.skeletonTable2 = failed(e.what());
  }
  try {
    if (!eigenwalker) throw Error(ErrorKind::BadData, name, "", "the eigenwalker gave no walker: " + row.error);
    row.skeletonEigenwalkerBones =
        skeletonOnClip(clip, t, boneLengthsFromWalker(eigenwalker->w, eigenwalker->omegaRadS, name), name,
                       kCameraSkeletonEigenwalkerBones, gait, &eigenwalker->guideMm);
  } catch (const std::exception& e) {
    row.skeletonEigenwalkerBones = failed(e.what());
  }
}

// The clip's folder copied to dir/SUBJECT_cameraK_Npx (experiment options keepClipsDir).
void keepClip(const fs::path& folder, const fs::path& dir, const CameraRow& row) {
  char name[160];
  std::snprintf(name, sizeof name, "%s_camera%d_%gpx", row.subject.c_str(), row.camera, row.noisePx);
  const fs::path target = dir / name;
  std::error_code ec;
  fs::remove_all(target, ec);
  fs::create_directories(dir, ec);
  fs::copy(folder, target, fs::copy_options::recursive, ec);
  if (ec) throw Error(ErrorKind::Io, target.string(), "", "cannot keep the clip: " + ec.message());
}

void reconstructClip(const Fold& fold, const ExperimentWalker& w, const Clip& clip, const MatrixXd& observed,
                     const MatrixXd& confidence, const MatrixXd* other, const SnippetEngine* snippet,
                     const CameraExperimentOptions& o, int index, CameraRow& row) {
  const fs::path folder = clipFolder(index);
  fs::remove_all(folder);
  std::vector<OpenPosePerson> people{{observed, confidence}};
  if (other) people.push_back({*other, MatrixXd()});
  fs::path input = folder;
  if (o.layout == ClipLayout::Coco17) {
    fs::create_directories(folder);
    input = folder / "alphapose-results.json";
    writeAlphaPoseCoco17(input, people);
  } else {
    writeOpenPoseBody25(folder, people);
  }
  try {
    KeypointOptions k;
    k.fps = o.fps;
    k.detectorOffsets = o.allowForDetectorOffsets;
    if (o.imageSizeKnown)
      k.imageSize = KeypointImageSize{static_cast<int>(std::lround(clip.imageW)), static_cast<int>(std::lround(clip.imageH))};
    const KeypointTrial t = readKeypointTrial(input, k);
    std::optional<EigenwalkerClip> walker;
    try {
      walker = eigenwalkerOnClip(fold, w, clip, t, folder.string(), o, row);
    } catch (const std::exception& e) {
      row.error = e.what();
    }
    if (o.skeleton || o.snippet) geometricEnginesOnClip(clip, t, snippet, walker, o, folder.string(), row);
  } catch (const std::exception& e) {  // the clip could not be read back: no engine saw it
    row.error = e.what();
    otherEnginesFailed(o, e.what(), row);
  }
  if (o.keepClipsDir) keepClip(folder, *o.keepClipsDir, row);
  fs::remove_all(folder);
}

// Each fold's snippet prior, learnt from the other subjects' walkers (4 cycles at 1.3 m/s,
// the middle of the clips' speeds); a fold whose prior cannot be learnt gets none (its
// clips then carry the reason).
std::vector<std::shared_ptr<const PreparedSnippetPrior>> snippetPriors(const std::vector<ExperimentWalker>& walkers,
                                                                       const std::vector<Fold>& folds, int threads,
                                                                       std::vector<std::string>& whyNot) {
  std::vector<std::shared_ptr<const PreparedSnippetPrior>> priors(folds.size());
  whyNot.assign(folds.size(), "");
  parallelFor(static_cast<int>(folds.size()), threads, [&](int f) {
    try {
      priors[static_cast<std::size_t>(f)] = std::make_shared<const PreparedSnippetPrior>(
          prepareSnippetPrior(fourierSnippetPrior(walkers, folds[static_cast<std::size_t>(f)].subject, 1.3)));
    } catch (const std::exception& e) {
      whyNot[static_cast<std::size_t>(f)] = std::string("snippet prior: ") + e.what();
    }
  });
  return priors;
}

}  // namespace

std::vector<CameraRow> cameraErrors(const std::vector<ExperimentWalker>& walkers, const std::vector<Fold>& folds,
                                    const CameraExperimentOptions& o) {
  checkOptions(o);
  struct Job {
    int fold, walker, camera;
  };
  std::vector<Job> jobs;
  for (std::size_t f = 0; f < folds.size(); ++f)
    for (int w : folds[f].testWalkers) {
      if (w < 0 || w >= static_cast<int>(walkers.size())) badCameraOption("a fold's test walker is not among the walkers");
      for (int c = 0; c < o.camerasPerWalker; ++c) jobs.push_back({static_cast<int>(f), w, c});
    }
  const std::size_t levels = o.noisePx.size();
  const JointOffsetsMm detector = simulatedDetector(o);
  std::vector<std::string> noPrior;
  const auto priors = o.snippet ? snippetPriors(walkers, folds, o.threads, noPrior)
                                : std::vector<std::shared_ptr<const PreparedSnippetPrior>>(folds.size());
  std::vector<CameraRow> rows(jobs.size() * levels);
  parallelFor(static_cast<int>(jobs.size()), o.threads, [&](int j) {
    const Job& job = jobs[static_cast<std::size_t>(j)];
    const ExperimentWalker& w = walkers[static_cast<std::size_t>(job.walker)];
    // One generator per (walker, camera): the same camera and bystander at every noise level.
    std::mt19937 rng(o.seed + 7919u * static_cast<unsigned>(job.walker) + 104729u * static_cast<unsigned>(job.camera));
    Clip clip = filmWalker(w, o, detector, rng);
    if (o.horizonReadSdDeg)
      clip.horizonRowPx = readHorizonRowPx(clip.camera, *o.horizonReadSdDeg, o.horizonReadBiasDeg,
                                           o.seed + 15485863u + static_cast<unsigned>(j));
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    const bool withBystander = uni(rng) < o.bystanderShare;
    const MatrixXd other = withBystander ? bystander(clip.px, clip.imageW, rng) : MatrixXd();
    for (std::size_t l = 0; l < levels; ++l) {
      std::normal_distribution<double> noise(0.0, 1.0);
      MatrixXd observed = clip.px;
      for (Eigen::Index i = 0; i < observed.size(); ++i) observed.data()[i] += o.noisePx[l] * noise(rng);
      MatrixXd confidence = MatrixXd::Constant(observed.rows(), kJointCount, 0.9);
      for (Eigen::Index i = 0; i < confidence.size(); ++i)
        if (uni(rng) < o.dropShare) confidence.data()[i] = 0.1;
      if (o.offPictureDropped) dropOffPicture(observed, clip.imageW, clip.imageH, confidence);
      CameraRow& row = rows[static_cast<std::size_t>(j) * levels + l];
      row.subject = w.subject;
      row.walker = w.id;
      row.camera = job.camera;
      row.noisePx = o.noisePx[l];
      row.bystander = withBystander;
      row.frames = static_cast<int>(clip.times.size());
      row.trueAlphaDeg = clip.camera.alphaDeg;
      row.trueElevationDeg = clip.camera.elevationDeg;
      row.trueFocalPx = clip.camera.focalPx;
      row.trueDistanceM = clip.camera.distanceMm / 1000;
      row.walkerHeightPx = medianHeightPx(clip.px);
      row.framingOffsetOfHeight = framingOffsetOfHeight(clip);
      row.strides = clip.strides;
      const auto& prior = priors[static_cast<std::size_t>(job.fold)];
      const SnippetEngine snippet{prior, {}};
      reconstructClip(folds[static_cast<std::size_t>(job.fold)], w, clip, observed, confidence,
                      withBystander ? &other : nullptr, prior ? &snippet : nullptr, o,
                      j * static_cast<int>(levels) + static_cast<int>(l), row);
      if (o.snippet && !prior) row.snippet = failed(noPrior[static_cast<std::size_t>(job.fold)]);
    }
  });
  return rows;
}

namespace {

double medianOf(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

CameraSummary::Other summarizeOtherEngine(const std::vector<const CameraRow*>& rows,
                                          std::optional<EngineClipScore> CameraRow::*score) {
  CameraSummary::Other out;
  double sum = 0;
  for (const auto* r : rows) {
    const auto& s = r->*score;
    if (!s) continue;
    ++out.clips;
    if (!s->error.empty() || !std::isfinite(s->mpjpeMm)) {
      ++out.failures;
      continue;
    }
    sum += s->mpjpeMm;
  }
  out.meanMpjpeMm = out.clips > out.failures ? sum / (out.clips - out.failures) : std::nan("");
  return out;
}

}  // namespace

std::vector<CameraSummary> summarizeCamera(const std::vector<CameraRow>& rows) {
  std::map<double, std::vector<const CameraRow*>> byNoise;
  for (const auto& r : rows) byNoise[r.noisePx].push_back(&r);
  std::vector<CameraSummary> out;
  for (const auto& [noise, list] : byNoise) {
    CameraSummary s;
    s.noisePx = noise;
    s.clips = static_cast<int>(list.size());
    std::vector<double> alpha, elevation, focal, height;
    double mpjpe = 0;
    int within = 0;
    for (const auto* r : list) {
      if (!r->error.empty()) {
        ++s.failures;
        continue;
      }
      mpjpe += r->mpjpeMm;
      alpha.push_back(r->alphaErrorDeg);
      elevation.push_back(r->elevationErrorDeg);
      focal.push_back(r->focalRelError);
      height.push_back(r->heightRelError);
      within += r->heightRelError <= 0.05;
    }
    s.skeleton = summarizeOtherEngine(list, &CameraRow::skeleton);
    s.skeletonGuided = summarizeOtherEngine(list, &CameraRow::skeletonGuided);
    s.skeletonTable2 = summarizeOtherEngine(list, &CameraRow::skeletonTable2);
    s.skeletonEigenwalkerBones = summarizeOtherEngine(list, &CameraRow::skeletonEigenwalkerBones);
    s.snippet = summarizeOtherEngine(list, &CameraRow::snippet);
    const int ok = s.clips - s.failures;
    s.meanMpjpeMm = ok ? mpjpe / ok : std::nan("");
    s.medianAlphaErrorDeg = medianOf(alpha);
    s.medianElevationErrorDeg = medianOf(elevation);
    s.medianFocalRelError = medianOf(focal);
    s.medianHeightRelError = medianOf(height);
    s.heightWithin5Share = ok ? static_cast<double>(within) / ok : 0.0;
    out.push_back(s);
  }
  return out;
}

// [SECTION] The widened experiment

std::vector<CameraWideCondition> cameraWideConditions(const CameraExperimentOptions& base,
                                                      const std::vector<std::string>& factors) {
  const auto fast = [](CameraExperimentOptions& o) {
    o.minSpeedMps = 1.5;
    o.maxSpeedMps = 2.0;
    o.cadenceSpeedExponent = 0.5;
  };
  const auto hardest = [&](CameraExperimentOptions& o) {
    o.clipStrides = 1.2;
    o.walkerHeightPx = 120;
    fast(o);
    o.layout = ClipLayout::Coco17;
    o.fps = 25;
    o.maxElevationDeg = 35;
  };
  using Change = std::function<void(CameraExperimentOptions&)>;
  const std::vector<std::tuple<const char*, std::string, Change>> all = {
      {"base", "as the camera experiment", [](CameraExperimentOptions&) {}},
      {"length (strides)", "3", [](CameraExperimentOptions& o) { o.clipStrides = 3; }},
      {"length (strides)", "2", [](CameraExperimentOptions& o) { o.clipStrides = 2; }},
      {"length (strides)", "1.5", [](CameraExperimentOptions& o) { o.clipStrides = 1.5; }},
      {"length (strides)", "1.2", [](CameraExperimentOptions& o) { o.clipStrides = 1.2; }},
      {"height (px)", "400", [](CameraExperimentOptions& o) { o.walkerHeightPx = 400; }},
      {"height (px)", "240", [](CameraExperimentOptions& o) { o.walkerHeightPx = 240; }},
      {"height (px)", "160", [](CameraExperimentOptions& o) { o.walkerHeightPx = 160; }},
      {"height (px)", "120", [](CameraExperimentOptions& o) { o.walkerHeightPx = 120; }},
      {"speed (m/s)", "1.5-2.0", fast},
      {"layout", "COCO-17", [](CameraExperimentOptions& o) { o.layout = ClipLayout::Coco17; }},
      {"fps", "25", [](CameraExperimentOptions& o) { o.fps = 25; }},
      {"elevation (deg)", "0-35", [](CameraExperimentOptions& o) { o.maxElevationDeg = 35; }},
      {"elevation (deg)", "20-35", [](CameraExperimentOptions& o) {
         o.minElevationDeg = 20;
         o.maxElevationDeg = 35;
       }},
      {"image", "size known", [](CameraExperimentOptions& o) { o.imageSizeKnown = true; }},
      {"aim", "look-at 0-2 m high", [](CameraExperimentOptions& o) {
         o.minLookAtHeightMm = 0;
         o.maxLookAtHeightMm = 2000;
       }},
      {"aim", "look-at 0-2 m high, 1.2 strides", [](CameraExperimentOptions& o) {
         o.minLookAtHeightMm = 0;
         o.maxLookAtHeightMm = 2000;
         o.clipStrides = 1.2;
       }},
      {"focal", "known", [](CameraExperimentOptions& o) { o.focalKnown = true; }},
      {"focal", "known, 1.2 strides", [](CameraExperimentOptions& o) {
         o.focalKnown = true;
         o.clipStrides = 1.2;
       }},
      {"edge", "points off the picture dropped", [](CameraExperimentOptions& o) { o.offPictureDropped = true; }},
      {"edge", "points off the picture dropped, 1.2 strides", [](CameraExperimentOptions& o) {
         o.offPictureDropped = true;
         o.clipStrides = 1.2;
       }},
      // Read off a video, whose image's size is known too.
      {"horizon", "the scene's, read within 0.5 deg; image size known", [](CameraExperimentOptions& o) {
         o.imageSizeKnown = true;
         o.horizonReadSdDeg = 0.5;
       }},
      {"horizon", "the same, read 3 deg off (a ramp's lines)", [](CameraExperimentOptions& o) {
         o.imageSizeKnown = true;
         o.horizonReadSdDeg = 0.5;
         o.horizonReadBiasDeg = 3.0;
       }},
      {"hardest", "1.2 strides, 120 px, 1.5-2.0 m/s, COCO-17, 25 fps, 0-35 deg", hardest},
      {"hardest", "the same, image size known", [&](CameraExperimentOptions& o) {
         hardest(o);
         o.imageSizeKnown = true;
       }},
      {"hardest", "the same, focal length known", [&](CameraExperimentOptions& o) {
         hardest(o);
         o.focalKnown = true;
       }},
      {"hardest", "the same, points off the picture dropped", [&](CameraExperimentOptions& o) {
         hardest(o);
         o.offPictureDropped = true;
       }},
      {"hardest", "the same, image size known and the scene's horizon read within 0.5 deg", [&](CameraExperimentOptions& o) {
         hardest(o);
         o.imageSizeKnown = true;
         o.horizonReadSdDeg = 0.5;
       }},
  };
  const auto firstWord = [](const std::string& f) { return f.substr(0, f.find(' ')); };
  for (const auto& f : factors) {
    const bool known = std::any_of(all.begin(), all.end(), [&](const auto& c) { return firstWord(std::get<0>(c)) == f; });
    if (!known) badCameraOption("no factor '" + f + "' (length, height, speed, layout, fps, elevation, image, aim, focal, edge, horizon, hardest)");
  }
  std::vector<CameraWideCondition> out;
  for (const auto& [factor, level, change] : all) {
    const bool asked = factors.empty() || std::find(factors.begin(), factors.end(), firstWord(factor)) != factors.end();
    if (!asked && std::string(factor) != "base") continue;
    CameraWideCondition c{factor, level, base};
    change(c.options);
    out.push_back(std::move(c));
  }
  return out;
}

std::vector<CameraWideRow> cameraWideErrors(const std::vector<ExperimentWalker>& walkers,
                                            const std::vector<Fold>& folds,
                                            const std::vector<CameraWideCondition>& conditions) {
  std::vector<CameraWideRow> out;
  for (const auto& c : conditions)
    for (auto& row : cameraErrors(walkers, folds, c.options)) out.push_back({c.factor, c.level, std::move(row)});
  return out;
}

namespace {

// The share of clips whose error is within 1.96 of the SDs the fit gave (NaN SDs not counted).
struct WithinTwoSds {
  int within = 0, scored = 0;
  void add(double error, double sd) {
    if (!(std::isfinite(sd) && sd > 0.0 && std::isfinite(error))) return;
    ++scored;
    within += std::abs(error) <= 1.96 * sd;
  }
  double share() const { return scored > 0 ? static_cast<double>(within) / scored : std::nan(""); }
};

}  // namespace

std::vector<CameraWideSummary> summarizeCameraWide(const std::vector<CameraWideRow>& rows) {
  std::vector<CameraWideSummary> out;
  std::vector<std::vector<const CameraRow*>> groups;
  for (const auto& r : rows) {
    if (out.empty() || out.back().factor != r.factor || out.back().level != r.level) {
      out.push_back({r.factor, r.level});
      groups.emplace_back();
    }
    groups.back().push_back(&r.clip);
  }
  for (std::size_t g = 0; g < out.size(); ++g) {
    CameraWideSummary& s = out[g];
    std::vector<double> mpjpe, alpha, elevation, viewElevation, distance, height, strides;
    int elevationOver5 = 0, distanceOver20 = 0;
    WithinTwoSds stature, speed, stride, strideGivenStature, alphaSd, elevationSd, focalSd, distanceSd;
    for (const CameraRow* r : groups[g]) {
      ++s.clips;
      height.push_back(r->walkerHeightPx);
      strides.push_back(r->strides);
      if (!r->error.empty()) {
        ++s.refusals;
        continue;
      }
      mpjpe.push_back(r->mpjpeMm);
      alpha.push_back(r->alphaErrorDeg);
      elevation.push_back(r->elevationErrorDeg);
      viewElevation.push_back(r->viewElevationErrorDeg);
      distance.push_back(r->distanceRelError);
      stature.add(r->statureM - r->trueStatureM, r->statureSdM);
      speed.add(r->speedMps - r->trueSpeedMps, r->speedSdMps);
      stride.add(r->strideLengthM - r->trueStrideLengthM, r->strideLengthSdM);
      strideGivenStature.add(r->strideGivenStatureM - r->trueStrideLengthM, r->strideGivenStatureSdM);
      alphaSd.add(r->alphaErrorDeg, r->alphaSdDeg);
      elevationSd.add(r->elevationErrorDeg, r->elevationSdDeg);
      focalSd.add(r->focalRelError * r->trueFocalPx, r->focalSdPx);
      distanceSd.add(r->walkerDistanceM - r->trueWalkerDistanceM, r->walkerDistanceSdM);
      elevationOver5 += r->elevationErrorDeg > 5;
      distanceOver20 += r->distanceRelError > 0.2;
    }
    const double ok = static_cast<double>(mpjpe.size());
    s.meanMpjpeMm = ok > 0 ? std::accumulate(mpjpe.begin(), mpjpe.end(), 0.0) / ok : std::nan("");
    s.medianMpjpeMm = medianOf(mpjpe);
    s.medianAlphaErrorDeg = medianOf(alpha);
    s.medianElevationErrorDeg = medianOf(elevation);
    s.medianViewElevationErrorDeg = medianOf(viewElevation);
    s.medianDistanceRelError = medianOf(distance);
    s.elevationOver5Share = ok > 0 ? elevationOver5 / ok : std::nan("");
    s.distanceOver20Share = ok > 0 ? distanceOver20 / ok : std::nan("");
    s.statureWithin2SdShare = stature.share();
    s.speedWithin2SdShare = speed.share();
    s.strideWithin2SdShare = stride.share();
    s.strideGivenStatureWithin2SdShare = strideGivenStature.share();
    s.alphaWithin2SdShare = alphaSd.share();
    s.elevationWithin2SdShare = elevationSd.share();
    s.focalWithin2SdShare = focalSd.share();
    s.distanceWithin2SdShare = distanceSd.share();
    s.medianWalkerHeightPx = medianOf(height);
    s.medianStrides = medianOf(strides);
  }
  return out;
}

}  // namespace ew
