#pragma once
// The guided tour for teaching: five steps, each a title, a short text and the actions that
// set the viewer up for it (a JSON script, applied through applyAction like any script).

#include <span>

namespace ew::ui {

// Where the tour's window sits, chosen per step to keep what the step talks about visible.
enum class TourAnchor { BottomCentre, BottomLeft, BottomRight };

struct TourStep {
  TourAnchor anchor;
  const char* title;
  const char* text;
  const char* actionsJson;  // a JSON array of one-key actions (docs/VIEWER.md)
};

std::span<const TourStep> tourSteps();

}  // namespace ew::ui
