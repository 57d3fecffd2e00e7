#pragma once
// The drawer's tab row (ui/app/layout.h): when the window is too small for the side and
// bottom columns, their six panels share one column and these tabs pick the one shown.

#include <string>

#include "ui/app/layout.h"
#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct DrawerPanel {
  DrawerTab active = DrawerTab::Controls;
  bool inUse = false;  // the last frame was laid out with the drawer (the app sets it)

  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
  bool shows(DrawerTab tab) const { return tab == active; }
};

// "subjects", "controls", "coefficients", "errors", "view", "log" (the script's names);
// throws std::invalid_argument naming them for anything else.
DrawerTab drawerTabFromName(const std::string& name);

}  // namespace ew::ui
