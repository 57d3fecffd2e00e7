#pragma once
// The top bar: the buttons, the model selector (Model…: the loaded population, the default
// model of real walkers, or an opened .ewm), and one line saying which model the selected
// walker is reconstructed with and whether it was in it ("model: 24 real walkers (default)
// · walker not in the model", "in the model: leave-one-out model without SM2014001"),
// shortened to fit beside the progress bar. Errors have their own row under it
// (notice_panel.h).

#include <string>
#include <vector>

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

struct HeaderPanel {
  bool modelMenuOpen = false;  // the model selector window
  bool openMore = false;       // open the More… menu on the next frame (scripts)
  bool moreShown = false;      // the last frame had buttons under More…

  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);
  // The model selector (a floating window under the Model button).
  void drawModelMenu(AppState& s, const FrameContext& ctx);

 private:
  float modelButtonX = 0.0f, modelButtonBottom = 0.0f;  // where the selector opens
};

// The header's line about the model, longest first: "model: … · walker not in the model ·
// N = 9 auto (95.4 % of variance) · data: walkers.csv (30 walkers)", then shorter forms
// for narrow windows (the header shows the longest that fits).
std::vector<std::string> modelLines(const AppState& s);

}  // namespace ew::ui
