// `eigenwalker-cli reconstruct [--model MODEL] [--components N] --input FILE
//  (--angle DEG | --unknown-angle) [--method lsq|map] [--sigma2 MM2] --out OUT.csv
//  [--project-angle DEG] [--json]`: the 3D walker behind a 2D sequence (METHOD §6). Without
// --model the default model of real walkers (core/engine/default_model.h); without
// --sigma2 the σ² optimum stored in the model (else the paper's 70 mm²). FILE is a 2D CSV
// (docs/EXPERIMENTS.md) or any 3D trial the loaders read, projected at --project-angle (ground
// truth known: errors of METHOD §7 are reported).
// `--engine snippet [--prior PRIOR.ewsp]`: the snippet engine (core/snippet) instead, through
// the engines' interface (core/engines/engine.h); without --prior its prior is learnt from
// the default model's real walkers (without the input's subject when it is one of them). A 3D
// input is then viewed overground (its progression put back), as the snippet prior was learnt.
// A 3D input whose subject the model holds is reconstructed by the model without it (METHOD §4).
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app/cli/commands.h"
#include "app/cli/video_input.h"
#include "app/cli/reconstruct_camera.h"
#include "app/cli/reconstruct_skeleton.h"
#include "core/camera/focal_length.h"
#include "core/common/errors.h"
#include "core/engine/default_model.h"
#include "core/engine/fourier.h"
#include "core/engine/joint_completion.h"
#include "core/engine/metrics.h"
#include "core/engine/model_file.h"
#include "core/engine/model_membership.h"
#include "core/engine/projection.h"
#include "core/engine/reconstruction.h"
#include "core/engines/engine.h"
#include "core/experiments/snippet_experiment.h"
#include "core/experiments/view_csv.h"
#include "core/io/trc_writer.h"
#include "core/snippet/snippet_file.h"
#include "core/synth/population.h"
#include "core/gait/dataset.h"
#include "core/io/joint_csv.h"

namespace ew::cli {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct ReconstructArgs {
  std::string model, input, out, method = "map", save2d;
  std::optional<double> angleDeg, projectAngleDeg;
  bool unknownAngle = false, json = false, dataPreserving = false;
  bool inSample = false;  // --in-sample: the whole model even when it holds the input's subject
  std::optional<double> sigma2Mm2;  // unset: the model's stored optimum (defaultSigma2Mm2)
  std::optional<int> components;    // unset: every eigenwalker of the model
  std::string mapping;              // joint mapping file for a 3D marker input (--mapping)
  bool unknownCamera = false;       // keypoint input through an unknown real camera
  std::string layout;               // keypoint layout (--layout)
  std::optional<double> fps, focalPx, elevationDeg;
  bool orthographic = false;
  bool noDetectorOffsets = false;   // take a detector's hips for joint centres
  std::string detectModel = "full"; // a video's input: the built-in detector's model (--detect-model)
  std::optional<int> modelLoop;     // --model-loop: rounds of the detection loop
  std::string corrections;          // --corrections: a keyframe file correcting the keypoints
  std::optional<int> person;        // --person: 1-based, instead of the one who walks
  std::string imageSize;
  std::string camera, cameraName;   // a calibration file (--camera) and which of its cameras
  std::string engine = "eigenwalker";
  std::string prior;                // the snippet engine's prior (--prior)
  std::string reference;            // the skeleton engine's 3D reference (--reference)
  std::string angles;               // the skeleton engine's joint angles out (--angles)
  // The skeleton engine's bone sources, guide and scale-depth camera (reconstruct_skeleton.h).
  std::string bones, referenceBone, guide, scaleDepthChain;
  std::optional<double> statureM;
  std::optional<int> boneFrame, scaleDepthFrame;

