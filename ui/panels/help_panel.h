#pragma once
// F1: the keyboard shortcuts and mouse controls, as an overlay in the middle of the window.

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct HelpPanel {
  bool open = false;

  void draw(AppState& s, const FrameContext& ctx);
};

}  // namespace ew::ui
