// `eigenwalker-cli reconstruct --model MODEL --input FILE (--angle DEG | --unknown-angle)
//  [--method lsq|map] [--sigma2 MM2] --out OUT.csv [--project-angle DEG] [--json]`:
// the 3D walker behind a 2D sequence (SPEC §6). FILE is a 2D CSV (docs/EXPERIMENTS.md) or
// any 3D trial the loaders read, projected at --project-angle (ground truth known: errors
// of SPEC §7 are reported).
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "app/cli/commands.h"
#include "core/common/errors.h"
#include "core/engine/fourier.h"
#include "core/engine/metrics.h"
#include "core/engine/model_file.h"
#include "core/engine/projection.h"
#include "core/engine/reconstruction.h"
#include "core/experiments/view_csv.h"
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
  double sigma2Mm2 = 70.0;
};

// The 2D input and, for a 3D file, the truth it came from.
struct Input {
  ViewSequence view;
  std::optional<double> omegaHintRadS;
  Eigen::MatrixXd frames3d;  // empty for a 2D file
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
    return in;
  }
  if (!a.projectAngleDeg) {
    throw Error(ErrorKind::BadArgument, "--project-angle", "",
                a.input + " is a 3D trial: give --project-angle DEG to view it in 2D (or pass a 2D CSV)");
  }
  const WalkingTrial trial = loadWalkingTrial(a.input);
  in.frames3d = trial.joints.positionsMm;
  in.view = {projectFramesToView(in.frames3d, *a.projectAngleDeg), trial.joints.rateHz};
  if (trial.cycles.strideHz > 0 && std::isfinite(trial.cycles.strideHz)) in.omegaHintRadS = 2.0 * std::numbers::pi * trial.cycles.strideHz;
  return in;
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

// SPEC §7 errors against the 3D truth: Fourier (one cycle) and raw frames.
json truthErrors(const Input& in, const FourierFit& fit2d, const Eigen::VectorXd& wRec, double trueAngleDeg) {
  FourierFitOptions o;
  o.omegaFixedRadS = fit2d.omegaRadS;
  const FourierFit truth = fitFourier(in.frames3d, in.view.rateHz, o);
  const Eigen::VectorXd aligned = rephase(wRec, fit2d.phaseRad, truth.phaseRad);
  const DepthErrors e = depthErrors(truth.w, aligned, trueAngleDeg);
  const DepthErrors f = depthErrorsFrames(in.frames3d, in.view.rateHz, wRec, fit2d.omegaRadS, fit2d.phaseRad, trueAngleDeg);
  return {{"abs_error_mm2", e.absMean}, {"rel_error", e.relMean}, {"var_missing_mm2", e.sigmaM2Mm2},
          {"mpjpe_mm", mpjpe(truth.w, aligned)}, {"abs_error_frames_mm2", f.absMean},
          {"mpjpe_frames_mm", mpjpeFrames(in.frames3d, in.view.rateHz, wRec, fit2d.omegaRadS, fit2d.phaseRad)}};
}

void printReport(const json& r) {
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
  std::cerr << "wrote " << r["output"].get<std::string>() << "\n";
}

int runReconstruct(const ReconstructArgs& a) {
  if (a.angleDeg.has_value() == a.unknownAngle) {
    throw Error(ErrorKind::BadArgument, "--angle", "", "give exactly one of --angle DEG and --unknown-angle");
  }
  const EigenwalkerModel model = loadModel(a.model);
  const Input in = readInput(a);
  if (!a.save2d.empty()) writeViewCsv(a.save2d, in.view, {"2D view of " + a.input});
  FourierFitOptions fitOptions;
  fitOptions.omegaHintRadS = in.omegaHintRadS;
  fitOptions.file = a.input;
  const FourierFit fit2d = fitFourier(in.view.framesMm, in.view.rateHz, fitOptions);
  const ModelGram gram = precomputeModelGram(model);
  const EstimatorOptions estimator{a.method == "map" ? Estimator::Map : Estimator::Lsq, a.sigma2Mm2};
  json report = {{"input", a.input}, {"model", a.model}, {"method", a.method}, {"output", a.out},
                 {"stride_hz", fit2d.omegaRadS / (2 * std::numbers::pi)}, {"cycles", fit2d.cycles},
                 {"phase_rad", fit2d.phaseRad}, {"frames", in.view.framesMm.rows()}, {"rate_hz", in.view.rateHz}};
  if (a.method == "map") report["sigma2_mm2"] = a.sigma2Mm2;
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
  writeJointCsv(a.out, frames, in.view.rateHz,
                {"eigenwalker reconstruction of " + a.input + " (" + a.method + ", view " + angle.str() + " deg)",
                 "model " + a.model});
  printReport(report);
  if (a.json) std::cout << report.dump(2) << "\n";
  return 0;
}

}  // namespace

void addReconstructCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<ReconstructArgs>();
  auto* cmd = app.add_subcommand(
      "reconstruct",
      "3D walker from a 2D sequence (SPEC §6). --input is a 2D CSV frame,time_s,head_u,head_v,...,l_ankle_v "
      "(mm; docs/EXPERIMENTS.md) or a 3D trial viewed at --project-angle (errors against it reported). "
      "Writes the 15-joint 3D CSV over the input's duration.");
  cmd->add_option("--model", args->model, "Model file from `build`")->required()->check(CLI::ExistingFile);
  cmd->add_option("--input", args->input, "2D CSV or 3D trial file")->required()->check(CLI::ExistingFile);
  cmd->add_option("--out", args->out, "3D joint CSV to write")->required();
  cmd->add_option("--angle", args->angleDeg, "Known view angle in degrees (0 frontal, +-90 profile)");
  cmd->add_flag("--unknown-angle", args->unknownAngle, "Estimate the view angle over the whole circle");
  cmd->add_option("--method", args->method, "lsq or map")->check(CLI::IsMember({"lsq", "map"}))->capture_default_str();
  cmd->add_option("--sigma2", args->sigma2Mm2, "MAP noise variance (mm^2)")->check(CLI::PositiveNumber)->capture_default_str();
  cmd->add_option("--project-angle", args->projectAngleDeg, "View a 3D input at this angle (degrees)");
  cmd->add_option("--save-2d", args->save2d, "Also write the 2D sequence that was reconstructed (2D CSV)");
  cmd->add_flag("--data-preserving", args->dataPreserving, "Keep the observed u, v; only depth from the model (eq. 3.16)");
  cmd->add_flag("--json", args->json, "Print the result (angle, k, errors) as JSON on stdout");
  cmd->callback([args, &exitCode] { exitCode = runReconstruct(*args); });
}

}  // namespace ew::cli