  bool skeletonOnlyGiven() const {
    return !bones.empty() || !referenceBone.empty() || !guide.empty() || !scaleDepthChain.empty() || statureM ||
           boneFrame || scaleDepthFrame;
  }
};

// The model the user named, or the default one (--components: applyComponents, the viewer's N).
struct ChosenModel {
  EigenwalkerModel model;
  std::string name;  // the file, or defaultRealModelName()
  std::string sigma2Source;  // where its σ² optimum comes from (defaultSigma2Source)
};

// Whole: a walker held out is left out of the whole model first, and --components then keeps
// that model's first N, as the viewer's N does (applyComponents).
ChosenModel chooseModel(const ReconstructArgs& a) {
  ChosenModel c;
  if (a.model.empty()) {
    c.model = defaultRealModel();
    c.name = defaultRealModelName();
  } else {
    c.model = loadModel(a.model);
    c.name = a.model;
  }
  if (a.components && *a.components > c.model.componentCount())
    throw Error(ErrorKind::BadArgument, "--components", "",
                std::to_string(*a.components) + " components asked, the model " + c.name + " has " +
                    std::to_string(c.model.componentCount()));
  std::cerr << "model: " << c.name << " (" << c.model.componentCount() << " eigenwalkers)\n";
  c.sigma2Source = defaultSigma2Source(c.model);
  return c;
}

// --components N: the model's first N eigenwalkers (at most as many as it has).
void applyComponents(ChosenModel& c, const ReconstructArgs& a) {
  if (a.components) c.model = leadingComponents(c.model, std::min(*a.components, c.model.componentCount()));
}

// The 2D input and, for a 3D file, the truth it came from.
struct Input {
  ViewSequence view;
  std::optional<double> omegaHintRadS;
  Eigen::MatrixXd frames3d;  // empty for a 2D file
  Eigen::MatrixXd frames3dOverground;  // frames3d with the trial's progression put back
  // Joints not measured in any frame (a lower-body marker set, a 2D column left empty):
  // dropped from the likelihood (their rows of Ê), estimated by the model, flagged.
  JointMask missing{};
};

bool isViewCsv(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorKind::Io, file.string(), "", "cannot open file");
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  return looksLikeViewCsv(head);
}

Input readInput(const ReconstructArgs& a) {
  Input in;
  if (isViewCsv(a.input)) {
    if (a.projectAngleDeg) throw Error(ErrorKind::BadArgument, "--project-angle", "", "the input is already 2D");
    in.view = readViewCsv(a.input);
    in.missing = jointsMissingThroughout(in.view.framesMm);
    return in;
  }
  if (!a.projectAngleDeg) {
    throw Error(ErrorKind::BadArgument, "--project-angle", "",
                a.input + " is a 3D trial: give --project-angle DEG to view it in 2D (or pass a 2D CSV)");
  }
  LoadOptions load;
  if (!a.mapping.empty()) load.mappingFile = a.mapping;
  const WalkingTrial trial = loadWalkingTrial(a.input, load);
  in.frames3d = trial.joints.positionsMm;
  in.frames3dOverground = framesWithProgression(trial);
  in.missing = trial.joints.missing;
  in.view = {projectFramesToView(in.frames3d, *a.projectAngleDeg), trial.joints.rateHz};
  if (trial.cycles.strideHz > 0 && std::isfinite(trial.cycles.strideHz)) in.omegaHintRadS = 2.0 * std::numbers::pi * trial.cycles.strideHz;
  return in;
}

// The model's name for the 3D input's subject when its walker is one of the model's (by its
// subject's name or its data; model_membership.h), else "" (and for a 2D input).
// A 3D input whose walker is one of the model's: the model
// is rebuilt without that subject, as the viewer and the experiments reconstruct a walker
// (METHOD §4), its component count kept; the subject's model name, or "" when none. Its errors
// against the truth would otherwise be those of a walker the model has seen.
std::string inputSubjectInModel(const EigenwalkerModel& model, const Input& in, const ReconstructArgs& a) {
  if (in.frames3d.rows() == 0) return "";
  FourierFitOptions o;
  o.omegaHintRadS = in.omegaHintRadS;
  o.file = a.input;
  const FourierFit fit = fitFourierMeasured(in.frames3d, in.view.rateHz, in.missing, o);
  return subjectInModel(model, subjectFromFileName(a.input), fit.w);
}

std::string holdOutTheInputsSubject(ChosenModel& chosen, const Input& in, const ReconstructArgs& a) {
  const std::string subject = inputSubjectInModel(chosen.model, in, a);
  if (subject.empty()) return "";
  if (a.inSample) {
    std::cerr << "the model holds this walker's subject " << subject << ": kept (--in-sample)\n";
    return "";
  }
  const int components = chosen.model.componentCount();
  // The σ² optimum was measured leaving each subject out in turn: it holds for this fold too.
  const auto sigma2 = chosen.model.sigma2Optimum;
  chosen.model = modelWithoutSubject(chosen.model, subject);
  chosen.model = leadingComponents(chosen.model, std::min(components, chosen.model.componentCount()));
  chosen.model.sigma2Optimum = sigma2;
  std::cerr << "the model holds this walker's subject " << subject << ": left out (leave-one-subject-out, "
            << chosen.model.walkerCount() << " walkers, " << chosen.model.componentCount() << " eigenwalkers)\n";
  return subject;
}

std::vector<std::string> jointNames(const JointMask& mask) {
  std::vector<std::string> out;
  for (int j = 0; j < kJointCount; ++j)
    if (mask[static_cast<size_t>(j)]) out.emplace_back(kJointNames[static_cast<size_t>(j)]);
  return out;
}

