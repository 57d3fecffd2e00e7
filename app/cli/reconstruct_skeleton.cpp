#include "app/cli/reconstruct_skeleton.h"
#include "app/cli/video_input.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <nlohmann/json.hpp>

#include "app/cli/video_beside_keypoints.h"
#include "core/camera/calibration_file.h"
#include "core/camera/camera_knowledge.h"
#include "core/common/errors.h"
#include "core/common/statistics.h"
#include "core/gait/joint_angles.h"
#include "core/io/joint_csv.h"
#include "core/io/load_trial.h"
#include "core/io/trc_writer.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/camera/clip_reconstruction.h"
#include "core/camera/walk_camera.h"
#include "core/engines/request.h"
#include "core/eigenwalker/default_model.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/skeleton/bone_choice.h"
#include "core/skeleton/bone_sources.h"
#include "core/skeleton/scale_depth.h"
#include "core/skeleton/skeleton_camera.h"

namespace ew::cli {
namespace {

using nlohmann::json;

void require(bool given, const char* option, const std::string& why) {
  if (!given) throw Error(ErrorKind::BadArgument, option, "", why);
}

JointTrial readReference(const std::string& file) {
  const JointTrial t = mapRawTrial(readRawTrial(file), {});
  for (int j = 0; j < kJointCount; ++j)
    if (t.missing[static_cast<size_t>(j)])
      throw Error(ErrorKind::BadData, file, "", "the reference lacks the " + std::string(jointName(static_cast<Joint>(j))) +
                                                    ": every bone length is needed");
  return t;
}

json comparisonJson(const ReferenceComparison& c) {
  json perJoint = json::object();
  for (int j = 0; j < kJointCount; ++j)
    perJoint[std::string(jointName(static_cast<Joint>(j)))] = c.perJointMm[static_cast<size_t>(j)];
  json axes = json::array();
  for (int r = 0; r < 3; ++r) axes.push_back({c.referenceToWorld(r, 0), c.referenceToWorld(r, 1), c.referenceToWorld(r, 2)});
  return {{"frames", c.frames}, {"mpjpe_raw_mm", c.rawMm}, {"mpjpe_mean_translation_mm", c.meanTranslationMm},
          {"mpjpe_procrustes_mm", c.procrustesMm}, {"per_joint_mm", perJoint}, {"reference_to_world", axes}};
}

// The result's up: in a calibration's world the axis nearest the body's head-above-ankles
// direction (METHOD §2's rule); in a camera's frame that direction itself (the camera may be tilted).
void writeAngles(const SkeletonArgs& a, const Eigen::MatrixXd& framesMm, double rateHz, bool world) {
  const Eigen::Vector3d up = bodyUp(framesMm, world ? 90.0 : 0.0);
  std::ostringstream upText;
  upText << up.transpose();
  writeJointAngles(a.angles, jointAngles(framesMm, up, a.out), rateHz,
                   {"source=skeleton engine (Zou et al. 2009) of " + a.input, "angles=degrees",
                    "up=" + upText.str() + " (the reconstruction's frame)"});
  std::cerr << "wrote " << a.angles << "\n";
}


// [SECTION] The eigenwalker's fit of this walker: bones and a guide for the branches

struct EigenwalkerOfClip {
  BoneLengths bones;
  std::vector<JointMatrix> poses;  // the fitted walker in its camera's frame, per input frame
};

EigenwalkerOfClip eigenwalkerOf(const KeypointTrial& keypoints, const CameraKnowledge& camera, const std::string& name) {
  CameraView view{keypoints, camera, 0, false, {}, name};
  const EigenwalkerEngine engine{defaultRealModel(), CameraFitOptions().estimator, {}};
  const ClipReconstruction clip = std::move(reconstruct(engine, {std::move(view)}).camera.eigenwalker->last);
  EigenwalkerOfClip out{boneLengthsFromWalker(clip.fit.w, clip.fit.omegaRadS, name), {}};
  const Eigen::MatrixXd inCamera = walkInCameraFrame(clip.framesMm, clip.timesS, clip.fit.camera);
  for (Eigen::Index frame = 0; frame < inCamera.rows(); ++frame)
    out.poses.push_back(Eigen::Map<const JointMatrix>(inCamera.row(frame).eval().data()));
  std::cerr << std::fixed << std::setprecision(1) << "eigenwalker fit of " << name << ": azimuth "
            << clip.fit.camera.alphaDeg << " deg, focal " << clip.fit.camera.focalPx << " px, reprojection RMS "
            << clip.fit.reprojectionRmsPx << " px\n";
  return out;
}

// [SECTION] Where the bone lengths come from (core/skeleton/bone_choice.h)

ChosenBones bonesFor(const SkeletonArgs& a, const KeypointTrial& keypoints, const std::optional<JointTrial>& reference,
                     const std::optional<EigenwalkerOfClip>& fit) {
  BoneChoice choice;
  if (!a.bones.empty()) choice.source = parseBoneSource(a.bones, "--bones");
  if (a.statureM) choice.statureMm = 1000.0 * *a.statureM;
  choice.frame = a.boneFrame;
  choice.referenceBone = a.referenceBone;
  return chooseBones(choice, keypoints, reference ? &*reference : nullptr, a.reference,
                     fit ? std::optional<BoneLengths>(fit->bones) : std::nullopt);
}

// [SECTION] The camera

struct ChosenCamera {
  CalibratedCamera camera;
  json description;
};

// A pinhole with the principal point in the middle of the image, no distortion, no extrinsics.
CalibratedCamera plainPinhole(double focalPx, const std::string& imageSize) {
  const KeypointImageSize size = parseKeypointImageSize(imageSize, "--image-size");
  CalibratedCamera c;
  c.name = c.table = "pinhole";
  c.widthPx = size.width, c.heightPx = size.height;
  c.fxPx = c.fyPx = focalPx;
  c.cxPx = 0.5 * size.width, c.cyPx = 0.5 * size.height;
  return c;
}

std::array<Joint, 4> chainOf(const std::string& text) {
  std::array<Joint, 4> chain{};
  std::size_t from = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t comma = text.find(',', from);
    if ((k < 3) == (comma == std::string::npos))
      throw Error(ErrorKind::BadArgument, "--scale-depth-chain", "", "expects four joints a,b,c,d, e.g. sternum,r_shoulder,r_elbow,r_wrist");
    chain[k] = jointNamed(text.substr(from, comma == std::string::npos ? std::string::npos : comma - from), "--scale-depth-chain");
    from = comma + 1;
  }
  return chain;
}

ChosenCamera cameraFor(const SkeletonArgs& a, const KeypointTrial& keypoints, const BoneLengths& bones) {
  const bool scaleDepth = a.scaleDepthFrame.has_value() || !a.scaleDepthChain.empty();
  if (!a.camera.empty()) {
    if (a.focalPx || scaleDepth)
      throw Error(ErrorKind::BadArgument, "--camera", "", "the calibration gives the camera: --focal-px and --scale-depth-* do not apply");
    const CalibratedCamera c =
        readCalibratedCamera(a.camera, a.cameraName.empty() ? std::nullopt : std::optional<std::string>(a.cameraName));
    return {c, {{"source", "calibration"}, {"file", a.camera}, {"focal_px", c.focalPx()}}};
  }
  require(!a.imageSize.empty(), "--image-size",
          "without a calibration (--camera) the principal point is the middle of the image: give --image-size WxH");
  if (a.focalPx) {
    if (scaleDepth) throw Error(ErrorKind::BadArgument, "--focal-px", "", "a focal length given: --scale-depth-* do not apply");
    return {plainPinhole(*a.focalPx, a.imageSize), {{"source", "user"}, {"focal_px", *a.focalPx}}};
  }
  require(a.scaleDepthFrame.has_value() && !a.scaleDepthChain.empty(), "--scale-depth-frame",
          "the skeleton engine needs a camera: --camera FILE, --focal-px F, or Zou et al.'s scale-depth relation on a "
          "frame with --scale-depth-frame F --scale-depth-chain a,b,c,d (the outer two segments parallel to the image)");
  const CalibratedCamera middle = plainPinhole(1.0, a.imageSize);
  const ScaleDepthFocal f = focalFromScaleDepth(keypointFrame(keypoints, *a.scaleDepthFrame, "--scale-depth-frame"),
                                                middle.cxPx, middle.cyPx, chainOf(a.scaleDepthChain), bones, a.input);
  std::cerr << std::fixed << std::setprecision(1) << "scale-depth relation on frame " << *a.scaleDepthFrame << " ("
            << a.scaleDepthChain << "): depth step " << f.depthStepMm << " mm, focal length " << f.focalPx << " px\n";
  return {plainPinhole(f.focalPx, a.imageSize),
          {{"source", "scale-depth relation"}, {"frame", *a.scaleDepthFrame}, {"chain", a.scaleDepthChain},
           {"focal_px", f.focalPx}, {"depth_step_mm", f.depthStepMm},
           {"scales_mm_per_px", {f.nearScaleMmPerPx, f.farScaleMmPerPx}}}};
}

KeypointTrial readKeypoints(const SkeletonArgs& a) {
  KeypointOptions ko;
  if (!a.layout.empty()) ko.layout = a.layout;
  ko.fps = a.fps;
  if (a.person) ko.person = *a.person - 1;
  // Points given as fractions of the image (MediaPipe, YOLO) need its size.
  if (!a.imageSize.empty()) ko.imageSize = parseKeypointImageSize(a.imageSize, "--image-size");
  if (!isVideoFile(a.input)) takeTheVideoBeside(a.input, ko);
  return keypointTrialOf(a.input, ko, {a.detectModel});
}

std::optional<JointTrial> referenceFor(const SkeletonArgs& a) {
  if (a.reference.empty()) return std::nullopt;
  JointTrial reference = readReference(a.reference);
  if (a.fps && reference.rateHz > 0.0 && std::abs(reference.rateHz - *a.fps) > 1e-6 * *a.fps)
    throw Error(ErrorKind::BadArgument, a.reference, "--fps",
                "the reference is at " + std::to_string(reference.rateHz) + " Hz, the keypoints at --fps " +
                    std::to_string(*a.fps) + " Hz: frames would not correspond");
  return reference;
}

// The eigenwalker's fit, when the bones or the guide ask for it, with the focal length
// the calibration or the user gives (else it estimates its own).
std::optional<EigenwalkerOfClip> eigenwalkerIfAsked(const SkeletonArgs& a, const KeypointTrial& keypoints) {
  if (a.bones != "eigenwalker" && a.guide != "eigenwalker") return std::nullopt;
  CameraGivens given;
  given.focalPx = a.focalPx;
  given.calibrationFile = a.camera;
  if (!a.cameraName.empty()) given.calibrationCamera = a.cameraName;
  return eigenwalkerOf(keypoints, resolveCameraKnowledge(given), a.input);
}

}  // namespace

