#pragma once
// Mode, view angle, estimator, σ², N, unknown-angle mode, camera presets, overlays and
// the UI scale.

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct ControlsPanel {
  float pendingUiScale = 0.0f;  // while the scale slider is dragged (applied on release)

  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
  // The 3D camera presets, overlays and display settings (every mode).
  void drawViewControls(AppState& s, const FrameContext& ctx);
};

}  // namespace ew::ui