json minimaJson(const ViewSearch& s) {
  json out = json::array();
  for (const auto& m : s.minima) {
    out.push_back({{"alpha_deg", m.alphaDeg}, {"objective", m.objective},
                   {"depth_reversed_of_best", m.depthReversedOfBest}, {"mirror_of_best", m.mirrorOfBest},
                   {"facing_of_best", m.facingOfBest}});
  }
  return out;
}

// METHOD §7 errors against the 3D truth: Fourier (one cycle) and raw frames. Joints the trial
// did not measure have no truth: they are filled with the reconstruction (zero error), and
// every error is averaged over the measured joints only (MPJPE over joints with 0 added
// rescaled by 15 / measured); σ_m² is then that of the truth completed by the reconstruction.
json truthErrors(const Input& in, const FourierFit& fit2d, const Eigen::VectorXd& wRec, double trueAngleDeg) {
  FourierFitOptions o;
  o.omegaFixedRadS = fit2d.omegaRadS;
  FourierFit truth = fitFourierMeasured(in.frames3d, in.view.rateHz, in.missing, o);
  const Eigen::VectorXd aligned = rephase(wRec, fit2d.phaseRad, truth.phaseRad);
  Eigen::MatrixXd frames = in.frames3d;
  const Eigen::MatrixXd recFrames =
      synthesizeFrames(wRec, fit2d.omegaRadS, fit2d.phaseRad,
                       frameTimes(static_cast<int>(frames.rows()), in.view.rateHz));
  JointMask measured{};
  for (int j = 0; j < kJointCount; ++j) {
    measured[static_cast<size_t>(j)] = !in.missing[static_cast<size_t>(j)];
    if (measured[static_cast<size_t>(j)]) continue;
    for (int b = 0; b < kFourierBlocks; ++b)
      truth.w.segment<3>(b * kDims3 + 3 * j) = aligned.segment<3>(b * kDims3 + 3 * j);
    frames.middleCols<3>(3 * j) = recFrames.middleCols<3>(3 * j);
  }
  const double scale = static_cast<double>(kJointCount) / jointCount(measured);
  const DepthErrors e = depthErrors(truth.w, aligned, trueAngleDeg);
  const DepthErrors f = depthErrorsFrames(frames, in.view.rateHz, wRec, fit2d.omegaRadS,
                                          fit2d.phaseRad, trueAngleDeg);
  const double absMeasured = meanOverJoints(e.absPerJoint, measured);
  const double mpjpeMeasured = meanOverJoints(mpjpePerJoint(truth.w, aligned), measured);
  return {{"abs_error_mm2", absMeasured},
          {"rel_error", absMeasured / e.sigmaM2Mm2},
          {"var_missing_mm2", e.sigmaM2Mm2},
          {"mpjpe_mm", mpjpeMeasured},
          {"abs_error_frames_mm2", meanOverJoints(f.absPerJoint, measured)},
          {"mpjpe_frames_mm",
           scale * mpjpeFrames(frames, in.view.rateHz, wRec, fit2d.omegaRadS, fit2d.phaseRad)},
          {"joints_scored", jointCount(measured)},
          {"mpjpe_measured_mm", mpjpeMeasured},
          // No truth for a joint the trial did not measure: nothing to score (null, not 0).
          {"mpjpe_model_estimated_mm", nullptr}};
}

void printReport(const json& r) {
  if (r.contains("sigma2_mm2"))
    std::cerr << "MAP sigma2 " << r["sigma2_mm2"].get<double>()
              << " mm2: " << r["sigma2_source"].get<std::string>() << "\n";
  std::cerr << std::fixed << std::setprecision(2);
  std::cerr << "view angle " << r["angle_deg"].get<double>() << " deg (" << r["angle_source"].get<std::string>() << ")";
  if (r.contains("angle_error_deg")) std::cerr << ", error " << r["angle_error_deg"].get<double>() << " deg";
  std::cerr << "; stride " << r["stride_hz"].get<double>() << " Hz, " << r["cycles"].get<double>() << " cycles\n";
  if (r.contains("minima")) {
    std::cerr << "local minima of J(alpha):";
    for (const auto& m : r["minima"]) std::cerr << " " << m["alpha_deg"].get<double>();
    std::cerr << "\n";
  }
  std::cerr << "alpha_hat (k):";
  for (const auto& k : r["k"]) std::cerr << " " << std::setprecision(1) << k.get<double>();
  std::cerr << "\n";
  if (r.contains("errors")) {
    const auto& e = r["errors"];
    std::cerr << std::setprecision(1) << "E_a " << e["abs_error_mm2"].get<double>() << " mm2, E_r "
              << std::setprecision(3) << e["rel_error"].get<double>() << ", MPJPE " << std::setprecision(1)
              << e["mpjpe_mm"].get<double>() << " mm (vs raw frames: E_a " << e["abs_error_frames_mm2"].get<double>()
              << " mm2, MPJPE " << e["mpjpe_frames_mm"].get<double>() << " mm)\n";
  }
  if (!r["joints_model_estimated"].empty()) {
    std::cerr << "model-estimated (not in the input, no truth to score):";
    for (const auto& j : r["joints_model_estimated"]) std::cerr << " " << j.get<std::string>();
    std::cerr << "\n";
    if (r.contains("errors"))
      std::cerr << "errors above: MPJPE measured " << r["errors"]["mpjpe_measured_mm"].get<double>()
                << " mm over the " << r["errors"]["joints_scored"].get<int>() << " measured joints\n";
  }
  std::cerr << "wrote " << r["output"].get<std::string>() << "\n";
}

