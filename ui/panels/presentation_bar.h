#pragma once
// Presentation mode's one row of controls under the two views (ui/app/layout.h): play / pause,
// the view angle as a dial and a slider, and the way back to the workspace.

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct PresentationBar {
  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
