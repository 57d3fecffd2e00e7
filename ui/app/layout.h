#pragma once
// Where each panel goes: a fixed layout computed from the window size and the UI scale.
//   header (full width)
//   notice row (full width; only while an error or warning is shown)
//   subjects | metrics strip            | coefficients
//   controls | 2D input | 3D view       |
//            | playback                 |
//            | joint errors | J(α) | log |

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct Layout {
  PanelRect header, notice, subjects, controls, metrics, input, reconstruction, playback,
      coefficients, jointErrors, profile, log;
};

// `noticeRow`: a row under the header for the error / warning notice, so that it covers
// nothing at any window size (the views move down by its height).
Layout computeLayout(float width, float height, float scale, bool noticeRow = false);
// The notice row's height at `scale`.
float noticeRowHeight(float scale);

}  // namespace ew::ui
