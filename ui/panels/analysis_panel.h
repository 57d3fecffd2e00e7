#pragma once
// Analysis window: the reconstruction error against the view angle (−90…90°) for the
// selected subject and the mean over every held-out subject, LSQ and MAP, metric E_a /
// E_r / MPJPE, with a marker at the current α; on request the snippet and skeleton engines'
// curves (MPJPE, E_a) in their compare-mode colours; the MAP error against σ² (log axis) with
// LSQ as reference; the eigenvalue spectrum with the chosen N. Computed in the background
// (ui/app/analysis.h), cached by its inputs; the curves export as CSV.

#include <array>
#include <string>

#include "ui/app/analysis.h"
#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct AnalysisPanel {
  bool open = false;
  ErrorMetric metric = ErrorMetric::MpjpeMm;
  bool showLsq = true, showMap = true;
  // The snippet and skeleton engines' curves beside the eigenwalker's (computed on request:
  // a prior per fold; on by itself in compare mode).
  bool showEngines = false;
  std::array<char, 512> csvPath{"analysis.csv"};
  std::string status;

  void draw(AppState& s, const FrameContext& ctx);

 private:
  // The metric, the curves shown and the CSV export: a row that wraps where the window ends.
  void drawControls(AppState& s, float scale);
};

}  // namespace ew::ui
