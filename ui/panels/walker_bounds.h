#pragma once
// Where a walker is on screen over its whole cycle: the rectangle a view's caption, legend and
// colour bar keep clear of (the whole cycle, so that they do not come and go as it walks).

#include <imgui.h>
#include <imgui_internal.h>

#include <Eigen/Core>

#include "ui/render/scene.h"

namespace ew::ui {

// The screen rectangle of the 3D walkers `w` (225-vectors, Fourier form) through `camera`
// in a view at `p0` of `size`, grown by `marginPx` (the joints' spheres). Nothing (an empty
// rectangle at p0) when there is no walker.
ImRect walkerBounds3(std::initializer_list<const Eigen::VectorXd*> w, const CameraMatrices& camera, ImVec2 p0,
                     ImVec2 size, float marginPx);
// The same for 2D points: a trail (one row per sample, u0 v0 u1 v1 … in mm) through an
// orthographic image camera.
ImRect trailBounds2(const Eigen::MatrixXd& trail, const CameraMatrices& camera, ImVec2 p0, ImVec2 size, float marginPx);

}  // namespace ew::ui
