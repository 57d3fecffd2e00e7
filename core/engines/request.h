#pragma once
// One reconstruction request for every engine (issue 54): the 2D input — a view in mm at the
// walker (an orthographic camera) or a pose estimator's pixels (a real camera) — and what is
// known of its camera, answered by reconstruct(engine, request). Each engine declares which
// knowledge it accepts (engineAccepts): a program checks a request against the table instead
// of refusing options one by one, and its error names the engine and what it takes.
//
//                               eigenwalker   snippet   skeleton
//   orthographic, α known           yes         yes        yes
//   orthographic, α unknown         yes         yes        yes
//   camera, focal unknown           yes          -          -     (the skeleton needs a focal
//   camera, focal known             yes          -         yes     length: a calibration, one
//   camera, calibration file        yes          -         yes     given, or Zou et al.'s
//   camera, lens distortion         yes          -         yes     scale-depth relation)
//   camera, scaled orthography      yes          -          -
//
// Through a camera the eigenwalker fits the walker and the camera together
// (core/camera/camera_reconstruction.h; the model loop of detection_loop.h where the
// detector's confidences say it is unsure), the skeleton engine places each frame's bones on
// the joints' rays (core/skeleton/skeleton_camera.h). The snippet engine's prior was learnt in
// mm at the walker: it takes orthographic views only.

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "core/camera/camera_knowledge.h"
#include "core/camera/detection_loop.h"
#include "core/engines/engine.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/skeleton/skeleton_camera.h"

namespace ew {

// Pixels through a real camera: the keypoints (already read, cleaned and undistorted as the
// caller chose: undistortKeypoints) and what is known of the camera.
struct CameraView {
  KeypointTrial keypoints;
  CameraKnowledge camera;
  // The eigenwalker's model loop (detection_loop.h): rounds where joints the detector was
  // unsure of are pulled to the fitted walker's reprojection.
  int modelLoopRounds = 0;
  // A joint tracker's track: the trunk's bob holds the stride (holdTheTrunksStride), where
  // the crossing feet are lost.
  bool strideFromTrunk = false;
  // The skeleton engine's camera when no calibration gives it: a focal length from the
  // scale-depth relation (core/skeleton/scale_depth.h), with the image's size.
  std::optional<double> skeletonFocalPx;
  std::string name;  // names the input in errors (the keypoints' file when empty)
};

// A walker's own 2D Fourier view (METHOD §5: C(α) applied to its 3D Fourier vector), the
// eigenwalker's currency: the viewer's walkers and the paper's experiments, which reconstruct
// a whole walker rather than frames. The eigenwalker only: the other engines take frames.
struct FourierView {
  Eigen::VectorXd w2d;             // 150: u, v of every block and joint
  std::optional<double> alphaDeg;  // the known view; unset: searched over the circle
  // The engine's model prepared for the joints the view does not hold (precomputeModelGram),
  // when the caller keeps it for several requests (a fold of an experiment, the viewer's
  // walker); null: prepared from the engine's model with every joint seen. A given gram IS
  // the model: the engine's own is not read.
  std::shared_ptr<const ModelGram> gram;
};

// A gram the caller keeps alive while the request is answered (a fold's, in a loop), lent
// without a copy.
inline std::shared_ptr<const ModelGram> lentGram(const ModelGram& gram) {
  return std::shared_ptr<const ModelGram>(std::shared_ptr<const ModelGram>(), &gram);
}

// The eigenwalker (estimator `estimator`) on a walker's Fourier view through a prepared model:
// reconstruct(engine, {FourierView}) as the experiments' loops and the viewer ask it.
EigenwalkerDiagnostics reconstructFourierView(const ModelGram& gram, const Eigen::VectorXd& w2d,
                                              std::optional<double> alphaDeg, const EstimatorOptions& estimator);

struct ReconstructionRequest {
  std::variant<ViewInput, CameraView, FourierView> input;
};

// What a request says of its camera, in the rows of the table above.
enum class CameraKnowledgeKind {
  OrthographicKnownView,
  OrthographicUnknownView,
  CameraUnknownFocal,
  CameraKnownFocal,
  CameraCalibration,
  CameraLensDistortion,
  CameraScaledOrthography,
};
const char* describe(CameraKnowledgeKind kind);  // "keypoints through a camera of unknown focal length", …

std::vector<CameraKnowledgeKind> knowledgeOf(const ReconstructionRequest& request);
bool engineAccepts(EngineKind engine, CameraKnowledgeKind kind);
// Error(BadArgument) naming `where` (e.g. "--engine"), the engine and what it does not take.
void checkEngineAccepts(EngineKind engine, const ReconstructionRequest& request, const std::string& where);

// The camera's results, for an engine that reconstructed through one.
struct CameraResults {
  std::optional<DetectionLoop> eigenwalker;          // the fit (last) and the loop's first fit
  std::optional<SkeletonCameraResult> skeleton;
  std::optional<CalibratedCamera> skeletonCamera;    // the pinhole the skeleton engine used
};

struct ReconstructionResult {
  EngineResult engine;       // framesMm: the walker's frame (orthographic and the eigenwalker's
                             // camera fit), the calibration's world or the camera's frame
                             // (the skeleton through a camera: see cameraFrame)
  CameraResults camera;
  bool worldFrame = false;   // the skeleton engine through a calibration with extrinsics
};

// Checks the request (checkEngineAccepts with where "engine") and answers it. Throws what
// the engine throws.
ReconstructionResult reconstruct(const Engine& engine, const ReconstructionRequest& request);

// The pinhole the skeleton engine sees through: the calibration's, else one of the known (or
// scale-depth) focal length with its principal point at the image's centre. Error(BadArgument)
// when neither a calibration nor a focal length with the image's size is known.
CalibratedCamera skeletonPinhole(const CameraView& view);

}  // namespace ew
