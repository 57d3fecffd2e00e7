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

struct ReconstructionViewPanel {
  gl::RenderTarget target;
  Scene scene;

  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
