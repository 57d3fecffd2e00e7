#pragma once
// The metrics strip (METHOD §7): E_a, E_r, MPJPE, the 2D residual, α and est. α with its error.

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct MetricsPanel {
  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
