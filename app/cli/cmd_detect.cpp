// `eigenwalker-cli detect --video V [--model lite|full|heavy] --out DIR
//  [--format mediapipe-csv|openpose] [--first F] [--last L] [--person N] [--no-tiles]
//  [--no-cache] [--compare KEYPOINTS [--compare-offset K]] [--json]`: the built-in pose
// detector (video/pose_detector.h, docs/DETECTOR.md). DIR gets the keypoints other tools read —
// keypoints.csv (MediaPipe Pose CSV, the walker) or keypoints/ (OpenPose JSON, everybody, 33
// points each, person_id the followed person) — and detect.json (what was done and measured).
// --compare: the pixel distance per joint to another estimator's keypoints of the same video
// (its file n against video frame n + K), and the frames where left and right disagree.
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/cli/checks.h"
#include "app/cli/commands.h"
#include "app/cli/video_input.h"
#include "core/common/errors.h"
#include "core/io/atomic_write.h"
#include "core/keypoints/keypoint_layout.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/keypoints/keypoint_writers.h"
#include "core/tracking/keyframes.h"
#include "core/tracking/track_compare.h"
#include "video/detection_cache.h"

namespace ew::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct DetectArgs {
  std::string video, out, model = "full", format = "mediapipe-csv", compare;
  int first = 0, last = -1, compareOffset = 0;
  double smoothSeconds = 0.0;
  std::optional<int> person;
  bool noTiles = false, noCache = false, json = false, keepModelLabels = false;
};

// The joints compared: shoulders, elbows, wrists, knees, ankles; the hips apart (detectors
// disagree on where a hip is).
std::array<bool, kJointCount> limbJoints(bool hips) {
  std::array<bool, kJointCount> use{};
  for (Joint j : {Joint::RShoulder, Joint::RElbow, Joint::RWrist, Joint::LShoulder, Joint::LElbow, Joint::LWrist,
                  Joint::RKnee, Joint::RAnkle, Joint::LKnee, Joint::LAnkle})
    use[static_cast<std::size_t>(j)] = !hips;
  use[static_cast<std::size_t>(Joint::RHip)] = use[static_cast<std::size_t>(Joint::LHip)] = hips;
  return use;
}

// Frames where the detection's left and right are the reference's swapped: four or more of the
// six left/right joint pairs present in both (the reference sure of them), and the crossed
// pairing of those nearer than the straight one.
json leftRightAgreement(const Eigen::MatrixXd& ours, const Eigen::MatrixXd& reference) {
  constexpr std::array<std::pair<Joint, Joint>, 6> pairs = {{{Joint::RShoulder, Joint::LShoulder},
                                                             {Joint::RElbow, Joint::LElbow},
                                                             {Joint::RWrist, Joint::LWrist},
                                                             {Joint::RHip, Joint::LHip},
                                                             {Joint::RKnee, Joint::LKnee},
                                                             {Joint::RAnkle, Joint::LAnkle}}};
  const auto at = [](const Eigen::MatrixXd& m, Eigen::Index f, Joint j) {
    return Eigen::Vector2d(m(f, 2 * static_cast<int>(j)), m(f, 2 * static_cast<int>(j) + 1));
  };
  int compared = 0, swapped = 0;
  json swappedFrames = json::array();
  for (Eigen::Index f = 0; f < std::min(ours.rows(), reference.rows()); ++f) {
    double straight = 0.0, crossed = 0.0;
    int complete = 0;
    for (const auto& [r, l] : pairs) {
      const Eigen::Vector2d a = at(ours, f, r), b = at(ours, f, l), c = at(reference, f, r), d = at(reference, f, l);
      if (!a.allFinite() || !b.allFinite() || !c.allFinite() || !d.allFinite()) continue;
      ++complete;
      straight += (a - c).norm() + (b - d).norm();
      crossed += (a - d).norm() + (b - c).norm();
    }
    if (complete < 4) continue;
    ++compared;
    if (crossed < straight) {
      ++swapped;
      swappedFrames.push_back(f);
    }
  }
  return {{"frames_compared", compared}, {"frames_swapped", swapped}, {"swapped_frames", swappedFrames}};
}

