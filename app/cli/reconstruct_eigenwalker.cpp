// `reconstruct` on an orthographic view (a 2D CSV, or a 3D trial viewed at --project-angle):
// the eigenwalker (METHOD §6) through reconstruct(engine, request), its report and, for a 3D
// input, its errors against the truth (METHOD §7).
#include "app/cli/reconstruct_runners.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "app/cli/reconstruct_view.h"
#include "core/common/errors.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/joint_completion.h"
#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/projection.h"
#include "core/engines/request.h"
#include "core/io/joint_csv.h"
#include "core/io/trc_writer.h"

namespace ew::cli {

namespace {

using nlohmann::json;

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

json reportOf(const ReconstructArgs& a, const ChosenModel& chosen, const std::string& heldOut, const Input& in,
              const EigenwalkerDiagnostics& d) {
  const EigenwalkerModel& model = chosen.model;
  json report = {{"input", a.input},
                 {"model", chosen.name},
                 {"held_out", heldOut.empty() ? json(nullptr) : json(heldOut)},
                 {"components", model.componentCount()},
                 {"method", a.method},
                 {"output", a.out},
                 {"stride_hz", d.fit2d.omegaRadS / (2 * std::numbers::pi)},
                 {"cycles", d.fit2d.cycles},
                 {"phase_rad", d.fit2d.phaseRad},
                 {"frames", in.view.framesMm.rows()},
                 {"rate_hz", in.view.rateHz}};
  if (a.method == "map") {
    report["sigma2_mm2"] = a.sigma2Mm2.value_or(defaultSigma2Mm2(model));
    report["sigma2_source"] = a.sigma2Mm2 ? std::string("given (--sigma2)") : chosen.sigma2Source;
  }
  report["angle_source"] = a.alphaDeg ? "given" : "estimated";
  if (d.search) report["minima"] = minimaJson(*d.search);
  const Reconstruction& rec = d.reconstruction;
  report["angle_deg"] = rec.alphaDeg;
  report["k"] = std::vector<double>(rec.k.data(), rec.k.data() + rec.k.size());
  report["data_preserving"] = a.dataPreserving;
  report["joints_model_estimated"] = jointNames(in.missing);
  if (in.frames3d.rows() > 0) {
    report["true_angle_deg"] = *a.projectAngleDeg;
    report["angle_error_deg"] = viewAngleErrorDeg(rec.alphaDeg, *a.projectAngleDeg);
    report["errors"] = truthErrors(in, d.fit2d, a.dataPreserving ? rec.wDataPreserving : rec.w, *a.projectAngleDeg);
  }
  return report;
}

void writeWalker(const ReconstructArgs& a, const ChosenModel& chosen, const Input& in, const EigenwalkerDiagnostics& d) {
  const Reconstruction& rec = d.reconstruction;
  const Eigen::VectorXd& w = a.dataPreserving ? rec.wDataPreserving : rec.w;
  const Eigen::MatrixXd frames = synthesizeFrames(w, d.fit2d.omegaRadS, d.fit2d.phaseRad,
                                                  frameTimes(static_cast<int>(in.view.framesMm.rows()), in.view.rateHz));
  std::ostringstream angle;
  angle << rec.alphaDeg;
  std::vector<std::string> comments = {
      "eigenwalker reconstruction of " + a.input + " (" + a.method + ", view " + angle.str() + " deg)",
      "model " + chosen.name + ", " + std::to_string(chosen.model.componentCount()) + " eigenwalkers"};
  if (anyJoint(in.missing))
    comments.push_back("model_estimated_joints=" + jointList(in.missing) + " (not in the input: estimated from the model)");
  writeJointTrajectories(a.out, frames, in.view.rateHz, comments);
}

}  // namespace

int runReconstructEigenwalker(const ReconstructArgs& a) {
  if (a.alphaDeg.has_value() == a.unknownAngle)
    throw Error(ErrorKind::BadArgument, "--angle", "", "give exactly one of --angle DEG and --unknown-angle");
  ChosenModel chosen = chooseModel(a);
  const Input in = readInput(a);
  const std::string heldOut = holdOutTheInputsSubject(chosen, in, a);
  applyComponents(chosen, a);
  if (!a.save2d.empty()) writeViewCsv(a.save2d, in.view, {"2D view of " + a.input});
  const EstimatorOptions estimator{a.method == "map" ? Estimator::Map : Estimator::Lsq,
                                   a.sigma2Mm2.value_or(defaultSigma2Mm2(chosen.model))};
  const ReconstructionResult r = reconstruct(EigenwalkerEngine{chosen.model, estimator, {}}, {viewInputOf(in, a)});
  const EigenwalkerDiagnostics& d = *r.engine.eigenwalker;
  const json report = reportOf(a, chosen, heldOut, in, d);
  writeWalker(a, chosen, in, d);
  printReport(report);
  if (a.json) std::cout << report.dump(2) << "\n";
  return 0;
}

}  // namespace ew::cli
