#pragma once
// The subject list: search, one row per walker (subject, source, stride), the selected
// walker's facts, and opening other data (a manifest, a folder or files).

#include <array>

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct SubjectsPanel {
  std::array<char, 128> filter{};
  std::array<char, 1024> openPath{};
  bool scrollToSelection = true;
  int scrolledFrames = 0;  // the scroll is repeated next frame: rows just added count then
  float belowList = 0.0f;  // the height under the list, measured each frame (0: not yet)
  float lastHeight = 0.0f;  // the panel's height: when it changes, the selection is brought back

  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