json distanceJson(const TrackDistance& d, const std::array<bool, kJointCount>& joints) {
  json perJoint = json::object();
  for (int j = 0; j < kJointCount; ++j)
    if (joints[static_cast<std::size_t>(j)] && d.frames[static_cast<std::size_t>(j)] > 0)
      perJoint[std::string(kJointNames[static_cast<std::size_t>(j)])] = d.medianPx[static_cast<std::size_t>(j)];
  return {{"median_px", d.medianAllPx}, {"p95_px", d.p95AllPx}, {"joint_frames", d.jointFrames},
          {"median_px_per_joint", perJoint}};
}

// The detection against another estimator's keypoints of the same video.
json compareWith(const DetectArgs& a, const KeypointTrial& ours, const VideoInfo& info) {
  KeypointOptions k;
  k.fps = info.fps;
  k.imageSize = KeypointImageSize{info.widthPx, info.heightPx};
  Eigen::MatrixXd referencePx, surePx;
  if (isKeyframeFile(a.compare)) {
    // Marks by hand on some frames (docs/TRACKING.md's keyframe files): sure where they are.
    referencePx = Eigen::MatrixXd::Constant(std::max(info.frameCount, 1), kDims2, std::nan(""));
    for (const Keyframe& key : readKeyframes(a.compare).keyframes)
      if (key.frame >= 0 && key.frame < referencePx.rows()) referencePx.row(key.frame) = key.jointsPx;
    surePx = referencePx;
  } else {
    referencePx = readKeypointTrial(a.compare, k).jointsPx;
    // Sure: OpenPose's own threshold for a point it would draw.
    k.minConfidence = 0.5;
    surePx = readKeypointTrial(a.compare, k).jointsPx;
  }
  const Eigen::Index offset = a.compareOffset;
  if (offset < 0 || offset >= ours.jointsPx.rows())
    throw Error(ErrorKind::BadArgument, "--compare-offset", "", "must be within the video's frames");
  const Eigen::MatrixXd shifted = ours.jointsPx.bottomRows(ours.jointsPx.rows() - offset);
  const TrackDistance limbs = compareTracks(shifted, 0, referencePx, limbJoints(false));
  const TrackDistance hips = compareTracks(shifted, 0, referencePx, limbJoints(true));
  json report = {{"file", a.compare},
                 {"offset_frames", a.compareOffset},
                 {"limbs", distanceJson(limbs, limbJoints(false))},
                 {"hips", distanceJson(hips, limbJoints(true))},
                 {"left_right", leftRightAgreement(shifted, surePx)}};
  std::cout << std::fixed << std::setprecision(1) << "against " << a.compare << " (its frame n = video frame n + "
            << a.compareOffset << "): median " << limbs.medianAllPx << " px over shoulders, elbows, wrists, knees, "
            << "ankles (" << limbs.jointFrames << " joint-frames), hips " << hips.medianAllPx << " px; left/right swapped on "
            << report["left_right"]["frames_swapped"] << " of " << report["left_right"]["frames_compared"]
            << " frames where it is sure\n"
            << std::defaultfloat;
  return report;
}

void writeKeypoints(const DetectArgs& a, const KeypointFrames& frames, const KeypointTrial& trial) {
  if (a.format == "openpose") {
    writeOpenPoseJson(fs::path(a.out) / "keypoints", fs::path(a.video).stem().string(), frames);
    return;
  }
  const auto& walker = trial.people[static_cast<std::size_t>(trial.chosen)];
  const auto& first = frames.frames[static_cast<std::size_t>(walker.frames.front())];
  const int id = first[static_cast<std::size_t>(walker.detection.front())].trackId;
  writeMediaPipeCsv(fs::path(a.out) / "keypoints.csv", frames, id, keypointLayoutNamed("MediaPipe-33").points);
}

