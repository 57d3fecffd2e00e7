#pragma once
// The message log: loads, data warnings, errors.

#include <cstddef>

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct LogPanel {
  std::size_t seenEntries = 0;  // scroll to the bottom when new entries arrive
  bool showInfo = true;

  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
