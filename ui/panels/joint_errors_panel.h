#pragma once
// Per-joint depth error bars (RMS over one cycle, √E_abs(j), mm), coloured like the joints.

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct JointErrorsPanel {
  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
