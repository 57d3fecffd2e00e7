#pragma once
// What the two views say about themselves: each one's title, subtitle and legend for the
// state shown. The panels draw them over the views; the video export burns the same words
// into its frames (ui/app/export_captions.h), so a clip shown on a projector and its exported
// video read alike.

#include <string>
#include <vector>

#include "ui/panels/view_overlay.h"

namespace ew::ui {

struct AppState;

struct ViewCaption {
  std::string title, subtitle;
  std::vector<LegendItem> legend;
};

// The 2D view of a walker (reconstruct and explore modes).
ViewCaption walkerInputCaption(const AppState& s);
// The 2D view of a keypoint clip at its frame `shown` (0-based): the largest residual of that
// frame is named in the legend.
ViewCaption clipInputCaption(const AppState& s, int shown, bool onScreen = false);
// The 2D view of an open video at its frame `frame` (0-based video frame); `decoding`: the
// frame shown is still the one before; `onScreen`: the legend may say what a drag does.
ViewCaption videoInputCaption(const AppState& s, int frame, bool decoding, bool onScreen);
// The two views of the classroom stage (ui/app/stage.h), when stageDrawsViews: what the
// display is, and a quiz's question without its answer.
ViewCaption stageInputCaption(const AppState& s);
ViewCaption stageReconstructionCaption(const AppState& s);
// "Which way is it walking? Trial 7 · answer ← or →" (a quiz running).
std::string quizMessage(const AppState& s);
// The 3D view (reconstruct and explore modes; compare mode lists each engine's error).
ViewCaption walkerReconstructionCaption(const AppState& s);
// The 3D view of a keypoint clip: the walker and the estimated camera.
ViewCaption clipReconstructionCaption(const AppState& s);

// Whichever of the above the mode shows (`clipFrame`: a clip's frame shown; with a tracked
// video, the video frame is the track's first plus it).
ViewCaption inputCaption(const AppState& s, int clipFrame);
ViewCaption reconstructionCaption(const AppState& s);

}  // namespace ew::ui
