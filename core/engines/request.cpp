#include "core/engines/request.h"

#include <limits>

#include "core/camera/clip_reconstruction.h"
#include "core/camera/known_stature.h"
#include "core/camera/lens_distortion.h"
#include "core/common/errors.h"

namespace ew {

namespace {

using Kind = CameraKnowledgeKind;

std::vector<Kind> cameraKnowledgeOf(const CameraView& v) {
  const CameraKnowledge& c = v.camera;
  std::vector<Kind> out;
  if (c.calibration) out.push_back(Kind::CameraCalibration);
  if (c.calibration && hasDistortion(*c.calibration)) out.push_back(Kind::CameraLensDistortion);
  if (c.focalPx || v.skeletonFocalPx) out.push_back(Kind::CameraKnownFocal);
  else out.push_back(c.estimateFocal ? Kind::CameraUnknownFocal : Kind::CameraScaledOrthography);
  return out;
}

// What the engine needs instead, said after "the E engine does not take …".
std::string whatTheEngineTakes(EngineKind engine) {
  switch (engine) {
    case EngineKind::Eigenwalker: return "";
    case EngineKind::Snippet: return "it takes 2D views in mm at the walker (an orthographic camera)";
    case EngineKind::Skeleton:
      return "it needs the camera's focal length: a calibration file, a focal length given, or Zou et al.'s "
             "scale-depth relation on a frame";
  }
  return "";
}

const std::string& nameOf(const CameraView& view) { return view.name.empty() ? view.keypoints.file : view.name; }

EngineResult fromCameraFit(const ClipReconstruction& clip) {
  EngineResult e;
  e.engine = EngineKind::Eigenwalker;
  e.framesMm = clip.framesMm;
  e.alphaDeg = clip.fit.camera.alphaDeg;
  // In px through the camera: CameraResults has it (ClipReconstruction::fit.reprojectionRmsPx).
  e.reprojectionRmsMm = std::numeric_limits<double>::quiet_NaN();
  e.warnings = clip.cautions;
  return e;
}

ReconstructionResult eigenwalkerThroughCamera(const EigenwalkerEngine& engine, const CameraView& view) {
  CameraFitOptions fit = cameraFitOptions(view.camera, engine.estimator, nameOf(view));
  if (view.strideFromTrunk) holdTheTrunksStride(view.keypoints, fit);
  DetectionLoopOptions loop;
  loop.rounds = view.modelLoopRounds;
  ReconstructionResult r;
  r.camera.eigenwalker = reconstructWithDetectionLoop(engine.model, view.keypoints, fit, loop);
  if (view.camera.statureMm) scaleToStature(*r.camera.eigenwalker, *view.camera.statureMm);
  r.engine = fromCameraFit(r.camera.eigenwalker->last);
  r.engine.alphaEstimated = !view.camera.alphaDeg;
  return r;
}

// The eigenwalker on a walker's Fourier view: the known-view estimate (METHOD §6) or the
// search over α.
ReconstructionResult eigenwalkerOnFourierView(const EigenwalkerEngine& engine, const FourierView& view) {
  const std::shared_ptr<const ModelGram> gram =
      view.gram ? view.gram : std::make_shared<const ModelGram>(precomputeModelGram(engine.model, {}));
  EigenwalkerDiagnostics d;
  if (view.alphaDeg) {
    d.reconstruction = reconstructKnownView(*gram, view.w2d, *view.alphaDeg, engine.estimator);
  } else {
    d.search = searchViewAngle(*gram, view.w2d, engine.estimator, engine.search);
    d.reconstruction = d.search->best;
  }
  d.missingJoints = gram->missingJoints;
  ReconstructionResult r;
  r.engine.engine = EngineKind::Eigenwalker;
  r.engine.alphaDeg = d.reconstruction.alphaDeg;
  r.engine.alphaEstimated = !view.alphaDeg;
  r.engine.reprojectionRmsMm = std::numeric_limits<double>::quiet_NaN();  // no frames: see the fit's J(α)
  r.engine.eigenwalker = std::move(d);
  return r;
}

ReconstructionResult skeletonThroughCamera(const SkeletonEngine& engine, const CameraView& view) {
  if (!engine.bones)
    throw Error(ErrorKind::BadArgument, nameOf(view), "",
                "the skeleton engine through a camera needs the walker's bone lengths");
  ReconstructionResult r;
  r.camera.skeletonCamera = skeletonPinhole(view);
  SkeletonCameraOptions options;
  options.solve = engine.solve;
  r.camera.skeleton = reconstructThroughCamera(view.keypoints.jointsPx, *r.camera.skeletonCamera, *engine.bones,
                                               view.keypoints.rateHz, nameOf(view), options);
  r.worldFrame = r.camera.skeletonCamera->hasExtrinsics;
  r.engine.engine = EngineKind::Skeleton;
  r.engine.framesMm = r.worldFrame ? r.camera.skeleton->worldMm : r.camera.skeleton->sequence.framesMm;
  r.engine.reprojectionRmsMm = std::numeric_limits<double>::quiet_NaN();
  r.engine.skeleton = r.camera.skeleton->sequence;
  return r;
}

}  // namespace

const char* describe(CameraKnowledgeKind kind) {
  switch (kind) {
    case Kind::OrthographicKnownView: return "a 2D view in mm at a known view angle";
    case Kind::OrthographicUnknownView: return "a 2D view in mm at an unknown view angle";
    case Kind::CameraUnknownFocal: return "keypoints through a camera of unknown focal length";
    case Kind::CameraKnownFocal: return "keypoints through a camera of known focal length";
    case Kind::CameraCalibration: return "a calibration file";
    case Kind::CameraLensDistortion: return "a lens distortion";
    case Kind::CameraScaledOrthography: return "keypoints through a distant camera (scaled orthography)";
  }
  return "";
}

std::vector<CameraKnowledgeKind> knowledgeOf(const ReconstructionRequest& request) {
  if (const auto* view = std::get_if<ViewInput>(&request.input))
    return {view->alphaDeg ? Kind::OrthographicKnownView : Kind::OrthographicUnknownView};
  if (const auto* view = std::get_if<FourierView>(&request.input))
    return {view->alphaDeg ? Kind::OrthographicKnownView : Kind::OrthographicUnknownView};
  return cameraKnowledgeOf(std::get<CameraView>(request.input));
}

bool engineAccepts(EngineKind engine, CameraKnowledgeKind kind) {
  const bool orthographic = kind == Kind::OrthographicKnownView || kind == Kind::OrthographicUnknownView;
  switch (engine) {
    case EngineKind::Eigenwalker: return true;
    case EngineKind::Snippet: return orthographic;
    case EngineKind::Skeleton: return kind != Kind::CameraUnknownFocal && kind != Kind::CameraScaledOrthography;
  }
  return false;
}

void checkEngineAccepts(EngineKind engine, const ReconstructionRequest& request, const std::string& where) {
  if (std::holds_alternative<FourierView>(request.input) && engine != EngineKind::Eigenwalker)
    throw Error(ErrorKind::BadArgument, where, "",
                std::string("the ") + engineName(engine) +
                    " engine takes a view's frames, not a walker's Fourier view (the eigenwalker's own)");
  for (const CameraKnowledgeKind kind : knowledgeOf(request))
    if (!engineAccepts(engine, kind))
      throw Error(ErrorKind::BadArgument, where, "",
                  std::string("the ") + engineName(engine) + " engine does not take " + describe(kind) + ": " +
                      whatTheEngineTakes(engine));
}

CalibratedCamera skeletonPinhole(const CameraView& view) {
  if (view.camera.calibration) return *view.camera.calibration;
  const std::optional<double> focal = view.camera.focalPx ? view.camera.focalPx : view.skeletonFocalPx;
  const std::optional<KeypointImageSize> size = view.camera.imageSize ? view.camera.imageSize : view.keypoints.imageSize;
  if (!focal || !size)
    throw Error(ErrorKind::BadArgument, nameOf(view), "",
                "the skeleton engine's pinhole needs a calibration, or a focal length and the image's size "
                "(its principal point is the image's centre)");
  CalibratedCamera c;
  c.name = c.table = "pinhole";
  c.widthPx = size->width, c.heightPx = size->height;
  c.fxPx = c.fyPx = *focal;
  c.cxPx = 0.5 * size->width, c.cyPx = 0.5 * size->height;
  return c;
}

EigenwalkerDiagnostics reconstructFourierView(const ModelGram& gram, const Eigen::VectorXd& w2d,
                                              std::optional<double> alphaDeg, const EstimatorOptions& estimator) {
  const EigenwalkerEngine engine{{}, estimator, {}};  // the model is the gram
  return std::move(*reconstruct(engine, {FourierView{w2d, alphaDeg, lentGram(gram)}}).engine.eigenwalker);
}

ReconstructionResult reconstruct(const Engine& engine, const ReconstructionRequest& request) {
  const EngineKind kind = engineKind(engine);
  checkEngineAccepts(kind, request, "engine");
  if (const auto* view = std::get_if<ViewInput>(&request.input)) return {reconstructWithEngine(engine, *view), {}, false};
  if (const auto* view = std::get_if<FourierView>(&request.input))
    return eigenwalkerOnFourierView(std::get<EigenwalkerEngine>(engine), *view);
  const CameraView& view = std::get<CameraView>(request.input);
  if (const auto* e = std::get_if<EigenwalkerEngine>(&engine)) return eigenwalkerThroughCamera(*e, view);
  return skeletonThroughCamera(std::get<SkeletonEngine>(engine), view);
}

}  // namespace ew
