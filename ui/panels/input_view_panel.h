#pragma once
// Left view: the 2D input — the held-out walker's orthographic projection at α, exactly
// what the reconstruction sees — as point-lights (optionally a stick figure and each
// point's path over the cycle), with the reconstruction projected back and the 2D residual.

#include "ui/gl/gl.h"
#include "ui/panels/panel_window.h"
#include "ui/render/scene.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct InputViewPanel {
  gl::RenderTarget target;
  Scene scene;  // rebuilt every frame; kept to reuse its allocations

  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
