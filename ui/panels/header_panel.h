#pragma once
// The top bar: what is loaded, which model the reconstruction uses ("model: 23 walkers,
// CMU07 held out"), background progress, and the last export error with Dismiss (a failed
// open has its own banner: notice_panel.h).

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct HeaderPanel {
  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
