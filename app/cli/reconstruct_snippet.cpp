// `reconstruct --engine snippet`: Howe, Leventon & Freeman's snippet engine (core/snippet,
// docs/SNIPPETS.md) on an orthographic view, through reconstruct(engine, request). Without
// --prior its prior is learnt from the default model's real walkers (without the input's
// subject when it is one of them).
#include "app/cli/reconstruct_runners.h"

#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli/reconstruct_view.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/metrics.h"
#include "core/eigenwalker/projection.h"
#include "core/engines/request.h"
#include "core/experiments/snippet_experiment.h"
#include "core/io/joint_csv.h"
#include "core/snippet/snippet_file.h"

namespace ew::cli {

namespace {

using nlohmann::json;

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

}  // namespace

int runReconstructSnippet(const ReconstructArgs& a) {
  if (a.alphaDeg.has_value() == a.unknownAngle)
    throw Error(ErrorKind::BadArgument, "--angle", "", "give exactly one of --angle DEG and --unknown-angle");
  const Input in = readInput(a);
  std::string priorSource;
  const SnippetEngine engine{
      std::make_shared<const PreparedSnippetPrior>(prepareSnippetPrior(chooseSnippetPrior(a, in, priorSource))), {}};
  // The snippet prior was learnt overground: a 3D input is viewed with its progression.
  ViewInput view;
  view.uvMm = in.frames3d.rows() > 0 ? projectFramesToView(in.frames3dOverground, *a.projectAngleDeg)
                                     : in.view.framesMm;
  view.rateHz = in.view.rateHz;
  view.alphaDeg = a.alphaDeg;
  view.name = a.input;
  if (!a.save2d.empty()) writeViewCsv(a.save2d, {view.uvMm, view.rateHz}, {"2D view of " + a.input + " (overground)"});
  const EngineResult r = reconstruct(engine, {view}).engine;
  const SnippetSequence& seq = *r.snippet;
  json report = {{"input", a.input}, {"engine", "snippet"}, {"prior", priorSource},
                 {"frames", view.uvMm.rows()}, {"rate_hz", view.rateHz}, {"angle_deg", r.alphaDeg},
                 {"angle_source", a.alphaDeg ? "given" : "estimated"}, {"snippets", seq.starts.size()},
                 {"snippet_rate_hz", seq.rateHz}, {"reprojection_rms_mm", r.reprojectionRmsMm},
                 {"output", a.out}};
  if (!a.alphaDeg) report["snippet_angles_deg"] = seq.freeAlphaDeg;
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

}  // namespace ew::cli
