// `eigenwalker-cli reconstruct`: the 3D walker behind a 2D input (METHOD §6), by one of
// four routes (reconstruct_args.h): the eigenwalker on an orthographic view (a 2D CSV, or a 3D
// trial viewed at --project-angle, its errors against the truth reported), the eigenwalker
// through a real camera (--unknown-camera: pose-estimator keypoints or a video, docs/CAMERA.md),
// the snippet engine (--engine snippet, docs/SNIPPETS.md) and the skeleton engine (--engine
// skeleton, Zou et al. 2009). Which options each route takes is one table
// (reconstruct_options.cpp); each runner asks its engine through reconstruct(engine, request)
// (core/engines/request.h).
#include <iostream>

#include "app/cli/commands.h"
#include "app/cli/reconstruct_runners.h"
#include "app/cli/reconstruct_view.h"
#include "core/camera/focal_length.h"
#include "core/common/errors.h"

namespace ew::cli {
namespace {

int runReconstructThroughCamera(const ReconstructArgs& a) {
  ChosenModel chosen = chooseModel(a);
  applyComponents(chosen, a);
  CameraArgs c = a;
  c.modelName = chosen.name;
  c.detectorOffsets = !a.noDetectorOffsets;
  return runReconstructCamera(chosen.model, c);
}

int runReconstruct(const ReconstructArgs& a) {
  // Before any file is read: a clip that is not walking must not hide a focal length no camera has.
  if (a.focalPx && !isPlausibleFocalPx(*a.focalPx))
    throw Error(ErrorKind::BadArgument, "--focal-px", "", focalLengthProblem(*a.focalPx));
  const ReconstructRoute route = routeOf(a);
  checkOptionsApply(a, route);
  switch (route) {
    case ReconstructRoute::EigenwalkerView: return runReconstructEigenwalker(a);
    case ReconstructRoute::EigenwalkerCamera: return runReconstructThroughCamera(a);
    case ReconstructRoute::Snippet: return runReconstructSnippet(a);
    case ReconstructRoute::Skeleton: return runReconstructSkeleton(a.skeletonArgs());
  }
  return 2;
}

}  // namespace

void addReconstructCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<ReconstructArgs>();
  auto* cmd = app.add_subcommand(
      "reconstruct",
      "3D walker from a 2D sequence (docs/METHOD.md §6). --input is a 2D CSV frame,time_s,head_u,head_v,...,l_ankle_v "
      "(mm; docs/EXPERIMENTS.md) or a 3D trial viewed at --project-angle (errors against it reported). "
      "Writes the 15-joint 3D CSV over the input's duration.");
  addReconstructOptions(*cmd, *args);
  cmd->callback([args, &exitCode] { exitCode = runReconstruct(*args); });
}

}  // namespace ew::cli