// [SECTION] The snippet engine

// Options that belong to the eigenwalker: an error with the snippet engine, not ignored.
void refuseEigenwalkerOptions(const ReconstructArgs& a) {
  const auto refuse = [](const std::string& option, const std::string& why) {
    throw Error(ErrorKind::BadArgument, option, "", why + " (--engine snippet)");
  };
  if (a.unknownCamera) refuse("--unknown-camera", "the real-camera fit is the eigenwalker's; the snippet engine takes 2D views in mm");
  if (!a.model.empty()) refuse("--model", "an eigenwalker model does not apply: give the snippet prior with --prior");
  if (a.components) refuse("--components", "eigenwalkers do not apply");
  if (a.sigma2Mm2) refuse("--sigma2", "the eigenwalker's MAP noise does not apply");
  if (a.method != "map") refuse("--method", "the snippet engine is MAP only");
  if (a.dataPreserving) refuse("--data-preserving", "eq. 3.16 is the eigenwalker's");
}

// --prior, else a prior learnt from the default model's real walkers (the eigenwalker's default
// too), without the input's subject when it is one of them; `source` says which.
SnippetPrior chooseSnippetPrior(const ReconstructArgs& a, const Input& in, std::string& source) {
  if (!a.prior.empty()) {
    std::cerr << "snippet prior: " << a.prior << "\n";
    source = a.prior;
    return loadSnippetPrior(a.prior);
  }
  ChosenModel chosen{defaultRealModel(), defaultRealModelName(), ""};
  const std::string heldOut = a.inSample ? std::string() : inputSubjectInModel(chosen.model, in, a);
  const std::vector<FourierWalkerTrial> walkers = modelFourierWalkers(chosen.model, heldOut);
  source = "the default model's walkers (" + std::to_string(walkers.size()) + (heldOut.empty() ? "" : ", without " + heldOut) + ")";
  std::cerr << "snippet prior: learnt from " << source << "; give --prior (from `build --engine snippet`) for others\n";
  return trainSnippetPrior(snippetTrialsFromFourier(walkers), {});
}

