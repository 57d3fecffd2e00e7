// `eigenwalker-cli track --video V (--keyframes K.json | --keyframes-from KEYPOINTS
//  [--keyframe-frames 0,60]) --out DIR [--first F] [--last L] [--compare KEYPOINTS]
//  [--reconstruct WALK3D.csv] [--json]`: the joints followed through a video from keyframes
// (video/joint_tracker.h, docs/TRACKING.md). DIR gets the track as OpenPose BODY_25 JSON
// (keypoints/, one file a frame, other tools read it), as the project's 2D CSV
// (track_2d.csv: pixels, v up) with confidence.csv beside it, and track.json (what was done).
// --compare: the pixel distance per joint to another 2D source of the same clip (a pose
// estimator's detections). --reconstruct: the eigenwalker through the unknown camera
// (the `reconstruct --unknown-camera` path) from the track.
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include <opencv2/imgcodecs.hpp>
#include "app/cli/checks.h"
#include "app/cli/commands.h"
#include "app/cli/reconstruct_camera.h"
#include "core/common/errors.h"
#include "core/eigenwalker/default_model.h"
#include "core/io/atomic_write.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/tracking/keyframes.h"
#include "core/tracking/track_compare.h"
#include "core/tracking/track_confidence.h"
#include "video/joint_tracker.h"
#include "video/model_loop.h"
#include "video/track_files.h"
#include "video/track_overlay.h"

namespace ew::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct TrackArgs {
  std::string video, keyframes, keyframesFrom, out, compare, reconstruct, tracker = "flow";
  // --reconstruct: CameraArgs::sceneHorizon; "check", since a track's fit held to it moved its
  // focal length and distance away from the scene's (docs/CAMERA.md, "The scene's horizon").
  std::string sceneHorizon = "check";
  std::vector<int> keyframeFrames{0};
  int first = 0, last = -1;
  int overlayEvery = 0;  // 0: no overlay pictures
  int modelLoop = 0;     // rounds of the model loop (video/model_loop.h)
  bool json = false, keyframeFramesGiven = false, flattenBackground = false, holdTrunk = false;
  double withinPx = 12.0;  // --within: the share of joint-frames this near the --compare source
};

// The keyframes of `all` at `frames`; Error(BadArgument) naming the file for one it lacks.
Keyframes keyframesAt(const Keyframes& all, const std::vector<int>& frames,
                      const std::string& file) {
  Keyframes kept{all.video, {}};
  for (const Keyframe& k : all.keyframes)
    if (std::find(frames.begin(), frames.end(), k.frame) != frames.end())
      kept.keyframes.push_back(k);
  for (int f : frames)
    if (std::none_of(kept.keyframes.begin(), kept.keyframes.end(),
                     [&](const Keyframe& k) { return k.frame == f; }))
      throw Error(ErrorKind::BadArgument, file, "",
                  "--keyframe-frames: no keyframe on frame " + std::to_string(f));
  return kept;
}

// A keypoint file of the video: its rate and size are the video's (the size is what a
// MediaPipe CSV's or YOLO labels' fractions are of).
KeypointOptions keypointsOfTheVideo(const VideoInfo& info) {
  KeypointOptions k;
  k.fps = info.fps;
  k.imageSize = KeypointImageSize{info.widthPx, info.heightPx};
  return k;
}

Keyframes keyframesFor(const TrackArgs& a, const VideoInfo& info) {
  if (!a.keyframes.empty()) {
    const Keyframes all = readKeyframes(a.keyframes);
    return a.keyframeFramesGiven ? keyframesAt(all, a.keyframeFrames, a.keyframes) : all;
  }
  const KeypointOptions k = keypointsOfTheVideo(info);
  const KeypointTrial trial = readKeypointTrial(a.keyframesFrom, k);
  return keyframesFromTrack(trial.jointsPx, a.keyframeFrames, a.video);
}

json distanceJson(const TrackDistance& d) {
  json perJoint = json::object();
  for (int j = 0; j < kJointCount; ++j) {
    if (d.frames[j] == 0) continue;
    perJoint[std::string(kJointNames[j])] = {{"median_px", d.medianPx[j]},
                                              {"p95_px", d.p95Px[j]},
                                              {"share_within", d.shareWithin[j]},
                                              {"frames", d.frames[j]}};
  }
  return {{"median_px", d.medianAllPx},
          {"p95_px", d.p95AllPx},
          {"within_px", d.withinPx},
          {"share_within", d.shareWithinAll},
          {"joint_frames", d.jointFrames},
          {"per_joint", perJoint}};
}

