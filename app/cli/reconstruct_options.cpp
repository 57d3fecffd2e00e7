// `reconstruct`'s options: their CLI11 bindings, and which of the command's routes takes
// each (one table, checkOptionsApply, instead of refusals in every runner).
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "app/cli/checks.h"
#include "app/cli/reconstruct_args.h"
#include "app/cli/video_input.h"
#include "core/common/errors.h"
#include "core/keypoints/keypoint_frames.h"

namespace ew::cli {

namespace {

using Route = ReconstructRoute;

constexpr unsigned bit(Route r) { return 1u << static_cast<unsigned>(r); }
constexpr unsigned kView = bit(Route::EigenwalkerView), kCamera = bit(Route::EigenwalkerCamera),
                   kSnippet = bit(Route::Snippet), kSkeleton = bit(Route::Skeleton);
constexpr unsigned kEigenwalker = kView | kCamera, kKeypoints = kCamera | kSkeleton;

const char* routeName(Route r) {
  switch (r) {
    case Route::EigenwalkerView: return "the eigenwalker on a 2D view in mm";
    case Route::EigenwalkerCamera: return "the eigenwalker through a real camera (--unknown-camera)";
    case Route::Snippet: return "--engine snippet";
    case Route::Skeleton: return "--engine skeleton";
  }
  return "";
}

std::string routesTaking(unsigned routes) {
  std::vector<std::string> names;
  for (Route r : {Route::EigenwalkerView, Route::EigenwalkerCamera, Route::Snippet, Route::Skeleton})
    if (routes & bit(r)) names.emplace_back(routeName(r));
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + names[i];
  return names.size() == 1 ? out + " only" : out;
}

struct OptionScope {
  const char* option;
  bool given;
  unsigned routes;  // the routes that take it
  const char* why;  // said when refused ("" for nothing more than where it applies)
};

std::vector<OptionScope> optionScopes(const ReconstructArgs& a) {
  const SkeletonOptions& s = a.skeleton;
  return {
      {"--model", !a.model.empty(), kEigenwalker, "the snippet engine's prior is --prior"},
      {"--components", a.components.has_value(), kEigenwalker, ""},
      {"--sigma2", a.sigma2Mm2.has_value(), kEigenwalker, "the eigenwalker's MAP noise"},
      {"--method", a.method != "map", kEigenwalker, "the snippet engine is MAP only"},
      {"--data-preserving", a.dataPreserving, kView, "eq. 3.16 keeps an orthographic view's u, v"},
      {"--prior", !a.prior.empty(), kSnippet, ""},
      {"--reference", !s.reference.empty(), kSkeleton, ""},
      {"--angles", !s.angles.empty(), kSkeleton, "for another engine run `angles` on the 3D CSV it writes"},
      {"--bones", !s.bones.empty(), kSkeleton, ""},
      {"--stature", a.statureM.has_value(), kKeypoints, ""},
      {"--bone-frame", s.boneFrame.has_value(), kSkeleton, ""},
      {"--reference-bone", !s.referenceBone.empty(), kSkeleton, ""},
      {"--guide", !s.guide.empty(), kSkeleton, ""},
      {"--scale-depth-frame", s.scaleDepthFrame.has_value(), kSkeleton, ""},
      {"--scale-depth-chain", !s.scaleDepthChain.empty(), kSkeleton, ""},
      {"--angle", a.alphaDeg.has_value(), kView | kCamera | kSnippet,
       "the skeleton engine places every bone through the camera: no view angle enters"},
      {"--unknown-angle", a.unknownAngle, kView | kSnippet,
       "through a real camera the camera's azimuth is estimated, or held with --angle"},
      {"--project-angle", a.projectAngleDeg.has_value(), kView | kSnippet, "it views a 3D trial in mm"},
      {"--unknown-camera", a.unknownCamera, kKeypoints, "the snippet engine takes 2D views in mm"},
      {"--elevation", a.elevationDeg.has_value(), kCamera, ""},
      {"--orthographic", a.orthographic, kCamera, ""},
      {"--no-detector-offsets", a.noDetectorOffsets, kCamera, ""},
      {"--camera", !a.camera.empty(), kKeypoints, ""},
      {"--camera-name", !a.cameraName.empty(), kKeypoints, ""},
      {"--focal-px", a.focalPx.has_value(), kKeypoints, ""},
      {"--image-size", !a.imageSize.empty(), kKeypoints, ""},
      {"--layout", !a.layout.empty(), kKeypoints, ""},
      {"--fps", a.fps.has_value(), kKeypoints, "a 2D CSV and a 3D trial carry their rate"},
      {"--detect-model", a.detectModel != "full", kKeypoints, "it reads a video"},
      {"--person", a.person.has_value(), kKeypoints, ""},
      {"--model-loop", a.modelLoop.has_value(), kCamera, ""},
      {"--corrections", !a.corrections.empty(), kCamera, ""},
      {"--scene-horizon", a.sceneHorizon != "prior", kCamera, ""},
      {"--save-2d", !a.save2d.empty(), kView | kSnippet, ""},
      {"--in-sample", a.inSample, kView | kSnippet, ""},
      {"--mapping", !a.mapping.empty(), kView | kCamera | kSnippet, ""},
  };
}

}  // namespace

ReconstructRoute routeOf(const ReconstructArgs& a) {
  if (a.engine == "snippet") return Route::Snippet;
  if (a.engine == "skeleton") return Route::Skeleton;
  // A video, and a pose estimator's keypoints (pixels), are seen through a real camera: they
  // go the unknown-camera way. Before, keypoints without --unknown-camera were read as a 3D
  // trial and refused for wanting --project-angle.
  const bool throughACamera = isVideoFile(a.input) || looksLikeKeypointInput(a.input);
  return a.unknownCamera || throughACamera ? Route::EigenwalkerCamera : Route::EigenwalkerView;
}

void checkOptionsApply(const ReconstructArgs& a, ReconstructRoute route) {
  for (const OptionScope& o : optionScopes(a)) {
    if (!o.given || (o.routes & bit(route))) continue;
    std::string why = std::string("does not apply to ") + routeName(route) + ": it applies to " + routesTaking(o.routes);
    if (*o.why) why += " (" + std::string(o.why) + ")";
    throw Error(ErrorKind::BadArgument, o.option, "", why);
  }
}

void addReconstructOptions(CLI::App& cmd, ReconstructArgs& a) {
  cmd.add_option("--engine", a.engine,
                  "eigenwalker (Zhang & Troje 2007), snippet (Howe, Leventon & Freeman 1999; docs/SNIPPETS.md) or "
                  "skeleton (Zou et al. 2009: keypoints through a calibrated --camera with --reference bone lengths)")
      ->check(CLI::IsMember({"eigenwalker", "snippet", "skeleton"}))
      ->capture_default_str();
  cmd.add_option("--reference", a.skeleton.reference,
                  "--engine skeleton: a 3D trial of the same person and frames (e.g. Pose2Sim's triangulated TRC): "
                  "its bone lengths are used and the result is scored against it")
      ->check(CLI::ExistingFile);
  cmd.add_option("--angles", a.skeleton.angles,
                  "--engine skeleton: also write the result's joint angles (.mot for OpenSim, or .csv; "
                  "docs/ANGLES.md)");
  cmd.add_option("--bones", a.skeleton.bones,
                  "--engine skeleton: where the bone lengths come from: reference (--reference, the default when "
                  "given), table2 (Zou et al.'s Table 2 at --stature), eigenwalker (the eigenwalker's fit of this "
                  "walker, scaled to --stature when given), frame (--bone-frame and --reference-bone)")
      ->check(CLI::IsMember({"reference", "table2", "eigenwalker", "frame"}));
  cmd.add_option("--stature", a.statureM,
                 "The walker's stature in metres: the unknown camera's fit is scaled to it (no image fixes the scale); "
                 "--engine skeleton: the bones of --bones table2, eigenwalker")
      ->check(finiteIn(0.5, 2.5));
  cmd.add_option("--bone-frame", a.skeleton.boneFrame,
                  "--engine skeleton, --bones frame: a frame (0-based) with the body parallel to the image plane (§4.1)")
      ->check(kNonNegativeFinite);
  cmd.add_option("--reference-bone", a.skeleton.referenceBone,
                  "--engine skeleton, --bones frame: the bone of known length, JOINT-JOINT=MM (e.g. r_elbow-r_wrist=260)");
  cmd.add_option("--guide", a.skeleton.guide,
                  "--engine skeleton: choose each bone's depth branch nearer the eigenwalker's fit of the walker")
      ->check(CLI::IsMember({"eigenwalker"}));
  cmd.add_option("--scale-depth-frame", a.skeleton.scaleDepthFrame,
                  "--engine skeleton without --camera or --focal-px: the frame (0-based) for Zou et al.'s "
                  "scale-depth relation T(dz), with --scale-depth-chain and --image-size")
      ->check(kNonNegativeFinite);
  cmd.add_option("--scale-depth-chain", a.skeleton.scaleDepthChain,
                  "--engine skeleton: four joints a,b,c,d of three linked segments, the outer two parallel to the "
                  "image plane on --scale-depth-frame (e.g. sternum,r_shoulder,r_elbow,r_wrist)");
  cmd.add_option("--prior", a.prior,
                  "Snippet prior from `build --engine snippet` (default: learnt from the embedded synthetic "
                  "population)")
      ->check(CLI::ExistingFile);
  cmd.add_option("--model", a.model,
                  "Model file from `build` (default: the built-in model of 24 real walkers)")
      ->check(CLI::ExistingFile);
  cmd.add_option("--components", a.components,
                  "Use the first N eigenwalkers of the model (as the viewer's N)")
      ->check(finiteIn(1, 100000));
  cmd.add_option("--input", a.input,
                  "2D CSV or 3D trial file; with --unknown-camera a pose estimator's keypoints "
                  "(OpenPose folder or JSON, AlphaPose or MMPose JSON) or a video (MP4, MOV, AVI…: the built-in "
                  "detector finds the walker; --unknown-camera is then implied)")
      ->required()
      ->check(CLI::ExistingPath);
  cmd.add_option("--detect-model", a.detectModel,
                  "For a video: the built-in pose detector's model, lite, full (default) or heavy")
      ->check(CLI::IsMember({"lite", "full", "heavy"}));
  cmd.add_option("--person", a.person,
                  "With --unknown-camera: the person to fit (1-based, as `info` and `detect` number them); default the "
                  "one who walks")
      ->check(kPositiveFinite);
  cmd.add_option("--corrections", a.corrections,
                  "With --unknown-camera: a keyframe file (docs/TRACKING.md) of joints corrected by hand; each "
                  "correction is carried to the frames around it (0.25 s either side, fading)")
      ->check(CLI::ExistingFile);
  cmd.add_option("--model-loop", a.modelLoop,
                  "With --unknown-camera: rounds of the model loop, where joints the detector is unsure of are pulled "
                  "towards the fitted walker and the fit is made again (default 1 for a video, 0 for keypoint files)")
      ->check(finiteIn(0, 5));
  cmd.add_option("--scene-horizon", a.sceneHorizon,
                  "For a video: its horizon, read off the scene's level lines (docs/CAMERA.md, \"The scene's "
                  "horizon\"): prior (the fit holds its camera's height to it), check (reported beside the fit's) or off")
      ->check(CLI::IsMember({"prior", "check", "off"}))
      ->capture_default_str();
  cmd.add_flag("--unknown-camera", a.unknownCamera,
                "Keypoints in pixels through an unknown real camera (docs/CAMERA.md): estimates azimuth, "
                "elevation, scale or distance, image translation and progression with the walker (implied "
                "for a video and a pose estimator's keypoint file or folder)");
  cmd.add_option("--layout", a.layout, "Keypoint layout (BODY_25, BODY_25B, COCO-18, COCO-17, Halpe-26, "
                                            "MediaPipe-33); guessed when not given");
  cmd.add_option("--fps", a.fps, "Video frame rate of keypoint input (JSON stores none; default 30)")
      ->check(kPositiveFinite);
  cmd.add_option("--focal-px", a.focalPx,
                  "Known focal length in pixels (else it is estimated with the camera)")
      ->check(kPositiveFinite);
  cmd.add_option("--elevation", a.elevationDeg,
                  "With --unknown-camera: the camera's known elevation in degrees (looking down), held "
                  "instead of estimated; --angle likewise holds the azimuth")
      ->check(finiteIn(-30.0, 80.0));
  cmd.add_option("--camera", a.camera,
                  "With --unknown-camera: a calibration file (Pose2Sim Calib_*.toml, Sports2D Calib_demo.toml) "
                  "giving the focal length and principal point (and a MediaPipe CSV's image size)")
      ->check(CLI::ExistingFile);
  cmd.add_option("--camera-name", a.cameraName, "Which camera of a --camera file with several (its name)");
  cmd.add_option("--image-size", a.imageSize,
                  "WxH in pixels of the video behind the keypoints: a MediaPipe CSV's and YOLO labels' "
                  "coordinates are fractions of it; with --unknown-camera the fit expects the camera's principal "
                  "point near its centre (docs/CAMERA.md). Else the size of a video found beside the keypoints "
                  "(docs/KEYPOINTS.md)");
  cmd.add_flag("--orthographic", a.orthographic,
                "With --unknown-camera and no --focal-px: scaled orthography instead of a pinhole "
                "whose focal length is estimated (a distant camera)");
  cmd.add_flag("--no-detector-offsets", a.noDetectorOffsets,
                "With --unknown-camera: take the detector's hips for hip-joint centres instead of allowing for "
                "the layout's detector offsets (docs/KEYPOINTS.md, \"Detector hips\")");
  cmd.add_option("--mapping", a.mapping,
                  "Joint mapping file (JSON, docs/FORMATS.md) for a 3D marker input whose set "
                  "the program does not know, or a DeepLabCut keypoint file's body parts");
  cmd.add_option("--out", a.out, "3D joints to write: the 15-joint CSV; a TRC (OpenSim's axes) when it ends in .trc; a C3D "
                 "when it ends in .c3d (the 15 joints and, in its EVENT group, the foot strikes and "
                 "offs of the reconstruction's own kinematics, docs/CLI.md)")->required();
  cmd.add_option("--angle", a.alphaDeg, "Known view angle in degrees (0 frontal, +-90 profile)")->check(kFinite);
  cmd.add_flag("--unknown-angle", a.unknownAngle, "Estimate the view angle over the whole circle");
  cmd.add_option("--method", a.method, "lsq or map")->check(CLI::IsMember({"lsq", "map"}))->capture_default_str();
  cmd.add_option("--sigma2", a.sigma2Mm2,
                  "MAP noise variance (mm^2); default: the optimum stored in the model, else 70")
      ->check(kPositiveFinite);
  cmd.add_option("--project-angle", a.projectAngleDeg, "View a 3D input at this angle (degrees)")->check(kFinite);
  cmd.add_option("--save-2d", a.save2d, "Also write the 2D sequence that was reconstructed (2D CSV)");
  cmd.add_flag("--data-preserving", a.dataPreserving, "Keep the observed u, v; only depth from the model (eq. 3.16)");
  cmd.add_flag("--in-sample", a.inSample,
                "A 3D input whose subject the model holds is reconstructed by the model without it (leave-one-"
                "subject-out, as the viewer does); this uses the whole model instead (an in-sample fit)");
  cmd.add_flag("--json", a.json, "Print the result (angle, k, errors) as JSON on stdout");
}

}  // namespace ew::cli
