#include "video/track_study.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>
#include <unistd.h>

#include "core/engines/request.h"
#include "core/camera/clip_reconstruction.h"
#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/projection.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/tracking/track_compare.h"
#include "video/model_loop.h"
#include "video/synthetic_footage.h"

namespace ew {
namespace fs = std::filesystem;

namespace {

std::vector<ExperimentWalker> othersThan(const std::vector<ExperimentWalker>& walkers,
                                         const std::string& subject) {
  std::vector<ExperimentWalker> others;
  std::copy_if(walkers.begin(), walkers.end(), std::back_inserter(others),
               [&](const ExperimentWalker& w) { return w.subject != subject; });
  return others;
}

fs::path footageFolder(const TrackStudyOptions& o) {
  static std::atomic<int> counter{0};
  const fs::path base = o.scratchDir.empty() ? fs::temp_directory_path() : o.scratchDir;
  const fs::path dir = base / ("eigenwalker_track_study_" + std::to_string(::getpid()) + "_" +
                               std::to_string(counter++));
  fs::create_directories(dir);
  return dir;
}

}  // namespace

HeldOutSubject holdOut(const std::vector<ExperimentWalker>& walkers, const std::string& subject) {
  const auto held = std::find_if(walkers.begin(), walkers.end(),
                                 [&](const ExperimentWalker& w) { return w.subject == subject; });
  if (held == walkers.end())
    throw Error(ErrorKind::BadArgument, "--subjects", "", "no walker of subject '" + subject + "'");
  const std::vector<ExperimentWalker> others = othersThan(walkers, subject);
  if (others.size() < 2)
    throw Error(ErrorKind::BadArgument, "--subjects", "",
                "holding out '" + subject + "' leaves fewer than two walkers to build a model");
  return {*held, std::make_shared<const EigenwalkerModel>(buildFullModel(others))};
}

FilmedHeldOutWalker::FilmedHeldOutWalker(const HeldOutSubject& held, double azimuthDeg,
                                         const TrackStudyOptions& options)
    : options_(options), model_(held.model) {
  strideHz_ = held.walker.fit.omegaRadS / (2.0 * std::numbers::pi);
  alphaDeg_ = wrapDeg(90.0 - azimuthDeg);
  const int frames = static_cast<int>(std::ceil(options.strides / strideHz_ * options.fps)) + 1;
  times_ = frameTimes(frames, options.fps);
  inPlace_ = synthesizeFrames(held.walker.fit.w, held.walker.fit.omegaRadS, 0.0, times_);
  Eigen::MatrixXd walking = inPlace_;
  for (int f = 0; f < frames; ++f)
    for (int j = 0; j < kJointCount; ++j) walking(f, 3 * j + 1) += options.speedMmS * times_[f];
  dir_ = footageFolder(options);
  file_ = dir_ / "walk.avi";
  const FootageCamera camera = cameraBeside(walking, azimuthDeg, options.distanceMm);
  imageSize_ = {camera.widthPx, camera.heightPx};
  truthPx_ = writeFootage(file_, walking, camera, options.fps, options.footageSeed);
}

FilmedHeldOutWalker::~FilmedHeldOutWalker() {
  std::error_code ignored;
  fs::remove_all(dir_, ignored);
}

Keyframes FilmedHeldOutWalker::firstFrameMarked() const {
  return keyframesFromTrack(truthPx_, {0}, file_.string());
}

FilmedHeldOutWalker::Fit FilmedHeldOutWalker::fitToTruth() const {
  KeypointOptions atFps;
  atFps.fps = options_.fps;
  atFps.imageSize = imageSize_;  // as the track's fit knows it
  return fitOf(trialFromJoints(truthPx_, Eigen::MatrixXd::Ones(truthPx_.rows(), kJointCount),
                               file_.string(), "true 2D", atFps),
               false);
}

FilmedHeldOutWalker::Fit FilmedHeldOutWalker::fitToTrack(const JointTrack& track) const {
  return fitOf(keypointTrialOf(track, file_.string()), true);
}

FilmedHeldOutWalker::Fit FilmedHeldOutWalker::fitOf(const KeypointTrial& joints, bool tracked) const {
  CameraView view;
  view.keypoints = joints;
  view.strideFromTrunk = tracked;
  const EigenwalkerEngine engine{*model_, {Estimator::Map, options_.sigma2Mm2}, {}};
  const ClipReconstruction c = std::move(reconstruct(engine, {std::move(view)}).camera.eigenwalker->last);
  const Eigen::MatrixXd walk = synthesizeFrames(c.fit.w, c.fit.omegaRadS, c.fit.phaseRad, times_);
  return {mpjpeWithoutTranslation(walk, inPlace_), c.fit.camera.alphaDeg};
}

namespace {

// A fit, or NaNs with the refusal kept (the first one) in `error`.
template <typename Fitting>
FilmedHeldOutWalker::Fit fitOrRefusal(Fitting fit, std::string& error) {
  try {
    return fit();
  } catch (const Error& e) {
    if (error.empty()) error = e.what();
    return {kNaN, kNaN};
  }
}

TrackerOptions trackerOptions(const TrackStudyOptions& o) {
  TrackerOptions t;
  t.holdTheTrunk = o.holdTheTrunk;
  return t;
}

TrackStudyRow studyOne(const HeldOutSubject& held, double azimuthDeg, const TrackStudyOptions& o) {
  const FilmedHeldOutWalker walker(held, azimuthDeg, o);
  VideoSource video(walker.file());
  const ModelLoopResult looped =
      trackWithModel(video, walker.firstFrameMarked(), walker.model(), trackerOptions(o),
                     ModelLoopOptions{o.rounds});
  const TrackDistance d = compareTracks(looped.track.jointsPx, 0, walker.truthPx());
  TrackStudyRow row;
  row.subject = held.walker.subject;
  row.azimuthDeg = azimuthDeg;
  row.rounds = static_cast<int>(looped.rounds.size());
  row.frames = static_cast<int>(walker.truthPx().rows());
  row.medianPx = d.medianAllPx;
  row.p95Px = d.p95AllPx;
  row.jointMedianPx = d.medianPx;
  row.jointP95Px = d.p95Px;
  row.strideHz = walker.strideHz();
  row.error = looped.stoppedBecause;
  row.alphaDeg = walker.alphaDeg();
  const auto truth = fitOrRefusal([&] { return walker.fitToTruth(); }, row.error);
  const auto track = fitOrRefusal([&] { return walker.fitToTrack(looped.track); }, row.error);
  row.mpjpeTruthMm = truth.mpjpeMm;
  row.mpjpeTrackMm = track.mpjpeMm;
  row.alphaTruthFitDeg = truth.alphaDeg;
  row.alphaTrackFitDeg = track.alphaDeg;
  return row;
}

std::vector<std::string> subjectsOf(const std::vector<ExperimentWalker>& walkers,
                                    const TrackStudyOptions& o) {
  if (!o.subjects.empty()) return o.subjects;
  return walkerSubjects(walkers);
}

}  // namespace

std::vector<TrackStudyRow> runTrackStudy(const std::vector<ExperimentWalker>& walkers,
                                         const TrackStudyOptions& options,
                                         const TrackStudyProgress& progress) {
  if (options.azimuthsDeg.empty())
    throw Error(ErrorKind::BadArgument, "--azimuths", "", "no azimuth to film from");
  if (options.rounds < 0 || options.rounds > 10)
    throw Error(ErrorKind::BadArgument, "--model-loop", "", "rounds must be 0-10");
  const std::vector<std::string> subjects = subjectsOf(walkers, options);
  for (const std::string& s : subjects)
    if (std::none_of(walkers.begin(), walkers.end(),
                     [&](const ExperimentWalker& w) { return w.subject == s; }))
      throw Error(ErrorKind::BadArgument, "--subjects", "", "no walker of subject '" + s + "'");
  std::vector<TrackStudyRow> rows;
  const int total = static_cast<int>(subjects.size() * options.azimuthsDeg.size());
  for (const std::string& subject : subjects) {
    const HeldOutSubject held = holdOut(walkers, subject);  // one model for every view
    for (double azimuth : options.azimuthsDeg) {
      rows.push_back(studyOne(held, azimuth, options));
      if (progress) progress(rows.back(), static_cast<int>(rows.size()), total);
    }
  }
  return rows;
}

}  // namespace ew