void printDistance(const TrackDistance& d, const std::string& against) {
  std::cout << "distance to " << against << ": median " << std::fixed << std::setprecision(1)
            << d.medianAllPx << " px, 95th percentile " << d.p95AllPx << " px over "
            << d.jointFrames << " joint-frames, " << std::setprecision(0) << 100.0 * d.shareWithinAll
            << " % within " << std::setprecision(1) << d.withinPx << " px\n";
  for (int j = 0; j < kJointCount; ++j) {
    if (d.frames[j] == 0) continue;
    std::cout << "  " << std::left << std::setw(11) << kJointNames[j] << std::right << " median "
              << std::setw(6) << d.medianPx[j] << " px  p95 " << std::setw(6) << d.p95Px[j]
              << " px  within " << std::setprecision(0) << std::setw(3) << 100.0 * d.shareWithin[j]
              << " %  (" << d.frames[j] << " frames)\n" << std::setprecision(1);
  }
}

// What --compare measures against: a keypoint file's detections on every frame, or the
// marks of a keyframe file on its frames that are not the track's own keyframes (those
// are the marks themselves).
Eigen::MatrixXd referenceFor(const TrackArgs& a, const VideoInfo& info, const Keyframes& used) {
  if (!isKeyframeFile(a.compare)) return readKeypointTrial(a.compare, keypointsOfTheVideo(info)).jointsPx;
  Eigen::MatrixXd reference = Eigen::MatrixXd::Constant(info.frameCount, kDims2, std::nan(""));
  for (const Keyframe& k : readKeyframes(a.compare).keyframes) {
    const bool own = std::any_of(used.keyframes.begin(), used.keyframes.end(),
                                 [&](const Keyframe& u) { return u.frame == k.frame; });
    if (!own && k.frame < info.frameCount) reference.row(k.frame) = k.jointsPx;
  }
  return reference;
}

// Each fit of the model loop: how well it met the track it was fitted to, and the walk it saw.
json modelLoopJson(const ModelLoopResult& r, int asked) {
  json rounds = json::array();
  for (const ModelLoopRound& q : r.rounds)
    rounds.push_back({{"reprojection_rms_px", q.reprojectionRmsPx},
                      {"stride_hz", q.strideHz},
                      {"alpha_deg", q.alphaDeg},
                      {"hidden_joint_frames", q.hiddenJointFrames}});
  std::cout << "model loop: " << r.rounds.size() << " of " << asked << " rounds";
  for (const ModelLoopRound& q : r.rounds)
    std::cout << " [fit " << q.reprojectionRmsPx << " px, " << q.strideHz << " Hz, "
              << q.hiddenJointFrames << " joint-frames hidden]";
  if (!r.stoppedBecause.empty()) std::cout << "; stopped: " << r.stoppedBecause;
  std::cout << "\n";
  return {{"rounds_asked", asked}, {"rounds", rounds}, {"stopped_because", r.stoppedBecause}};
}

// Every n-th tracked frame with the track drawn over it (and the --compare source, blue).
void writeOverlays(VideoSource& video, const JointTrack& t, const Eigen::MatrixXd* referencePx,
                   int every, const fs::path& dir) {
  fs::create_directories(dir);
  const OverlayStyle reference{cv::Scalar(255, 128, 0), 1.0 / 300.0, false};
  for (Eigen::Index r = 0; r < t.jointsPx.rows(); r += every) {
    const int frame = t.firstFrame + static_cast<int>(r);
    cv::Mat image = video.frame(frame);
    if (referencePx && frame < referencePx->rows())
      drawTrack(image, referencePx->row(frame), Eigen::RowVectorXd(), reference);
    drawTrack(image, t.jointsPx.row(r), t.confidence.row(r));
    std::ostringstream name;
    name << "frame_" << std::setw(6) << std::setfill('0') << frame << ".png";
    if (!cv::imwrite((dir / name.str()).string(), image))
      throw Error(ErrorKind::Io, (dir / name.str()).string(), "",
                  "cannot write the overlay picture");
  }
}

