#pragma once
// Where each panel goes: a fixed layout computed from the window size and the UI scale.
//   header (full width)
//   subjects | metrics strip            | coefficients
//   controls | 2D input | 3D view       |
//            | playback                 |
//            | joint errors | J(α) | log |

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct Layout {
  PanelRect header, subjects, controls, metrics, input, reconstruction, playback, coefficients,
      jointErrors, profile, log;
};

Layout computeLayout(float width, float height, float scale);

}  // namespace ew::ui
