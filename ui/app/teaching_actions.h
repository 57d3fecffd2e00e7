#pragma once
// Teaching (teaching_actions.cpp): theme, presentation mode, the guided tour, floating panels.
// Part of the viewer's actions (ui/app/actions.h): each validates its argument and throws
// std::invalid_argument with a readable message when it cannot apply.

#include <string>

#include "ui/app/app_state.h"

namespace ew::ui::actions {

// [SECTION] Teaching
void setTheme(AppState& s, const std::string& name);  // dark, light, projector
// Presentation mode (F5): only the two views, large captions, play / pause and the view angle.
void setPresentation(AppState& s, bool on);
// The guided tour (ui/app/tour.h): each step applies its actions through applyAction,
// exactly as a script would. Next on the last step ends the tour.
void tourStart(AppState& s);
void tourNext(AppState& s);
void tourBack(AppState& s);
void tourEnd(AppState& s);

// Floating panels: "export", "analysis", "help", "data", "notice_details" (the full message of
// the notice row), "model" (the model selector), "quiz"; throws for an unknown name.
void showPanel(AppState& s, const std::string& name, bool shown);

}  // namespace ew::ui::actions
