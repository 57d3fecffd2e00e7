#pragma once
// The look: a dark theme tuned for projectors, DejaVu Sans when installed (else ImGui's
// built-in font), every size scaled by the monitor's content scale × the user's UI scale.

#include "ui/app/app_state.h"

namespace ew::ui {

// Rebuilds the font atlas and the style for `scale`. Call between frames; the renderer
// backend's font texture must be recreated afterwards (the app does).
void applyTheme(Fonts& fonts, float scale);

}  // namespace ew::ui
