#pragma once
// Play/pause (space), speed 0.1–2×, gait-phase scrubbing, frame steps.

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

// What plays has frames (a video's own, before a track or over its tracked range; a keypoint
// clip's), not only a walker's cycle.
bool playsFrames(const AppState& s);
// The slider of those frames, at the width set before it (playsFrames).
void drawFrameSlider(AppState& s, bool narrow);

struct PlaybackPanel {
  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
};

}  // namespace ew::ui