int runReconstructSnippet(const ReconstructArgs& a) {
  refuseEigenwalkerOptions(a);
  if (a.angleDeg.has_value() == a.unknownAngle)
    throw Error(ErrorKind::BadArgument, "--angle", "", "give exactly one of --angle DEG and --unknown-angle");
  const Input in = readInput(a);
  std::string priorSource;
  const SnippetEngine engine{
      std::make_shared<const PreparedSnippetPrior>(prepareSnippetPrior(chooseSnippetPrior(a, in, priorSource))), {}};
  ViewInput view;
  view.uvMm = in.frames3d.rows() > 0 ? projectFramesToView(in.frames3dOverground, *a.projectAngleDeg)
                                     : in.view.framesMm;
  view.rateHz = in.view.rateHz;
  view.alphaDeg = a.angleDeg;
  view.name = a.input;
  if (!a.save2d.empty()) writeViewCsv(a.save2d, {view.uvMm, view.rateHz}, {"2D view of " + a.input + " (overground)"});
  const EngineResult r = reconstructWithEngine(engine, view);
  const SnippetSequence& seq = *r.snippet;
  json report = {{"input", a.input}, {"engine", "snippet"}, {"prior", priorSource},
                 {"frames", view.uvMm.rows()}, {"rate_hz", view.rateHz}, {"angle_deg", r.alphaDeg},
                 {"angle_source", a.angleDeg ? "given" : "estimated"}, {"snippets", seq.starts.size()},
                 {"snippet_rate_hz", seq.rateHz}, {"reprojection_rms_mm", r.reprojectionRmsMm},
                 {"output", a.out}};
  if (!a.angleDeg) report["snippet_angles_deg"] = seq.freeAlphaDeg;
  std::cerr << std::fixed << std::setprecision(2) << "snippet engine: view " << r.alphaDeg << " deg ("
            << report["angle_source"].get<std::string>() << "), " << seq.starts.size() << " snippets, reprojection RMS "
            << r.reprojectionRmsMm << " mm\n";
  if (in.frames3d.rows() > 0) {
    const ClipErrors e = clipErrors(r.framesMm, in.frames3dOverground, *a.projectAngleDeg);
    report["true_angle_deg"] = *a.projectAngleDeg;
    report["angle_error_deg"] = viewAngleErrorDeg(r.alphaDeg, *a.projectAngleDeg);
    report["errors"] = {{"mpjpe_frames_mm", e.mpjpeMm}, {"abs_error_frames_mm2", e.depthErrorMm2}};
    std::cerr << std::setprecision(1) << "vs the trial's frames (mean translation removed): MPJPE " << e.mpjpeMm
              << " mm, E_a " << e.depthErrorMm2 << " mm2\n";
  }
  std::ostringstream angle;
  angle << r.alphaDeg;
  writeJointTrajectories(a.out, r.framesMm, view.rateHz,
                {"snippet-engine reconstruction of " + a.input + " (MAP, view " + angle.str() + " deg)",
                 "prior " + report["prior"].get<std::string>()});
  std::cerr << "wrote " << a.out << "\n";
  if (a.json) std::cout << report.dump(2) << "\n";
  return 0;
}

// [SECTION] The skeleton engine

SkeletonArgs skeletonArgs(const ReconstructArgs& a) {
  const auto refuse = [](bool given, const char* option) {
    if (given) throw Error(ErrorKind::BadArgument, option, "", "does not apply to --engine skeleton");
  };
  refuse(!a.model.empty() || a.components.has_value(), "--model");
  refuse(!a.prior.empty(), "--prior");
  refuse(a.angleDeg.has_value() || a.unknownAngle, "--angle");
  refuse(a.projectAngleDeg.has_value(), "--project-angle");
  refuse(a.elevationDeg.has_value() || a.orthographic, "--elevation");
  refuse(!a.save2d.empty() || a.dataPreserving, "--save-2d");
  refuse(a.noDetectorOffsets, "--no-detector-offsets");
  SkeletonArgs s;
  s.input = a.input, s.out = a.out, s.layout = a.layout, s.camera = a.camera, s.cameraName = a.cameraName;
  s.reference = a.reference, s.fps = a.fps, s.json = a.json, s.angles = a.angles;
  s.focalPx = a.focalPx, s.imageSize = a.imageSize, s.scaleDepthFrame = a.scaleDepthFrame;
  s.scaleDepthChain = a.scaleDepthChain, s.bones = a.bones, s.statureM = a.statureM, s.boneFrame = a.boneFrame;
  s.referenceBone = a.referenceBone, s.guide = a.guide;
  s.detectModel = a.detectModel;
  return s;
}

// [SECTION] The eigenwalker

