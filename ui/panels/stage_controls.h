#pragma once
// The classroom displays' controls (ui/app/stage_actions.h): the Controls panel's "Classroom"
// section and the presentation bar's Displays menu draw the same widgets, each calling the
// action its key and script action call.

namespace ew::ui {

struct AppState;

// The displays, the mask's and the lifetime's numbers, the turning stage, "all off" and the
// quiz. Fits any width the panels have (the toggles wrap).
void drawStageControls(AppState& s);

}  // namespace ew::ui
