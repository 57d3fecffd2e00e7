#pragma once
// Eigenwalker coefficients in units of each component's SD (±3). Explore mode: sliders
// that synthesise a walker (reset, randomise, start from the selected subject).
// Reconstruct mode: the estimated k; dragging one shows how the 2D reprojection, the 3D
// reconstruction and the residual change (reset returns to the estimate).

#include "ui/panels/panel_window.h"
#include "ui/panels/semantic_controls.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct CoefficientsPanel {
  unsigned randomSeed = 1;
  SemanticControls semantic;

  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