int runReconstruct(const ReconstructArgs& a) {
  const EngineKind engine = parseEngineKind(a.engine, "--engine");
  // Before any file is read: a clip that is not walking must not hide a focal length no camera has.
  if (a.focalPx && !isPlausibleFocalPx(*a.focalPx))
    throw Error(ErrorKind::BadArgument, "--focal-px", "", focalLengthProblem(*a.focalPx));
  if (engine != EngineKind::Skeleton && a.skeletonOnlyGiven())
    throw Error(ErrorKind::BadArgument, "--bones", "",
                "--bones, --stature, --bone-frame, --reference-bone, --guide and --scale-depth-* apply to --engine skeleton only");
  if (engine == EngineKind::Snippet) return runReconstructSnippet(a);
  if (engine == EngineKind::Skeleton) return runReconstructSkeleton(skeletonArgs(a));
  if (!a.reference.empty())
    throw Error(ErrorKind::BadArgument, "--reference", "", "a 3D reference applies to --engine skeleton only");
  if (!a.angles.empty())
    throw Error(ErrorKind::BadArgument, "--angles", "",
                "--angles applies to --engine skeleton; for another engine run `angles` on the 3D CSV it writes");
  if (!a.prior.empty())
    throw Error(ErrorKind::BadArgument, "--prior", "", "a snippet prior applies to --engine snippet only");
  if (a.unknownCamera) {
    if (a.unknownAngle || a.projectAngleDeg)
      throw Error(ErrorKind::BadArgument, "--unknown-camera", "",
                  "the camera's azimuth is estimated (or given with --angle): --unknown-angle and --project-angle "
                  "do not apply");
    ChosenModel chosen = chooseModel(a);
    applyComponents(chosen, a);
    CameraArgs c;
    c.input = a.input, c.out = a.out, c.layout = a.layout, c.method = a.method, c.modelName = chosen.name;
    c.mapping = a.mapping, c.imageSize = a.imageSize, c.fps = a.fps, c.focalPx = a.focalPx;
    c.sigma2Mm2 = a.sigma2Mm2, c.json = a.json, c.orthographic = a.orthographic;
    c.detectorOffsets = !a.noDetectorOffsets;
    c.alphaDeg = a.angleDeg, c.elevationDeg = a.elevationDeg;
    c.camera = a.camera, c.cameraName = a.cameraName;
    c.detectModel = a.detectModel;
    c.modelLoop = a.modelLoop;
    c.corrections = a.corrections;
    c.person = a.person;
    return runReconstructCamera(chosen.model, c);
  }
  if (a.elevationDeg || !a.camera.empty())
    throw Error(ErrorKind::BadArgument, a.elevationDeg ? "--elevation" : "--camera", "",
                "a camera elevation or calibration applies to --unknown-camera only");
  if (a.noDetectorOffsets)
    throw Error(ErrorKind::BadArgument, "--no-detector-offsets", "", "applies to --unknown-camera only");
  if (a.angleDeg.has_value() == a.unknownAngle) {
    throw Error(ErrorKind::BadArgument, "--angle", "", "give exactly one of --angle DEG and --unknown-angle");
  }
  ChosenModel chosen = chooseModel(a);
  const Input in = readInput(a);
  const std::string heldOut = holdOutTheInputsSubject(chosen, in, a);
  applyComponents(chosen, a);
  const EigenwalkerModel& model = chosen.model;
  const double sigma2Mm2 = a.sigma2Mm2.value_or(defaultSigma2Mm2(model));
  if (!a.save2d.empty()) writeViewCsv(a.save2d, in.view, {"2D view of " + a.input});
  FourierFitOptions fitOptions;
  fitOptions.omegaHintRadS = in.omegaHintRadS;
  fitOptions.file = a.input;
  const FourierFit fit2d =
      fitFourierMeasured(in.view.framesMm, in.view.rateHz, in.missing, fitOptions);
  std::vector<int> missingJoints;
  for (int j = 0; j < kJointCount; ++j)
    if (in.missing[static_cast<size_t>(j)]) missingJoints.push_back(j);
  const ModelGram gram = precomputeModelGram(model, missingJoints);
  const EstimatorOptions estimator{a.method == "map" ? Estimator::Map : Estimator::Lsq, sigma2Mm2};
  json report = {{"input", a.input},
                 {"model", chosen.name},
                 {"held_out", heldOut.empty() ? json(nullptr) : json(heldOut)},
                 {"components", model.componentCount()},
                 {"method", a.method},
                 {"output", a.out},
                 {"stride_hz", fit2d.omegaRadS / (2 * std::numbers::pi)},
                 {"cycles", fit2d.cycles},
                 {"phase_rad", fit2d.phaseRad},
                 {"frames", in.view.framesMm.rows()},
                 {"rate_hz", in.view.rateHz}};
  if (a.method == "map") {
    report["sigma2_mm2"] = sigma2Mm2;
    report["sigma2_source"] =
        a.sigma2Mm2 ? std::string("given (--sigma2)") : chosen.sigma2Source;
  }
  Reconstruction rec;
  if (a.angleDeg) {
    rec = reconstructKnownView(gram, fit2d.w, *a.angleDeg, estimator);
    report["angle_source"] = "given";
  } else {
    const ViewSearch s = searchViewAngle(gram, fit2d.w, estimator);
    rec = s.best;
    report["angle_source"] = "estimated";
    report["minima"] = minimaJson(s);
  }
  report["angle_deg"] = rec.alphaDeg;
  report["k"] = std::vector<double>(rec.k.data(), rec.k.data() + rec.k.size());
  report["data_preserving"] = a.dataPreserving;
  report["joints_model_estimated"] = jointNames(in.missing);
  const Eigen::VectorXd& wOut = a.dataPreserving ? rec.wDataPreserving : rec.w;
  if (in.frames3d.rows() > 0) {
    report["true_angle_deg"] = *a.projectAngleDeg;
    report["angle_error_deg"] = viewAngleErrorDeg(rec.alphaDeg, *a.projectAngleDeg);
    report["errors"] = truthErrors(in, fit2d, wOut, *a.projectAngleDeg);
  }
  const Eigen::MatrixXd frames = synthesizeFrames(wOut, fit2d.omegaRadS, fit2d.phaseRad,
                                                  frameTimes(static_cast<int>(in.view.framesMm.rows()), in.view.rateHz));
  std::ostringstream angle;
  angle << rec.alphaDeg;
  std::vector<std::string> comments = {
      "eigenwalker reconstruction of " + a.input + " (" + a.method + ", view " + angle.str() +
          " deg)",
      "model " + chosen.name + ", " + std::to_string(model.componentCount()) + " eigenwalkers"};
  if (anyJoint(in.missing))
    comments.push_back("model_estimated_joints=" + jointList(in.missing) +
                       " (not in the input: estimated from the model)");
  writeJointTrajectories(a.out, frames, in.view.rateHz, comments);
  printReport(report);
  if (a.json) std::cout << report.dump(2) << "\n";
  return 0;
}

}  // namespace

void addReconstructCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<ReconstructArgs>();
  auto* cmd = app.add_subcommand(
      "reconstruct",
      "3D walker from a 2D sequence (docs/METHOD.md §6). --input is a 2D CSV frame,time_s,head_u,head_v,...,l_ankle_v "
      "(mm; docs/EXPERIMENTS.md) or a 3D trial viewed at --project-angle (errors against it reported). "
      "Writes the 15-joint 3D CSV over the input's duration.");
  cmd->add_option("--engine", args->engine,
                  "eigenwalker (Zhang & Troje 2007), snippet (Howe, Leventon & Freeman 1999; docs/SNIPPETS.md) or "
                  "skeleton (Zou et al. 2009: keypoints through a calibrated --camera with --reference bone lengths)")
      ->check(CLI::IsMember({"eigenwalker", "snippet", "skeleton"}))
      ->capture_default_str();
  cmd->add_option("--reference", args->reference,
                  "--engine skeleton: a 3D trial of the same person and frames (e.g. Pose2Sim's triangulated TRC): "
                  "its bone lengths are used and the result is scored against it")
      ->check(CLI::ExistingFile);
  cmd->add_option("--angles", args->angles,
                  "--engine skeleton: also write the result's joint angles (.mot for OpenSim, or .csv; "
                  "docs/ANGLES.md)");
  cmd->add_option("--bones", args->bones,
                  "--engine skeleton: where the bone lengths come from: reference (--reference, the default when "
                  "given), table2 (Zou et al.'s Table 2 at --stature), eigenwalker (the eigenwalker's fit of this "
                  "walker, scaled to --stature when given), frame (--bone-frame and --reference-bone)")
      ->check(CLI::IsMember({"reference", "table2", "eigenwalker", "frame"}));
  cmd->add_option("--stature", args->statureM, "--engine skeleton: the walker's stature in metres (--bones table2, eigenwalker)")
      ->check(CLI::Range(0.5, 2.5));
  cmd->add_option("--bone-frame", args->boneFrame,
                  "--engine skeleton, --bones frame: a frame (0-based) with the body parallel to the image plane (§4.1)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--reference-bone", args->referenceBone,
                  "--engine skeleton, --bones frame: the bone of known length, JOINT-JOINT=MM (e.g. r_elbow-r_wrist=260)");
  cmd->add_option("--guide", args->guide,
                  "--engine skeleton: choose each bone's depth branch nearer the eigenwalker's fit of the walker")
      ->check(CLI::IsMember({"eigenwalker"}));
  cmd->add_option("--scale-depth-frame", args->scaleDepthFrame,
                  "--engine skeleton without --camera or --focal-px: the frame (0-based) for Zou et al.'s "
                  "scale-depth relation T(dz), with --scale-depth-chain and --image-size")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--scale-depth-chain", args->scaleDepthChain,
                  "--engine skeleton: four joints a,b,c,d of three linked segments, the outer two parallel to the "
                  "image plane on --scale-depth-frame (e.g. sternum,r_shoulder,r_elbow,r_wrist)");
  cmd->add_option("--prior", args->prior,
                  "Snippet prior from `build --engine snippet` (default: learnt from the embedded synthetic "
                  "population)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--model", args->model,
                  "Model file from `build` (default: the built-in model of 24 real walkers)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--components", args->components,
                  "Use the first N eigenwalkers of the model (as the viewer's N)")
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--input", args->input,
                  "2D CSV or 3D trial file; with --unknown-camera a pose estimator's keypoints "
                  "(OpenPose folder or JSON, AlphaPose or MMPose JSON) or a video (MP4, MOV, AVI…: the built-in "
                  "detector finds the walker; --unknown-camera is then implied)")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--detect-model", args->detectModel,
                  "For a video: the built-in pose detector's model, lite, full (default) or heavy")
      ->check(CLI::IsMember({"lite", "full", "heavy"}));
  cmd->add_option("--person", args->person,
                  "With --unknown-camera: the person to fit (1-based, as `info` and `detect` number them); default the "
                  "one who walks")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--corrections", args->corrections,
                  "With --unknown-camera: a keyframe file (docs/TRACKING.md) of joints corrected by hand; each "
                  "correction is carried to the frames around it (0.25 s either side, fading)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--model-loop", args->modelLoop,
                  "With --unknown-camera: rounds of the model loop, where joints the detector is unsure of are pulled "
                  "towards the fitted walker and the fit is made again (default 1 for a video, 0 for keypoint files)")
      ->check(CLI::Range(0, 5));
  cmd->add_flag("--unknown-camera", args->unknownCamera,
                "Keypoints in pixels through an unknown real camera (docs/CAMERA.md): estimates azimuth, "
                "elevation, scale or distance, image translation and progression with the walker");
  cmd->add_option("--layout", args->layout, "Keypoint layout (BODY_25, BODY_25B, COCO-18, COCO-17, Halpe-26, "
                                            "MediaPipe-33); guessed when not given");
  cmd->add_option("--fps", args->fps, "Video frame rate of keypoint input (JSON stores none; default 30)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--focal-px", args->focalPx,
                  "Known focal length in pixels (else it is estimated with the camera)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--elevation", args->elevationDeg,
                  "With --unknown-camera: the camera's known elevation in degrees (looking down), held "
                  "instead of estimated; --angle likewise holds the azimuth")
      ->check(CLI::Range(-30.0, 80.0));
  cmd->add_option("--camera", args->camera,
                  "With --unknown-camera: a calibration file (Pose2Sim Calib_*.toml, Sports2D Calib_demo.toml) "
                  "giving the focal length and principal point (and a MediaPipe CSV's image size)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--camera-name", args->cameraName, "Which camera of a --camera file with several (its name)");
  cmd->add_option("--image-size", args->imageSize,
                  "WxH in pixels of the video behind the keypoints: a MediaPipe CSV's and YOLO labels' "
                  "coordinates are fractions of it; with --unknown-camera the fit expects the camera's principal "
                  "point near its centre (docs/CAMERA.md). Else the size of a video found beside the keypoints "
                  "(docs/KEYPOINTS.md)");
  cmd->add_flag("--orthographic", args->orthographic,
                "With --unknown-camera and no --focal-px: scaled orthography instead of a pinhole "
                "whose focal length is estimated (a distant camera)");
  cmd->add_flag("--no-detector-offsets", args->noDetectorOffsets,
                "With --unknown-camera: take the detector's hips for hip-joint centres instead of allowing for "
                "the layout's detector offsets (docs/KEYPOINTS.md, \"Detector hips\")");
  cmd->add_option("--mapping", args->mapping,
                  "Joint mapping file (JSON, docs/FORMATS.md) for a 3D marker input whose set "
                  "the program does not know, or a DeepLabCut keypoint file's body parts");
  cmd->add_option("--out", args->out, "3D joints to write: the 15-joint CSV, or a TRC (OpenSim's axes) when it ends in .trc")->required();
  cmd->add_option("--angle", args->angleDeg, "Known view angle in degrees (0 frontal, +-90 profile)");
  cmd->add_flag("--unknown-angle", args->unknownAngle, "Estimate the view angle over the whole circle");
  cmd->add_option("--method", args->method, "lsq or map")->check(CLI::IsMember({"lsq", "map"}))->capture_default_str();
  cmd->add_option("--sigma2", args->sigma2Mm2,
                  "MAP noise variance (mm^2); default: the optimum stored in the model, else 70")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--project-angle", args->projectAngleDeg, "View a 3D input at this angle (degrees)");
  cmd->add_option("--save-2d", args->save2d, "Also write the 2D sequence that was reconstructed (2D CSV)");
  cmd->add_flag("--data-preserving", args->dataPreserving, "Keep the observed u, v; only depth from the model (eq. 3.16)");
  cmd->add_flag("--in-sample", args->inSample,
                "A 3D input whose subject the model holds is reconstructed by the model without it (leave-one-"
                "subject-out, as the viewer does); this uses the whole model instead (an in-sample fit)");
  cmd->add_flag("--json", args->json, "Print the result (angle, k, errors) as JSON on stdout");
  cmd->callback([args, &exitCode] {
    // A video is seen through a real camera: its keypoints go the unknown-camera way.
    if (isVideoFile(args->input) && args->engine != "snippet") args->unknownCamera = true;
    exitCode = runReconstruct(*args);
  });
}

}  // namespace ew::cli
