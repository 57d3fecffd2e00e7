#pragma once
// `reconstruct`'s routes (reconstruct_args.h, routeOf), one runner each. Every runner builds
// a ReconstructionRequest (core/engines/request.h) and answers it with its engine.
#include "app/cli/reconstruct_args.h"
#include "app/cli/reconstruct_camera.h"
#include "app/cli/reconstruct_skeleton.h"

namespace ew::cli {

// The eigenwalker on an orthographic view: a 2D CSV, or a 3D trial viewed at --project-angle
// (errors against it reported; its subject held out of the model).
int runReconstructEigenwalker(const ReconstructArgs& args);
// The snippet engine on the same views.
int runReconstructSnippet(const ReconstructArgs& args);

}  // namespace ew::cli
