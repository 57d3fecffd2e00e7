#include "app/cli/reconstruct_camera.h"
#include "app/cli/video_input.h"
#include "core/camera/detection_loop.h"
#include "core/engines/request.h"
#include "core/tracking/corrected_track.h"
#include "core/tracking/keyframes.h"

#include <cmath>
#include <numbers>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli/video_beside_keypoints.h"
#include "core/camera/camera_knowledge.h"
#include "core/camera/clip_reconstruction.h"
#include "core/camera/detector_offsets.h"
#include "core/camera/lens_distortion.h"
#include "core/common/errors.h"
#include "core/common/json_number.h"
#include "core/eigenwalker/model_file.h"
#include "core/io/joint_csv.h"
#include "core/io/trc_writer.h"
#ifdef EW_HAVE_VIDEO
#include "video/scene_horizon.h"
#endif

namespace ew::cli {
namespace {

using nlohmann::json;

// " ± 0.05" for a measured SD (two decimals, as the values beside it), "" for null.
std::string plusMinus(const json& sd, int decimals = 2) {
  if (!sd.is_number() || sd.get<double>() == 0.0) return "";  // none, or given (a known stature)
  char text[40];
  std::snprintf(text, sizeof text, " ± %.*f", decimals, sd.get<double>());
  return text;
}

json startsJson(const CameraFit& fit) {
  json out = json::array();
  for (const auto& s : fit.starts) {
    out.push_back({{"start_alpha_deg", s.startAlphaDeg},
                   {"alpha_deg", s.alphaDeg},
                   {"elevation_deg", s.elevationDeg},
                   {"objective", s.objective},
                   {"reprojection_rms_px", s.reprojectionRmsPx},
                   {"speed_mps", s.speedMmS / 1000.0},
                   {"iterations", s.iterations}});
  }
  return out;
}

// The offsets the fit allowed for, per joint that has one.
json offsetsJson(const JointOffsetsMm& offsets) {
  json out = json::object();
  for (int j = 0; j < kJointCount; ++j) {
    const auto& o = offsets[static_cast<std::size_t>(j)];
    if (o[0] != 0.0 || o[1] != 0.0 || o[2] != 0.0)
      out[std::string(jointName(static_cast<Joint>(j)))] = o;
  }
  return out;
}

json reportJson(const CameraArgs& a, const CameraKnowledge& camera, const KeypointTrial& t, const CameraFit& fit) {
  const WalkCamera& c = fit.camera;
  const bool pinhole = c.model == CameraModel::Pinhole;
  std::vector<std::string> unseen;
  for (int j : fit.unseenJoints) unseen.emplace_back(jointName(static_cast<Joint>(j)));
  return {{"input", a.input},
          {"format", t.format},
          {"layout", t.layout->name},
          {"layout_source", t.layoutSource},
          {"person", t.chosenReason},
          {"frames", t.frameCount},
          {"rate_hz", t.rateHz},
          {"rate_assumed", t.rateAssumed},
          {"output", a.out},
          {"camera_model", pinhole ? "pinhole" : "scaled orthographic"},
          {"alpha_deg", c.alphaDeg},
          {"alpha_source", camera.alphaSource},
          {"elevation_deg", c.elevationDeg},
          {"view_elevation_deg", fit.viewElevationDeg},
          {"elevation_source", camera.elevationSource},
          {"focal_px", pinhole ? json(c.focalPx) : json(nullptr)},
          {"focal_source", pinhole ? json(camera.focalSource) : json(nullptr)},
          {"alpha_sd_deg", finiteOrNull(fit.sd.alphaDeg)},
          {"elevation_sd_deg", finiteOrNull(fit.sd.elevationDeg)},
          {"focal_sd_px", finiteOrNull(fit.sd.focalPx)},
          {"distance_m", pinhole ? json(c.distanceMm / 1000.0) : json(nullptr)},
          {"walker_distance_m", finiteOrNull(fit.walkerDistanceM)},
          {"walker_distance_sd_m", finiteOrNull(fit.sd.walkerDistanceM)},
          {"walker_distance_first_m", finiteOrNull(fit.walkerDistanceFirstM)},
          {"walker_distance_last_m", finiteOrNull(fit.walkerDistanceLastM)},
          {"px_per_mm", pinhole ? json(nullptr) : json(c.pxPerMm)},
          {"image_centre_px", {c.cxPx, c.cyPx}},
          {"reprojection_rms_px", fit.reprojectionRmsPx},
          {"outlier_samples", fit.outlierSamples},
          {"stride_hz", fit.strideHz},
          {"cadence_steps_per_min", fit.cadenceStepsPerMin},
          {"walking_in_place", fit.inPlace},
          {"speed_mps", fit.speedMps},
          {"speed_source", fit.inPlace ? "the stance feet (walking in place: a treadmill's belt)" : "the walker's progression"},
          {"stride_length_m", fit.strideLengthM},
          {"head_height_m", fit.headHeightMm / 1000.0},
          {"stature_m", fit.statureMm / 1000.0},
          {"speed_sd_mps", finiteOrNull(fit.sd.speedMps)},
          {"stride_length_sd_m", finiteOrNull(fit.sd.strideLengthM)},
          {"stature_sd_m", finiteOrNull(fit.sd.statureMm / 1000.0)},
          {"stature_source", camera.statureSource},
          {"k", std::vector<double>(fit.k.data(), fit.k.data() + fit.k.size())},
          {"joints_model_estimated", unseen},
          {"minima", startsJson(fit)},
          {"detector_offsets_mm", offsetsJson(t.detectorOffsetMm)}};
}

void printSummary(const json& r) {
  std::cerr << std::fixed << std::setprecision(1) << r["format"].get<std::string>() << ", layout "
            << r["layout"].get<std::string>() << " (" << r["layout_source"].get<std::string>()
            << "); " << r["person"].get<std::string>() << "\n";
  std::cerr << "camera (" << r["camera_model"].get<std::string>() << "): azimuth "
            << r["alpha_deg"].get<double>() << plusMinus(r["alpha_sd_deg"], 1) << " deg, elevation "
            << r["elevation_deg"].get<double>() << plusMinus(r["elevation_sd_deg"], 1) << " deg (the walker seen from "
            << std::abs(r["view_elevation_deg"].get<double>()) << " deg "
            << (r["view_elevation_deg"].get<double>() >= 0.0 ? "above" : "below") << ")";
  if (r["walker_distance_m"].is_number())
    std::cerr << ", the walker " << std::setprecision(1) << r["walker_distance_first_m"].get<double>() << " to "
              << r["walker_distance_last_m"].get<double>() << " m away (mean " << std::setprecision(2)
              << r["walker_distance_m"].get<double>() << plusMinus(r["walker_distance_sd_m"]) << " m), focal "
              << std::setprecision(0) << r["focal_px"].get<double>() << plusMinus(r["focal_sd_px"], 0) << " px ("
              << r["focal_source"].get<std::string>() << ")";
  if (r["camera_model"] == "pinhole")
    std::cerr << ", principal point prior: " << r["principal_point_prior"].get<std::string>();
  std::cerr << "; reprojection RMS " << std::setprecision(2)
            << r["reprojection_rms_px"].get<double>() << " px";
  if (r["outlier_samples"].get<int>() > 0)
    std::cerr << " (" << r["outlier_samples"].get<int>()
              << " samples rejected as detector glitches)";
  std::cerr << "\n";
  std::cerr << "walk: stride " << std::setprecision(3) << r["stride_hz"].get<double>() << " Hz ("
            << std::setprecision(0) << r["cadence_steps_per_min"].get<double>()
            << " steps/min), " << (r["walking_in_place"].get<bool>() ? "walking in place (a treadmill), belt speed " : "speed ")
            << std::setprecision(2) << r["speed_mps"].get<double>() << plusMinus(r["speed_sd_mps"])
            << " m/s" << (r["walking_in_place"].get<bool>() ? " from the stance feet" : "") << ", stride length "
            << r["stride_length_m"].get<double>() << plusMinus(r["stride_length_sd_m"]) << " m, head height "
            << r["head_height_m"].get<double>() << " m (stature about " << r["stature_m"].get<double>()
            << plusMinus(r["stature_sd_m"]) << " m)";
  if (r["stride_length_sd_m"].is_number() || r["stature_sd_m"].is_number())
    std::cerr << "; ± one SD of the fit (docs/CAMERA.md, \"How sure the fit is\")";
  if (r["rate_assumed"].get<bool>())
    std::cerr << " (at an assumed " << r["rate_hz"].get<double>() << " fps: give --fps)";
  // Said when the trunk stood in for feet that read another stride (a view from the front).
  if (r.contains("stride_source") && r["stride_source"].get<std::string>().starts_with("trunk"))
    std::cerr << "\nstride from the " << r["stride_source"].get<std::string>();
  if (r.contains("feet") && r["feet"]["samples_seen"].get<int>() > 0)
    std::cerr << "\nfeet: " << r["feet"]["note"].get<std::string>()
              << (r["feet"]["written"].get<bool>() ? "" : " (written to a .c3d output only)");
  if (r["scene_horizon"].is_object() && r["scene_horizon"]["row_px"].is_number())
    std::cerr << "\nscene: its level lines put the horizon at row " << std::setprecision(0)
              << r["scene_horizon"]["row_px"].get<double>() << " px (" << r["scene_horizon"]["frames_agreeing"].get<int>()
              << " of " << r["scene_horizon"]["frames_read"].get<int>() << " frames), the fitted camera at row "
              << r["scene_horizon"]["fit_row_px"].get<double>() << " px"
              << (r["scene_horizon"]["used_as_prior"].get<bool>() ? " (the fit held to the scene's)" : "");
  for (const auto& caution : r["cautions"]) std::cerr << "\ncaution: " << caution.get<std::string>();
  std::cerr << "\nwrote " << r["output"].get<std::string>() << "\n";
}

// The horizon read off a video's own level lines (video/scene_horizon.h), before the fit that
// may hold to it; nothing for a keypoint file, a camera without a horizon (scaled orthography,
// a held elevation) or --scene-horizon off.
struct SceneHorizonReading {
  bool read = false;
  std::optional<double> rowPx;  // the horizon's row, when found
  json found;                   // what was found: the vanishing point, the frames agreeing …
  std::string why;              // … or why none was
};

SceneHorizonReading readSceneHorizon(const CameraArgs& a, const CameraKnowledge& camera) {
  SceneHorizonReading r;
#ifdef EW_HAVE_VIDEO
  const bool pinhole = camera.focalPx || camera.estimateFocal;
  const std::string& video = a.horizonVideo.empty() ? a.input : a.horizonVideo;
  if (!isVideoFile(video) || a.sceneHorizon == "off" || !pinhole || camera.elevationDeg) return r;
  r.read = true;
  const std::optional<SceneHorizon> h = sceneHorizonOf(video, kSceneHorizonFrames, r.why);
  if (!h) return r;
  r.rowPx = h->rowPx;
  r.found = {{"row_px", h->rowPx},
             {"vanishing_point_px", {h->vanishingPointPx.x(), h->vanishingPointPx.y()}},
             {"row_spread_px", h->rowSpreadPx},
             {"frames_agreeing", h->framesAgreeing},
             {"frames_read", h->framesRead}};
#else
  (void)a, (void)camera;
#endif
  return r;
}

// The scene's horizon beside the fitted camera's, and a caution when they disagree; null when
// not read.
json sceneHorizonJson(const SceneHorizonReading& reading, bool usedAsPrior, const CameraFit& fit,
                      std::vector<std::string>& cautions) {
  if (!reading.read || fit.camera.model != CameraModel::Pinhole) return nullptr;
  if (!reading.rowPx) return {{"row_px", nullptr}, {"why_none", reading.why}};
  const double row = *reading.rowPx;
  const double fitRow = horizonRowPx(fit.camera);
  const double offDeg = horizonOffDeg(fit.camera, row);
  if (std::string caution = sceneHorizonCaution(fit, row, usedAsPrior); !caution.empty())
    cautions.push_back(std::move(caution));
  json out = reading.found;
  out["used_as_prior"] = usedAsPrior;
  out["fit_row_px"] = fitRow;
  out["fit_off_deg"] = offDeg;
  return out;
}

// What the command line says of the camera (core/camera/camera_knowledge.h).
CameraKnowledge cameraKnowledgeOf(const CameraArgs& a) {
  CameraGivens g;
  g.focalPx = a.focalPx;
  g.calibrationFile = a.camera;
  if (!a.cameraName.empty()) g.calibrationCamera = a.cameraName;
  if (!a.imageSize.empty()) g.imageSize = parseKeypointImageSize(a.imageSize, "--image-size");
  g.alphaDeg = a.alphaDeg;
  g.elevationDeg = a.elevationDeg;
  g.orthographic = a.orthographic;
  if (a.statureM) g.statureMm = 1000.0 * *a.statureM;
  CameraKnowledge k = resolveCameraKnowledge(g);
  if (k.calibration)
    std::cerr << "camera " << k.calibration->name << " of " << a.camera << ": focal " << *k.focalPx << " px\n";
  return k;
}

EstimatorOptions estimatorOf(const EigenwalkerModel& model, const CameraArgs& a) {
  return {a.method == "map" ? Estimator::Map : Estimator::Lsq, a.sigma2Mm2.value_or(defaultSigma2Mm2(model))};
}

// A calibrated camera's lens distortion taken out of the keypoints (core/camera/lens_distortion.h).
json undistorted(const CameraArgs& a, const CameraKnowledge& camera, KeypointTrial& t) {
  const std::optional<int> lost = undistortKeypoints(camera, t);
  if (!lost) return nullptr;
  const CalibratedCamera& c = *camera.calibration;
  std::cerr << "keypoints undistorted with " << a.camera << " [" << c.table << "] (k1 "
            << c.distortions[0] << ", k2 " << c.distortions[1] << ", p1 " << c.distortions[2]
            << ", p2 " << c.distortions[3] << ")";
  if (*lost > 0) std::cerr << "; " << *lost << " points outside the calibrated field dropped";
  std::cerr << "\n";
  return {{"k1_k2_p1_p2", c.distortions}, {"points_dropped", *lost}};
}

// The keypoints corrected by hand (a keyframe file): the track redone around each correction
// (core/tracking/corrected_track.h); a corrected joint is as sure as can be.
void applyCorrections(const std::string& file, KeypointTrial& t) {
  const Keyframes keys = readKeyframes(file);
  if (t.imageSize) checkMarksWithin(keys, t.imageSize->width, t.imageSize->height, file);
  const int span = correctTrial(t, keys);
  std::cerr << "corrections from " << file << ": " << keys.keyframes.size() << " frames, each carried over "
            << span << " frames either side\n";
}

// The model loop's rounds: as asked, else one for a video's detections (whose confidences say
// where the detector is unsure), none for a keypoint file.
int modelLoopRounds(const CameraArgs& a) { return a.modelLoop.value_or(isVideoFile(a.input) ? 1 : 0); }

json modelLoopJson(const DetectionLoop& loop, const DetectionLoopOptions& o) {
  if (o.rounds == 0) return {{"rounds", 0}};
  return {{"rounds", o.rounds},
          {"sure_confidence", o.sureConfidence},
          {"unsure_joint_frames", loop.unsureJointFrames},
          {"reprojection_rms_on_sure_px_before", loop.firstRmsOnSurePx},
          {"reprojection_rms_on_sure_px_after", loop.lastRmsOnSurePx},
          {"before", {{"alpha_deg", loop.first.fit.camera.alphaDeg},
                      {"reprojection_rms_px", loop.first.fit.reprojectionRmsPx},
                      {"stature_m", loop.first.fit.statureMm / 1000.0}}}};
}

// [first, last] frames where the walker has a seen joint; the whole clip when none.
std::pair<Eigen::Index, Eigen::Index> seenSpan(const Eigen::MatrixXd& jointsPx) {
  Eigen::Index first = -1, last = -1;
  for (Eigen::Index r = 0; r < jointsPx.rows(); ++r) {
    if (!jointsPx.row(r).array().isFinite().any()) continue;
    if (first < 0) first = r;
    last = r;
  }
  if (first < 0) return {0, jointsPx.rows() - 1};
  return {first, last};
}

// The eigenwalker through the camera (reconstruct(engine, request), core/engines/request.h),
// written and reported.
int fitAndReport(const EigenwalkerModel& model, const CameraArgs& a, KeypointTrial keypoints,
                 CameraKnowledge camera, const json& lens, const json& imageSizeFrom = nullptr,
                 CameraFit* fitOut = nullptr) {
  sayKeypointWarnings(a.input, keypoints);
  const SceneHorizonReading horizon = readSceneHorizon(a, camera);
  const bool horizonPrior = horizon.rowPx && a.sceneHorizon == "prior";
  if (horizonPrior) camera.horizonRowPx = horizon.rowPx;
  DetectionLoopOptions loopOptions;
  loopOptions.rounds = modelLoopRounds(a);
  const CameraFitOptions o = cameraFitOptions(camera, estimatorOf(model, a), a.input);
  CameraView view{std::move(keypoints), camera, loopOptions.rounds, a.strideFromTrunk, {}, a.input};
  const ReconstructionResult r = reconstruct(EigenwalkerEngine{model, o.estimator, {}}, {std::move(view)});
  const DetectionLoop& loop = *r.camera.eigenwalker;
  const ClipReconstruction& clip = loop.last;
  const KeypointTrial& t = clip.trial;
  const CameraFit& fit = clip.fit;
  const Eigen::MatrixXd& frames = clip.framesMm;
  std::ostringstream what;
  what << "eigenwalker reconstruction of " << a.input << " through an unknown camera (azimuth "
       << fit.camera.alphaDeg << " deg, elevation " << fit.camera.elevationDeg << " deg), model "
       << a.modelName;
  std::vector<std::string> notes = {what.str()};
  if (clip.feet.pointsSeen > 0) notes.push_back("feet: " + clip.feet.note);
  const auto [first, last] = a.seenFramesOnly ? seenSpan(t.jointsPx) : std::pair<Eigen::Index, Eigen::Index>{0, frames.rows() - 1};
  const Eigen::Index n = last - first + 1;
  if (a.seenFramesOnly)
    notes.push_back("frames " + std::to_string(first) + "-" + std::to_string(last) + " of the clip: where the walker is seen");
  const Eigen::MatrixXd feet = clip.feet.feetMm.size() ? Eigen::MatrixXd(clip.feet.feetMm.middleRows(first, n)) : Eigen::MatrixXd();
  writeJointTrajectories(a.out, frames.middleRows(first, n), t.rateHz, notes, feet, true);
  json report = reportJson(a, camera, t, fit);
  report["warnings"] = t.warnings;
  if (t.sternumFromShoulders) {  // allowed for by the fit (core/camera/detector_offsets.h)
    const Eigen::Vector3d sternum = sternumAsShouldersMidpointOffsetMm(model);
    report["detector_offsets_mm"]["sternum"] = {sternum.x(), sternum.y(), sternum.z()};
  }
  report["feet"] = {{"samples_seen", clip.feet.pointsSeen},
                    {"samples_lifted", clip.feet.pointsLifted},
                    {"written", clip.feet.pointsLifted > 0 && writesC3d(a.out)},
                    {"note", clip.feet.note}};
  json residuals = json::object();
  for (int j = 0; j < kJointCount; ++j)
    if (std::isfinite(clip.residualRmsPx[static_cast<std::size_t>(j)]))
      residuals[std::string(jointName(static_cast<Joint>(j)))] = clip.residualRmsPx[static_cast<std::size_t>(j)];
  report["residual_rms_px_per_joint"] = residuals;
  report["model_loop"] = modelLoopJson(loop, loopOptions);
  report["lens_undistorted"] = lens;
  report["stride_source"] = clip.strideSource;
  report["principal_point_prior"] = principalPointPrior(o, t);
  report["image_size_px"] = t.imageSize ? json{t.imageSize->width, t.imageSize->height} : json(nullptr);
  report["image_size_from"] = t.imageSize ? imageSizeFrom : json(nullptr);
  report["rate_from"] = t.rateSource;
  std::vector<std::string> cautions = clip.cautions;
  report["scene_horizon"] = sceneHorizonJson(horizon, horizonPrior, fit, cautions);
  report["cautions"] = cautions;
  printSummary(report);
  if (a.json) std::cout << report.dump(2) << "\n";
  if (fitOut) *fitOut = fit;
  return 0;
}

}  // namespace

int runReconstructCamera(const EigenwalkerModel& model, const CameraArgs& a, CameraFit* fitOut) {
  const CameraKnowledge camera = cameraKnowledgeOf(a);
  KeypointOptions k;
  if (!a.layout.empty()) k.layout = a.layout;
  if (!a.mapping.empty()) k.mappingFile = a.mapping;
  k.imageSize = camera.imageSize;
  k.fps = a.fps;
  k.detectorOffsets = a.detectorOffsets;
  if (a.person) k.person = *a.person - 1;
  // A video is its own: the built-in detector finds the walker's keypoints in it.
  if (!isVideoFile(a.input)) takeTheVideoBeside(a.input, k);
  KeypointTrial keypoints = keypointTrialOf(a.input, k, {a.detectModel});
  if (!a.corrections.empty()) applyCorrections(a.corrections, keypoints);
  const json imageSizeFrom = camera.imageSizeFromCalibration ? json(camera.imageSizeSource) : json(keypoints.imageSizeSource);
  const json lens = undistorted(a, camera, keypoints);
  return fitAndReport(model, a, std::move(keypoints), camera, lens, imageSizeFrom, fitOut);
}

int runReconstructCamera(const EigenwalkerModel& model, const CameraArgs& a, KeypointTrial joints) {
  const CameraKnowledge camera = cameraKnowledgeOf(a);
  const json lens = undistorted(a, camera, joints);
  return fitAndReport(model, a, std::move(joints), camera, lens);
}

}  // namespace ew::cli
