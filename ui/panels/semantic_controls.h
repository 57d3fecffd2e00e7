#pragma once
// The coefficients panel's semantic axes (ui/app/semantic.h). Explore mode: a slider per
// attribute ("slower ↔ faster", showing the value it implies, "1.42 m/s") that moves the
// explorer's walker along the attribute's axis, and a small plot of gait space (e1 × e2) with the
// population, the explorer's walker and each strong axis as an arrow. Reconstruct mode: the
// attributes predicted from the 2D view alone beside those from the 3D walker and the truth.

#include <map>
#include <string>

#include "ui/app/semantic.h"

namespace ew::ui {

struct AppState;

struct SemanticControls {
  // The drag in progress: the walker it started from and the slider's value then.
  std::string dragging;
  ExploreState anchor;
  double anchorValue = 0.0;
  // The value a slider last set, shown while the walker is still the one it set (the predictor
  // reads a move along the axis as gain × the move, so its reading would not sit under the mouse).
  struct Shown {
    ExploreState state;
    double value = 0.0;
  };
  std::map<std::string, Shown> shown;

  void drawExplore(AppState& s, float scale);
  void drawFromView(const AppState& s, float scale);
};

}  // namespace ew::ui
