#pragma once
// The banner over the top of the views after an open went wrong (Jobs::notice): what could
// not be opened, why (the file, where in it, the problem), and what the viewer still shows,
// with Retry and Dismiss. In amber when an open succeeded but skipped some of the items.
// The same message is in the log.

#include <cstdint>

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct NoticePanel {
  std::uint64_t frontSerial = 0;  // the notice last brought to the front

  // `area`: the rectangle the banner spans the top of (the metrics strip and the views).
  void draw(AppState& s, const FrameContext& ctx, const PanelRect& area);
};

}  // namespace ew::ui
