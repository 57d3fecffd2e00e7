#include "app/cli/reconstruct_view.h"

#include <cmath>
#include <fstream>
#include <iostream>
#include <numbers>

#include "core/common/errors.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/eigenwalker/joint_completion.h"
#include "core/eigenwalker/model_file.h"
#include "core/eigenwalker/model_membership.h"
#include "core/eigenwalker/projection.h"
#include "core/gait/dataset.h"

namespace ew::cli {

namespace fs = std::filesystem;

namespace {

bool isViewCsv(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorKind::Io, file.string(), "", "cannot open file");
  std::string head(4096, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(in.gcount()));
  return looksLikeViewCsv(head);
}

}  // namespace

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

void applyComponents(ChosenModel& c, const ReconstructArgs& a) {
  if (a.components) c.model = leadingComponents(c.model, std::min(*a.components, c.model.componentCount()));
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

std::string inputSubjectInModel(const EigenwalkerModel& model, const Input& in, const ReconstructArgs& a) {
  if (in.frames3d.rows() == 0) return "";
  FourierFitOptions o;
  o.omegaHintRadS = in.omegaHintRadS;
  o.file = a.input;
  const FourierFit fit = fitFourierMeasured(in.frames3d, in.view.rateHz, in.missing, o);
  return subjectInModel(model, subjectFromFileName(a.input), fit.w);
}

// Its errors against the truth would otherwise be those of a walker the model has seen.
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

ViewInput viewInputOf(const Input& in, const ReconstructArgs& a) {
  ViewInput view;
  view.uvMm = in.view.framesMm;
  // A joint the input does not measure is unseen in every frame, whatever a 3D trial holds there.
  for (int j = 0; j < kJointCount; ++j)
    if (in.missing[static_cast<size_t>(j)]) view.uvMm.middleCols<2>(2 * j).setConstant(std::nan(""));
  view.rateHz = in.view.rateHz;
  view.alphaDeg = a.alphaDeg;
  if (in.omegaHintRadS) view.strideHzHint = *in.omegaHintRadS / (2.0 * std::numbers::pi);
  view.inPlace = true;  // a 2D CSV of the experiments, or a trial's canonical frames
  view.name = a.input;
  return view;
}

}  // namespace ew::cli
