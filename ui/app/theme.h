#pragma once
// The look: a dark theme tuned for projectors, DejaVu Sans when installed (else ImGui's
// built-in font), every size scaled by the monitor's content scale × the user's UI scale.

#include <filesystem>
#include <imgui.h>

#include <string>

#include "ui/app/app_state.h"

namespace ew::ui {

// Rebuilds the font atlas and the style for `scale` (which already includes the projector
// factor) and the theme's colours. Call between frames; the renderer backend's font
// texture must be recreated afterwards (the app does).
// `presentation` gets the same fonts kPresentationTextScale times larger (the views' captions
// and the bar in presentation mode).
void applyTheme(Fonts& fonts, Fonts& presentation, float scale, Theme theme = Theme::Dark);

// The installed font file `file` (e.g. "DejaVuSans.ttf"; fonts-dejavu-core), empty when absent.
std::filesystem::path findFont(const char* file);

// "dark", "light", "projector"; throws std::invalid_argument for anything else.
Theme themeFromName(const std::string& name);
const char* themeName(Theme theme);

// Warning text that reads on the current theme's window background (amber on dark,
// dark orange on light).
ImVec4 warningTextColour();
// Text for a good outcome (a view angle found): teal on dark, dark teal on light.
ImVec4 goodTextColour();

}  // namespace ew::ui
