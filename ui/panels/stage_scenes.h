#pragma once
// The classroom stage drawn in the two views (ui/app/stage.h says what it is): the display's
// dots, the depth-reversed walker, the turning stage's view. The views call these instead of
// their usual scene builders while stageDrawsViews (ui/app/stage_actions.h).

#include <Eigen/Core>

#include "ui/render/scene.h"

namespace ew::ui {

struct AppState;

// The 2D view at playback time `cycles`: the stage's walker seen at the stage's azimuth and
// elevation, its noise dots, and the depth-reversed walker's dots as rings. False when there
// is no walker to show.
bool buildStageInputScene(const AppState& s, Scene& scene, float lineScale, double cycles);
// The 3D view: the walker as a figure (or dots, when the display has no form or point-lights
// are on), the noise dots, the depth-reversed walker beside it, the camera of the 2D view.
bool buildStageReconstructionScene(const AppState& s, Scene& scene, float lineScale, double cycles);
// Where the 2D view's dots go over one cycle (kTrailSamples rows of u, v pairs), what the
// view's framing and annotations keep clear of; empty without a walker.
Eigen::MatrixXd stageTrail2d(const AppState& s);

}  // namespace ew::ui
