#pragma once
// `reconstruct`'s command line, grouped by what each option says, bound by CLI11 once
// (reconstruct_options.cpp) and read by each engine's runner through the group it needs — no
// copies field by field:
//   KeypointSourceArgs  where the 2D input comes from and where the 3D goes (every engine)
//   CameraArgs          + the eigenwalker's estimator and the real camera's fit
//                       (--unknown-camera; also `track --reconstruct` and `gait V.mp4`)
//   SkeletonArgs        + the skeleton engine's bones, camera and reference
//   ReconstructArgs     all of them, + the orthographic view's and the snippet engine's own
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace ew::cli {

struct KeypointSourceArgs {
  std::string input, out;
  std::string layout;                 // keypoint layout (--layout); guessed when empty
  std::string mapping;                // joint mapping file (--mapping)
  std::string imageSize;              // WxH (--image-size)
  std::string camera, cameraName;     // a calibration file (--camera) and which of its cameras
  std::string detectModel = "full";   // a video's input: the built-in detector's model
  std::optional<double> fps, focalPx;
  std::optional<int> person;          // 1-based: the person to fit instead of the one who walks
  // The walker's stature (m), when known: the eigenwalker's camera fit is scaled to it
  // (core/camera/known_stature.h); the skeleton engine's table2 and eigenwalker bones use it.
  std::optional<double> statureM;
  bool json = false;
};

struct CameraArgs : KeypointSourceArgs {
  std::string method = "map", modelName;
  std::optional<double> sigma2Mm2;
  std::optional<double> alphaDeg, elevationDeg;  // known: held, not estimated
  bool orthographic = false;     // scaled orthography instead of estimating the focal length
  bool detectorOffsets = true;   // allow for the layout's detector offsets (KeypointLayout)
  bool strideFromTrunk = false;  // a tracker's joints: hold the trunk's bob as the stride
  // Rounds of the model loop on the detections' confidences (core/camera/detection_loop.h);
  // unset: 1 for a video, 0 for keypoint files.
  std::optional<int> modelLoop;
  // A keyframe file of corrections to the keypoints (core/tracking/corrected_track.h).
  std::string corrections;
  // A video's own horizon (video/scene_horizon.h): "prior" (the fit holds its camera's height
  // to it), "check" (reported beside the fit's only) or "off" (not read).
  std::string sceneHorizon = "prior";
  // The video whose horizon is read when the input is not that video itself (`track
  // --reconstruct` fits its track of it); "" reads the input's, when it is a video.
  std::string horizonVideo;
  // Write only the frames from the walker's first seen frame to its last (`gait V.mp4`: the
  // periodic walker before and after is the model's, not the footage's). No flag sets it.
  bool seenFramesOnly = false;
};

// The skeleton engine's own options (reconstruct_skeleton.h).
struct SkeletonOptions {
  std::string reference;   // a 3D trial of the same person and frames: bones and scoring
  std::string angles;      // joint angles (.mot or .csv) of the result, when given
  // Without a calibration: a focal length, or T(dz) on a frame and a chain "a,b,c,d"; the
  // principal point is the middle of --image-size WxH.
  std::optional<int> scaleDepthFrame;
  std::string scaleDepthChain;
  // Bone lengths: "" (the reference's), reference, table2 (with statureM), eigenwalker
  // (scaled to statureM when given), frame (boneFrame and referenceBone "a-b=MM").
  std::string bones;
  std::optional<int> boneFrame;
  std::string referenceBone;
  std::string guide;  // "" or eigenwalker
};

struct SkeletonArgs : KeypointSourceArgs, SkeletonOptions {};

struct ReconstructArgs : CameraArgs {
  std::string engine = "eigenwalker";
  std::string model;                  // an eigenwalker model file (--model)
  std::optional<int> components;      // unset: every eigenwalker of the model
  std::string prior;                  // the snippet engine's prior (--prior)
  bool unknownCamera = false;         // keypoints through an unknown real camera
  bool noDetectorOffsets = false;     // take a detector's hips for joint centres
  // The orthographic view (a 2D CSV, or a 3D trial viewed at --project-angle).
  bool unknownAngle = false;
  std::optional<double> projectAngleDeg;
  std::string save2d;
  bool dataPreserving = false;
  bool inSample = false;  // the whole model even when it holds the input's subject
  SkeletonOptions skeleton;

  SkeletonArgs skeletonArgs() const { return {{*this}, skeleton}; }
};

// The ways `reconstruct` goes, and which options each takes (reconstruct_options.cpp).
enum class ReconstructRoute { EigenwalkerView, EigenwalkerCamera, Snippet, Skeleton };
ReconstructRoute routeOf(const ReconstructArgs& args);
// Error(BadArgument) naming the first option given that the route does not take.
void checkOptionsApply(const ReconstructArgs& args, ReconstructRoute route);
// Binds every option of `reconstruct` to `args`.
void addReconstructOptions(CLI::App& command, ReconstructArgs& args);

}  // namespace ew::cli
