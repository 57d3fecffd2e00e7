#pragma once
// Right view: the 3D reconstruction, orbitable (drag), pannable (right-drag), zoomable
// (wheel), double-click to reset; floor grid, reconstruction, ground-truth ghost, error
// lines and colours, and the camera the 2D view is taken from.

#include "ui/gl/gl.h"
#include "ui/panels/panel_window.h"
#include "ui/render/scene.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

// The view's scene at a continuous gait-cycle count (its fraction is the phase; the floor
// scrolls with it): the panel draws it each frame, the video export at exact phases.
// errorScale receives the depth-error colour scale (mm). Returns false when there is
// nothing to show yet.
bool buildReconstructionScene(const AppState& s, Scene& scene, float lineScale, double cycles,
                              float* errorScale);

struct ReconstructionViewPanel {
  gl::RenderTarget target;
  Scene scene;
  PanelRect lastImage;  // where the view was drawn last frame (screen pixels), for PNG export

  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
