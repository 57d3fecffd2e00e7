#pragma once
// Annotations the two views draw over their images with ImGui's draw list: a caption,
// a legend, a colour bar, a scale bar. Helpers shared by both view panels.

#include <imgui.h>
#include <imgui_internal.h>

#include <span>
#include <string>
#include <utility>

#include <glm/glm.hpp>

namespace ew::ui {

struct LegendItem {
  glm::vec4 colour;
  std::string label;
  bool line = false;  // a line swatch instead of a disc
};

// Caption at the top-left corner, on a translucent plate.
// In a view `viewSize` big its lines wrap between words, and the subtitle is left out when
// the caption would take more than 0.3 of the view's height (it would meet the legend). The
// plate's rectangle is returned (the colour bar keeps clear of it).
ImRect drawCaption(ImDrawList* dl, ImVec2 at, const std::string& title, const std::string& subtitle,
                 ImFont* titleFont, float scale, ImVec2 viewSize = {1e9f, 1e9f});
// Legend rows, bottom-left corner upwards; the plate's rectangle is returned (so other
// overlays can keep clear of it). In a view `viewWidth` wide, a legend wider than 0.55 of it
// is drawn in smaller text (down to 0.6 of the body size) so it covers less of the walker,
// and a label that would still leave the view ends in "…".
ImRect drawLegend(ImDrawList* dl, ImVec2 bottomLeft, std::span<const LegendItem> items, float scale,
                  float viewWidth = 1e9f);
// Vertical colour bar of the error map, 0 … maxMm, at the right edge.
void drawErrorColourBar(ImDrawList* dl, ImVec2 topRight, float heightPx, float maxMm,
                        const char* title, float scale);
// Horizontal scale bar `lengthPx` screen pixels long from `left`, `label` ("50 cm",
// "200 px") centred above it.
void drawScaleBar(ImDrawList* dl, ImVec2 left, float lengthPx, const char* label, float scale);

}  // namespace ew::ui
