#pragma once
// Play/pause (space), speed 0.1–2×, gait-phase scrubbing, frame steps.

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct PlaybackPanel {
  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