int runTrack(const TrackArgs& a) {
  VideoSource video(a.video);
  const VideoInfo& info = video.info();
  const Keyframes keys = keyframesFor(a, info);
  // The keyframes' source is named for a mark or a frame the video does not have, not the video.
  const std::string keysFile = a.keyframes.empty() ? a.keyframesFrom : a.keyframes;
  checkKeyframesWithin(keys, info.frameCount, keysFile);
  checkMarksWithin(keys, info.widthPx, info.heightPx, keysFile);
  TrackerOptions o;
  o.kind = trackerFromName(a.tracker);
  o.firstFrame = a.first;
  o.lastFrame = a.last;
  o.flattenStaticBackground = a.flattenBackground;
  o.holdTheTrunk = a.holdTrunk;
  const auto start = std::chrono::steady_clock::now();
  if (a.modelLoop > 0 && o.kind != TrackerKind::OpticalFlow)
    throw Error(ErrorKind::BadArgument, "--model-loop", "",
                "the model loop guides the flow tracker only");
  if (o.holdTheTrunk && o.kind != TrackerKind::OpticalFlow)
    throw Error(ErrorKind::BadArgument, "--hold-trunk", "", "holds the flow tracker's joints only");
  ModelLoopOptions loop;
  loop.rounds = a.modelLoop;
  const ModelLoopResult looped = trackWithModel(video, keys, defaultRealModel(), o, loop);
  const JointTrack& track = looped.track;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  writeTrackFiles(a.out, track);
  const auto frames = track.jointsPx.rows();
  std::vector<int> keyframeFrames;
  for (const Keyframe& k : keys.keyframes) keyframeFrames.push_back(k.frame);
  const Eigen::VectorXd meanConfidence = track.confidence.rowwise().mean();
  const std::vector<int> leastSure = leastSureFrames(meanConfidence, track.firstFrame, keyframeFrames, 5,
                                                     std::max(1, static_cast<int>(frames) / 20));
  std::cout << "tracked " << frames << " frames (" << track.firstFrame << "-"
            << track.firstFrame + frames - 1 << ") of " << info.file << " (" << info.widthPx << "x"
            << info.heightPx << ", " << info.fps << " fps) from " << keys.keyframes.size()
            << " keyframe(s) by the " << trackerName(o.kind) << " tracker in " << std::fixed
            << std::setprecision(2) << seconds << " s (" << std::setprecision(1)
            << static_cast<double>(frames) / std::max(seconds, 1e-9) << " frames/s)\n";
  json leastSureJson = json::array();
  if (!leastSure.empty()) std::cout << "least sure frames (mean confidence; where to check):";
  for (const int f : leastSure) {
    const double c = meanConfidence(f - track.firstFrame);
    std::cout << " " << f << " (" << std::setprecision(2) << c << ")";
    leastSureJson.push_back({{"frame", f}, {"mean_confidence", c}});
  }
  if (!leastSure.empty()) std::cout << std::setprecision(1) << "\n";
  const std::vector<int> markNext = framesToMarkNext(track.jointsPx, track.firstFrame, keyframeFrames, 3);
  if (!markNext.empty()) std::cout << "frames to mark next (where marks cut the tracker's drift most, best first):";
  for (const int f : markNext) std::cout << " " << f;
  if (!markNext.empty()) std::cout << "\n";
  json report = {{"video", info.file},
                 {"tracker", trackerName(o.kind)},
                 {"background", track.background},
                 {"trunk_held", o.holdTheTrunk},
                 {"width_px", info.widthPx},
                 {"height_px", info.heightPx},
                 {"fps", info.fps},
                 {"first_frame", track.firstFrame},
                 {"frames", frames},
                 {"keyframes", keys.keyframes.size()},
                 {"seconds", seconds},
                 {"mean_confidence", track.confidence.mean()},
                 {"least_sure_frames", leastSureJson},
                 {"frames_to_mark_next", markNext}};
  if (a.modelLoop > 0) report["model_loop"] = modelLoopJson(looped, a.modelLoop);
  std::optional<Eigen::MatrixXd> referencePx;
  if (!a.compare.empty()) {
    referencePx = referenceFor(a, info, keys);
    const TrackDistance d = compareTracks(track.jointsPx, track.firstFrame, *referencePx, allJoints(), a.withinPx);
    printDistance(d, a.compare);
    report["compare"] = distanceJson(d);
    report["compare"]["file"] = a.compare;
  }
  if (a.overlayEvery > 0)
    writeOverlays(video, track, referencePx ? &*referencePx : nullptr, a.overlayEvery,
                  fs::path(a.out) / "overlay");
  writeFileAtomically(fs::path(a.out) / "track.json",
                      [&](std::ostream& out) { out << report.dump(2) << "\n"; });
  if (a.json) std::cout << report.dump(2) << "\n";
  if (a.reconstruct.empty()) return 0;
  // The track itself, as the viewer fits it: read back from the OpenPose files it would pass
  // through BODY_25's mapping and detector offsets, which are not what was tracked.
  CameraArgs c;
  c.input = info.file + " (tracked)";
  c.horizonVideo = info.file;
  c.sceneHorizon = a.sceneHorizon;
  c.out = a.reconstruct;
  c.modelName = defaultRealModelName();
  c.strideFromTrunk = true;
  return runReconstructCamera(defaultRealModel(), c, keypointTrialOf(track, info.file));
}

}  // namespace

void addTrackCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<TrackArgs>();
  CLI::App* cmd = app.add_subcommand(
      "track", "Follow a walker's joints through a video from keyframes marked by hand");
  cmd->add_option("--video", args->video, "the video (MP4, AVI, MOV: what FFmpeg decodes)")
      ->required();
  auto* keys = cmd->add_option("--keyframes", args->keyframes, "keyframe file (docs/TRACKING.md)");
  auto* from = cmd->add_option(
      "--keyframes-from", args->keyframesFrom,
      "take the keyframes from a keypoint file or folder (OpenPose, AlphaPose, MMPose, CSV)");
  keys->excludes(from);
  auto* keyframeFrames = cmd->add_option("--keyframe-frames", args->keyframeFrames,
                                         "which frames are keyframes (default: with --keyframes "
                                         "every keyframe of the file, with --keyframes-from 0)")
                             ->delimiter(',');
  cmd->add_option("--out", args->out, "output folder")->required();
  cmd->add_option("--tracker", args->tracker,
                  "flow: optical flow with keyframe patches (default); appearance: Zou et al. "
                  "2009's colour histograms of the segments' rectangles")
      ->check(CLI::IsMember({"flow", "appearance"}));
  cmd->add_option(
         "--model-loop", args->modelLoop,
         "rounds of the model loop: fit the eigenwalker through the unknown camera to the track, "
         "track again guided by it (flow tracker; default 0)")
      ->check(finiteIn(0, 10));
  cmd->add_option("--first", args->first, "first frame tracked (default 0)");
  cmd->add_option("--last", args->last, "last frame tracked (default the video's last)");
  cmd->add_option("--compare", args->compare,
                  "measure the track against another 2D source of the clip (keypoints), or a "
                  "keyframe file's marks on frames that are not keyframes of this track");
  cmd->add_option("--within", args->withinPx,
                  "with --compare, also the share of joint-frames within this many pixels of it "
                  "(default 12)")
      ->check(finiteIn(0.1, 10000.0));
  cmd->add_option("--reconstruct", args->reconstruct,
                  "also write the 3D walker (eigenwalker, unknown camera) here");
  cmd->add_option("--scene-horizon", args->sceneHorizon,
                  "with --reconstruct: the video's horizon, read off the scene's level lines "
                  "(docs/CAMERA.md, \"The scene's horizon\"): check (reported beside the fit's, "
                  "with a caution when they disagree), prior (the fit holds its camera's height to "
                  "it: on a track it can pull the focal length and distance away) or off")
      ->check(CLI::IsMember({"prior", "check", "off"}))
      ->capture_default_str();
  cmd->add_option("--overlay-every", args->overlayEvery,
                  "draw the track over every N-th frame into OUT/overlay/ (PNG)")
      ->check(kPositiveFinite);
  cmd->add_flag(
      "--flatten-background", args->flattenBackground,
      "flatten a fixed camera's still background before the flow, when the footage has one "
      "(docs/TRACKING.md, \"The still background\")");
  cmd->add_flag("--hold-trunk", args->holdTrunk,
                "hold the shoulders and hips to the pelvis-sternum line where their flow "
                "strays (a bare or plain upper body; flow tracker; docs/TRACKING.md, \"Holding the "
                "trunk\")");
  cmd->add_flag("--json", args->json, "print the report as JSON too");
  cmd->callback([args, &exitCode, keys, from, keyframeFrames] {
    args->keyframeFramesGiven = keyframeFrames->count() > 0;
    if (keys->count() == 0 && from->count() == 0)
      throw Error(ErrorKind::BadArgument, "", "",
                  "track needs --keyframes FILE or --keyframes-from KEYPOINTS");
    exitCode = runTrack(*args);
  });
}

}  // namespace ew::cli
