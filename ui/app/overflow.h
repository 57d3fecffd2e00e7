#pragma once
// Which of this frame's windows are narrower than what was put in them: text and widgets past
// a window's right edge are cut there (issue 18's "no text cut mid-word"). The layout tests
// read it from export_state.

#include <string>
#include <utility>
#include <vector>

namespace ew::ui {

// Every window drawn this frame (not tooltips, popups or menus, nor windows that scroll
// sideways) whose content reaches further right than its clip edge, or, without a scroll bar,
// further down ("NAME (bottom)"), or that reaches past the screen's right or bottom edge ("NAME
// (off the screen)"), with by how many pixels.
// Call after the last ImGui::End of the frame, before ImGui::Render.
std::vector<std::pair<std::string, float>> windowsCutOnTheRight();

}  // namespace ew::ui
