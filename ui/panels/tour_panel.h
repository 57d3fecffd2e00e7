#pragma once
// The guided tour's window (ui/app/tour.h): the step's title and text, Back / Next / End.
// Its steps apply their actions through the script action system (actions::tourNext …).

#include "ui/app/tour.h"
#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct TourPanel {
  bool active = false;
  int step = 0;  // 0-based
  float lastHeight = 0.0f;  // of the window last frame (the analysis window stays above it)
  float bottom = 0.0f;      // the card sits above this y (the app sets it; 0: the window's bottom)
  float left = 0.0f;        // and right of this x (the drawer's edge, which the steps point into)
  // A step that opens the analysis window on a short screen folds its text away so that the
  // window has room above the card (1024×768 at UI scale 2); the reader can unfold it.
  int unfoldedStep = -1;    // the step whose folded text the reader unfolded
  bool folded = false;      // the text was folded last frame

  void draw(AppState& s, const FrameContext& ctx);

 private:
  // The text would leave the window this step opened too little room: it folds unless unfolded.
  bool textCrowdsTheWindow(const AppState& s, const TourStep& st, float wrapWidth, float scale) const;
};

}  // namespace ew::ui
