#pragma once
// Export window (opened from the header's "Export" button): PNG of the window or one
// view, a video of both views, the displayed walker as CSV / BVH, the current model.
// Every button calls the same action a script does (ui/app/actions.h).

#include <array>
#include <string>

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct ExportPanel {
  bool open = false;
  std::array<char, 512> folder{"."};
  std::array<char, 128> baseName{"eigenwalker"};
  int videoCycles = 2;
  int videoFps = 30;
  int videoWidth = 1280, videoHeight = 720;
  int videoFormat = 0;     // 0 = .avi (MJPG), 1 = .mp4 (mp4v)
  bool videoCaptions = true;  // titles, metrics and legends burnt into the frames
  int motionCycles = 0;    // CSV / BVH: 0 = the walker's trial duration
  std::string status;      // the last export's outcome, shown in the window

  void draw(AppState& s, const FrameContext& ctx);
};

}  // namespace ew::ui