int runReconstructSkeleton(const SkeletonArgs& a) {
  // What is missing is said before any file is read.
  require(!a.camera.empty() || a.focalPx || a.scaleDepthFrame, "--camera",
          "the skeleton engine reconstructs through a pinhole camera: give --camera FILE (a Pose2Sim calibration), "
          "--focal-px F or --scale-depth-frame F with --image-size WxH; orthographic 2D views are scored by "
          "'evaluate --experiment snippet --engine skeleton'");
  require(!a.bones.empty() || !a.reference.empty(), "--reference",
          "the skeleton engine needs the bone lengths: give --reference FILE, a 3D trial of the same person, or "
          "--bones table2|eigenwalker|frame");
  const KeypointTrial keypoints = readKeypoints(a);
  sayKeypointWarnings(a.input, keypoints);
  const std::optional<JointTrial> reference = referenceFor(a);
  const std::optional<EigenwalkerOfClip> fit = eigenwalkerIfAsked(a, keypoints);
  const ChosenBones bones = bonesFor(a, keypoints, reference, fit);
  const ChosenCamera chosen = cameraFor(a, keypoints, bones.lengths);
  const CalibratedCamera& camera = chosen.camera;
  SkeletonEngine engine{bones.lengths, {}};
  if (fit && a.guide == "eigenwalker") engine.solve.guideMm = fit->poses;
  CameraView view;
  view.keypoints = keypoints;
  view.camera.calibration = camera;
  view.camera.focalPx = camera.focalPx();
  view.name = a.input;
  const ReconstructionResult result = reconstruct(engine, {std::move(view)});
  const SkeletonCameraResult& r = *result.camera.skeleton;
  const bool world = camera.hasExtrinsics;
  const std::string cameraText = a.camera.empty() ? "a pinhole of " + std::to_string(camera.focalPx()) + " px"
                                                  : "camera " + camera.name + " of " + a.camera;
  writeJointTrajectories(a.out, world ? r.worldMm : r.sequence.framesMm, keypoints.rateHz,
                {"skeleton engine (Zou et al. 2009) of " + a.input + " through " + cameraText,
                 world ? "frame: the calibration's world (mm)" : "frame: the camera's (x right, y down, z forward; mm)"});
  json report = {{"engine", "skeleton"}, {"input", a.input}, {"camera", camera.name}, {"frames", r.sequence.framesMm.rows()},
                 {"rate_hz", keypoints.rateHz}, {"clamped_bone_frames", r.sequence.clampedBoneFrames},
                 {"filled_points", r.filledPoints}, {"frame", world ? "world" : "camera"},
                 {"bones", bones.source}, {"camera_source", chosen.description},
                 {"guide", a.guide.empty() ? "none" : a.guide}, {"warnings", keypoints.warnings}};
  const double depthMm = median(r.rootDistanceMm);
  report["pelvis_distance_median_mm"] = depthMm;
  std::cerr << std::fixed << std::setprecision(1) << "skeleton: " << r.sequence.framesMm.rows() << " frames through "
            << camera.name << ", bones from " << bones.source << ", pelvis at " << depthMm << " mm (median), "
            << r.sequence.clampedBoneFrames << " clamped bone-frames, " << r.filledPoints << " joint-frames filled\n";
  if (world && reference) {
    const ReferenceComparison c = compareWithReference(r.worldMm, reference->positionsMm, a.reference);
    report["reference"] = comparisonJson(c);
    std::cerr << "against " << a.reference << " (" << c.frames << " frames): MPJPE " << c.rawMm << " mm as is, "
              << c.meanTranslationMm << " mm without the mean translation, " << c.procrustesMm
              << " mm after Procrustes\n";
  } else if (!world) {
    std::cerr << "no extrinsics: the result stays in the camera's frame" << (reference ? " and is not scored" : "") << "\n";
  }
  std::cerr << "wrote " << a.out << "\n";
  if (!a.angles.empty()) writeAngles(a, world ? r.worldMm : r.sequence.framesMm, keypoints.rateHz, world);
  if (a.json) std::cout << report.dump(2) << "\n";
  return 0;
}

}  // namespace ew::cli
