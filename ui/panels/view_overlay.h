#pragma once
// Annotations the two views draw over their images with ImGui's draw list: a caption,
// a legend, a colour bar, a scale bar. Helpers shared by both view panels.

#include <imgui.h>
#include <imgui_internal.h>

#include <span>
#include <string>
#include <utility>

#include <glm/glm.hpp>

#include "ui/panels/panel_window.h"

namespace ew::ui {

struct LegendItem {
  glm::vec4 colour;
  std::string label;
  bool line = false;  // a line swatch instead of a disc
};

// No rectangle: nothing to keep clear of.
inline const ImRect kNothing{ImVec2(0.0f, 0.0f), ImVec2(0.0f, 0.0f)};
bool overlaps(const ImRect& a, const ImRect& b);
inline PanelRect toPanelRect(const ImRect& r) { return {r.Min, ImVec2(r.GetWidth(), r.GetHeight())}; }
// The smallest rectangle holding both (an empty one, Min = Max, holds nothing).
ImRect unite(const ImRect& a, const ImRect& b);

// A caption's title as drawCaption sets it: in the large font, or in the body's ×1.1 (`small`).
struct CaptionTitle {
  ImFont* font = nullptr;
  float size = 0.0f;
  std::string lines;  // wrapped between words to the view's width
  ImVec2 extent{0.0f, 0.0f};
};
CaptionTitle captionTitle(const std::string& title, ImFont* titleFont, float scale, float viewWidth, bool small);
// The plate of a caption with its small title alone, and of the folded legend's tab: what a
// view frames its walker clear of when they would cover it.
ImVec2 smallCaptionPlate(const std::string& title, float scale, float viewWidth);
ImVec2 legendTabSize(float scale);
// The plate of the legend drawLegend draws unfolded.
ImVec2 legendSize(std::span<const LegendItem> items, float scale, float viewWidth);

// Caption at the top-left corner, on a translucent plate.
// In a view `viewSize` big its lines wrap between words, and the subtitle is left out when
// the caption would take more than 0.3 of the view's height (it would meet the legend) or
// would cover `keepClear` (the walker: the subtitle is then the caption's tooltip). The
// plate's rectangle is returned (the colour bar keeps clear of it); with no draw list, only
// that (the caption measured, not drawn). A view narrower than `narrowBelowPx` (unscaled)
// gets smaller type; a column set aside for the caption passes 0.
inline constexpr float kNarrowViewPx = 330.0f;
ImRect drawCaption(ImDrawList* dl, ImVec2 at, const std::string& title, const std::string& subtitle,
                 ImFont* titleFont, float scale, ImVec2 viewSize = {1e9f, 1e9f}, const ImRect& keepClear = kNothing,
                 float narrowBelowPx = kNarrowViewPx);
// Legend rows, bottom-left corner upwards; the plate's rectangle is returned (so other
// overlays can keep clear of it). In a view `viewWidth` wide, a legend wider than 0.55 of it
// is drawn in smaller text (down to 0.6 of the body size) so it covers less of the walker,
// and a label that would still leave the view ends in "…". A legend that would still cover
// `keepClear` (the walker) folds into a small "legend" tab that shows it while hovered.
ImRect drawLegend(ImDrawList* dl, ImVec2 bottomLeft, std::span<const LegendItem> items, float scale,
                  float viewWidth = 1e9f, const ImRect& keepClear = kNothing);
// Vertical colour bar of the error map, 0 … maxMm, at the right edge.
void drawErrorColourBar(ImDrawList* dl, ImVec2 topRight, float heightPx, float maxMm,
                        const char* title, float scale);
// Horizontal scale bar `lengthPx` screen pixels long from `left`, `label` ("50 cm",
// "200 px") centred above it.
void drawScaleBar(ImDrawList* dl, ImVec2 left, float lengthPx, const char* label, float scale);

}  // namespace ew::ui