int runDetect(const DetectArgs& a) {
  PoseDetectionOptions o;
  o.model = parsePoseModelSize(a.model);
  o.tiles = !a.noTiles;
  o.fixLeftRight = !a.keepModelLabels;
  o.smoothSeconds = a.smoothSeconds;
  o.firstFrame = a.first;
  o.lastFrame = a.last;
  o.progress = detectionProgressOnStderr();
  bool fromCache = false;
  const PoseDetectionRun run = detectPosesCached(a.video, o, fromCache, !a.noCache);
  const KeypointFrames frames = keypointFramesOf(run);
  KeypointOptions k;
  if (a.person) k.person = *a.person - 1;
  const KeypointTrial trial = cleanKeypoints(frames, k);
  std::error_code ec;
  fs::create_directories(a.out, ec);
  if (ec) throw Error(ErrorKind::Io, a.out, "", "cannot create the folder: " + ec.message());
  writeKeypoints(a, frames, trial);
  const double frameCount = static_cast<double>(run.poses.size());
  const auto& walker = trial.people[static_cast<std::size_t>(trial.chosen)];
  json report = {{"video", a.video},
                 {"width_px", run.video.widthPx},
                 {"height_px", run.video.heightPx},
                 {"fps", run.video.fps},
                 {"frames", run.poses.size()},
                 {"first_frame", run.firstFrame},
                 {"model", poseModelSizeName(run.model)},
                 {"people_followed", run.people},
                 {"walker", {{"person", trial.chosen + 1}, {"reason", trial.chosenReason},
                             {"frames", walker.frames.size()}}},
                 {"left_right_swaps_undone", run.leftRightSwapsUndone},
                 {"from_cache", fromCache},
                 {"format", a.format},
                 {"warnings", trial.warnings}};
  if (!fromCache)
    report["timing_s"] = {{"total", run.totalSeconds}, {"decode", run.decodeSeconds},
                          {"landmarks", run.landmarkSeconds}, {"person_detector", run.personSeconds},
                          {"frames_per_s", frameCount / std::max(run.totalSeconds, 1e-9)}};
  std::cout << "detected " << run.people << " people in " << run.poses.size() << " frames of " << a.video
            << "; the walker: " << trial.chosenReason << "\n";
  if (!fromCache)
    std::cout << std::fixed << std::setprecision(1) << "time: " << run.totalSeconds << " s ("
              << frameCount / std::max(run.totalSeconds, 1e-9) << " frames/s; decode " << run.decodeSeconds
              << " s, landmarks " << run.landmarkSeconds << " s, person detector " << run.personSeconds << " s)\n"
              << std::defaultfloat;
  for (const auto& w : trial.warnings) std::cerr << "warning: " << w << "\n";
  if (!a.compare.empty()) report["compare"] = compareWith(a, trial, run.video);
  writeFileAtomically(fs::path(a.out) / "detect.json", [&](std::ostream& out) { out << report.dump(2) << "\n"; });
  if (a.json) std::cout << report.dump(2) << "\n";
  return 0;
}

}  // namespace

void addDetectCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<DetectArgs>();
  CLI::App* cmd = app.add_subcommand("detect", "Find people's keypoints in a video with the built-in pose detector");
  cmd->add_option("--video", args->video, "the video (MP4, AVI, MOV: what FFmpeg decodes)")->required();
  cmd->add_option("--out", args->out, "output folder")->required();
  cmd->add_option("--model", args->model, "BlazePose landmark model: lite, full (default) or heavy")
      ->check(CLI::IsMember({"lite", "full", "heavy"}));
  cmd->add_option("--format", args->format,
                  "mediapipe-csv: the walker as a MediaPipe Pose CSV (default); openpose: everybody as OpenPose JSON")
      ->check(CLI::IsMember({"mediapipe-csv", "openpose"}));
  cmd->add_option("--first", args->first, "first frame (default 0)")->check(kNonNegativeFinite);
  cmd->add_option("--last", args->last, "last frame (default the video's last)");
  cmd->add_option("--person", args->person, "the person to write as the walker (1-based; default: the one who walks)")
      ->check(kPositiveFinite);
  cmd->add_flag("--no-tiles", args->noTiles, "look for people in the whole frame only, not also in square tiles");
  cmd->add_option("--smooth", args->smoothSeconds,
                  "smooth each landmark's path over this many seconds, centred (no lag; default 0: none)")
      ->check(finiteIn(0.0, 2.0));
  cmd->add_flag("--keep-model-labels", args->keepModelLabels,
                "keep left and right as the landmark model labels each frame (no consistency through time)");
  cmd->add_flag("--no-cache", args->noCache, "detect again even when the detections of this video are cached");
  cmd->add_option("--compare", args->compare,
                  "measure the detections against another estimator's keypoints, or a keyframe file's marks");
  cmd->add_option("--compare-offset", args->compareOffset,
                  "with --compare: its frame n is the video's frame n + K (default 0)")
      ->check(kNonNegativeFinite);
  cmd->add_flag("--json", args->json, "print the report as JSON too");
  cmd->callback([args, &exitCode] { exitCode = runDetect(*args); });
}

}  // namespace ew::cli
