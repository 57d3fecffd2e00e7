#pragma once
// The profile objective J(α) of the unknown-view search over (−180°, 180°], log scale,
// with its local minima (the mirror and facing ambiguities), α̂ and the true α. Drawn with
// ImDrawList.

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct ProfilePanel {
  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
