#include "ui/panels/view_overlay.h"

#include <algorithm>
#include <cstdio>

#include "ui/convert.h"
#include "ui/render/palette.h"

namespace ew::ui {

namespace {

// `text` with its spaces turned into line breaks where a line would pass `width`: ImGui's own
// wrapping also breaks after a full stop, which cut "α = 30.0°" in two.
std::string wrapAtSpaces(const ImFont* font, float size, const std::string& text, float width) {
  std::string out, line;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t space = std::min(text.find(' ', start), text.size());
    const std::string word = text.substr(start, space - start);
    const std::string longer = line.empty() ? word : line + " " + word;
    if (!line.empty() && font->CalcTextSizeA(size, 1e9f, 0.0f, longer.c_str()).x > width) {
      out += line + "\n";
      line = word;
    } else {
      line = longer;
    }
    start = space + 1;
  }
  return out + line;
}

// The folded legend: a small tab at the legend's corner.
ImRect legendTab(ImVec2 bottomLeft, float scale) {
  const float size = ImGui::GetFontSize() * 0.85f;
  const ImVec2 text = ImGui::GetFont()->CalcTextSizeA(size, 1e9f, 0.0f, "legend");
  const float pad = 5.0f * scale;
  return {ImVec2(bottomLeft.x, bottomLeft.y - text.y - 2 * pad), ImVec2(bottomLeft.x + text.x + 2 * pad, bottomLeft.y)};
}

void drawLegendTab(ImDrawList* dl, const ImRect& tab, float scale) {
  dl->AddRectFilled(tab.Min, tab.Max, IM_COL32(10, 12, 16, 170), 5.0f * scale);
  dl->AddText(ImGui::GetFont(), ImGui::GetFontSize() * 0.85f, ImVec2(tab.Min.x + 5.0f * scale, tab.Min.y + 5.0f * scale),
              IM_COL32(200, 206, 215, 255), "legend");
}

}  // namespace

CaptionTitle captionTitle(const std::string& title, ImFont* titleFont, float scale, float viewWidth, bool small) {
  CaptionTitle c;
  c.font = small || !titleFont ? ImGui::GetFont() : titleFont;
  // (× FontGlobalScale: presentation mode draws narrow views' text smaller with it.)
  c.size = small ? ImGui::GetFontSize() * 1.1f : c.font->FontSize * ImGui::GetIO().FontGlobalScale;
  const float wrap = std::max(40.0f * scale, viewWidth - 16.0f * scale);
  c.lines = wrapAtSpaces(c.font, c.size, title, wrap);
  c.extent = c.font->CalcTextSizeA(c.size, 1e9f, 0.0f, c.lines.c_str());
  return c;
}

ImVec2 smallCaptionPlate(const std::string& title, float scale, float viewWidth) {
  const ImVec2 t = captionTitle(title, nullptr, scale, viewWidth, true).extent;
  return {t.x + 16.0f * scale, t.y + 18.0f * scale};
}

ImVec2 legendTabSize(float scale) {
  const ImRect tab = legendTab(ImVec2(0.0f, 0.0f), scale);
  return {tab.GetWidth(), tab.GetHeight()};
}

bool overlaps(const ImRect& a, const ImRect& b) {
  return a.Min.x < b.Max.x && b.Min.x < a.Max.x && a.Min.y < b.Max.y && b.Min.y < a.Max.y;
}

ImRect unite(const ImRect& a, const ImRect& b) {
  if (a.Min.x >= a.Max.x || a.Min.y >= a.Max.y) return b;
  if (b.Min.x >= b.Max.x || b.Min.y >= b.Max.y) return a;
  ImRect u = a;
  u.Add(b);
  return u;
}

ImRect drawCaption(ImDrawList* dl, ImVec2 at, const std::string& title, const std::string& subtitle,
                 ImFont* titleFont, float scale, ImVec2 viewSize, const ImRect& keepClear,
                 float narrowBelowPx) {
  const float maxWidth = viewSize.x;
  // A narrow view (a small window, a large UI scale) gets the caption in smaller type, and so
  // does one where the large title would cover the walker.
  const bool narrow = maxWidth < narrowBelowPx * scale;
  ImFont* body = ImGui::GetFont();
  const float bodySize = ImGui::GetFontSize() * (narrow ? 0.8f : 1.0f);
  const float pad = 8.0f * scale;
  const float wrap = std::max(40.0f * scale, maxWidth - 2 * pad);  // whole words onto the next line
  CaptionTitle tt = captionTitle(title, titleFont, scale, maxWidth, narrow || !titleFont);
  const auto plateOf = [&](ImVec2 sub) {
    return ImRect(at, ImVec2(at.x + std::max(tt.extent.x, sub.x) + 2 * pad,
                             at.y + tt.extent.y + sub.y + 2 * pad + 2.0f * scale));
  };
  if (overlaps(plateOf(ImVec2(0.0f, 0.0f)), keepClear) && !narrow && titleFont)
    tt = captionTitle(title, titleFont, scale, maxWidth, true);
  const ImVec2 t = tt.extent;
  ImFont* font = tt.font;
  const float titleSize = tt.size;
  const std::string& titleLines = tt.lines;
  const std::string subtitleLines = wrapAtSpaces(body, bodySize, subtitle, wrap);
  ImVec2 s = body->CalcTextSizeA(bodySize, 1e9f, 0.0f, subtitleLines.c_str());
  const bool withSubtitle = t.y + s.y + 2 * pad <= 0.3f * viewSize.y && !overlaps(plateOf(s), keepClear);
  if (!withSubtitle) s = ImVec2(0.0f, 0.0f);
  const ImVec2 plate{std::max(t.x, s.x) + 2 * pad, t.y + s.y + 2 * pad + 2.0f * scale};
  const ImRect rect(at, ImVec2(at.x + plate.x, at.y + plate.y));
  if (!dl) return rect;
  dl->AddRectFilled(at, ImVec2(at.x + plate.x, at.y + plate.y), IM_COL32(10, 12, 16, 150), 6.0f * scale);
  dl->AddText(font, titleSize, ImVec2(at.x + pad, at.y + pad), IM_COL32(235, 238, 245, 255), titleLines.c_str());
  if (withSubtitle)
    dl->AddText(body, bodySize, ImVec2(at.x + pad, at.y + pad + t.y + 2.0f * scale), IM_COL32(150, 160, 175, 255),
                subtitleLines.c_str());
  if (!withSubtitle && !subtitle.empty() && ImGui::IsMouseHoveringRect(rect.Min, rect.Max, false))
    ImGui::SetTooltip("%s", subtitle.c_str());
  return rect;
}

namespace {

// The legend's type and plate in a view `viewWidth` wide (see drawLegend).
struct LegendLayout {
  float scale, width, fontSize, row, pad;
  ImVec2 size;
};

LegendLayout layOutLegend(std::span<const LegendItem> items, float scale, float viewWidth) {
  float width = 0.0f;
  for (const auto& it : items) width = std::max(width, ImGui::CalcTextSize(it.label.c_str()).x);
  const float natural = width + 42.0f * scale;
  const float soft = 0.55f * viewWidth;
  const float shrink = natural > soft ? std::max(0.6f, soft / natural) : 1.0f;
  // The plate stays inside the view with the callers' 10 px (× scale) margin on either side.
  const float hardText = viewWidth - 20.0f * scale - 42.0f * scale * shrink;
  LegendLayout l;
  l.scale = scale * shrink;
  l.width = std::min(width * shrink, std::max(hardText, 20.0f * l.scale));
  l.fontSize = ImGui::GetFontSize() * shrink;
  l.row = l.fontSize + 4.0f * l.scale;
  l.pad = 8.0f * l.scale;
  l.size = ImVec2(l.width + 2 * l.pad + 26.0f * l.scale, l.row * static_cast<float>(items.size()) + 2 * l.pad);
  return l;
}

}  // namespace

ImVec2 legendSize(std::span<const LegendItem> items, float scale, float viewWidth) {
  if (items.empty()) return {0.0f, 0.0f};
  return layOutLegend(items, scale, viewWidth).size;
}

ImRect drawLegend(ImDrawList* dl, ImVec2 bottomLeft, std::span<const LegendItem> items, float scale,
                  float viewWidth, const ImRect& keepClear) {
  if (items.empty()) return ImRect(bottomLeft, bottomLeft);  // nothing to explain: no plate
  const LegendLayout l = layOutLegend(items, scale, viewWidth);
  const float shrink = l.scale / scale;
  scale = l.scale;
  const float width = l.width, fontSize = l.fontSize;
  // A label longer than the room left: its end becomes "…".
  const auto fitted = [&](const std::string& label) {
    if (ImGui::GetFont()->CalcTextSizeA(fontSize, 1e9f, 0.0f, label.c_str()).x <= width) return label;
    std::string cut = label;
    const auto popCharacter = [&cut] {  // a whole UTF-8 character: its continuation bytes, then its lead
      while (!cut.empty() && (static_cast<unsigned char>(cut.back()) & 0xC0) == 0x80) cut.pop_back();
      if (!cut.empty()) cut.pop_back();
    };
    while (!cut.empty() && ImGui::GetFont()->CalcTextSizeA(fontSize, 1e9f, 0.0f, (cut + "…").c_str()).x > width)
      popCharacter();
    return cut + "…";
  };
  const float row = l.row, pad = l.pad;
  const ImVec2 tl{bottomLeft.x, bottomLeft.y - l.size.y};
  const ImVec2 br{tl.x + l.size.x, bottomLeft.y};
  if (overlaps(ImRect(tl, br), keepClear)) {
    const ImRect tab = legendTab(bottomLeft, scale / shrink);
    if (!ImGui::IsMouseHoveringRect(tab.Min, tab.Max, false)) {
      drawLegendTab(dl, tab, scale / shrink);
      return tab;
    }
  }
  dl->AddRectFilled(tl, br, IM_COL32(10, 12, 16, 150), 6.0f * scale);
  float y = tl.y + pad;
  for (const auto& it : items) {
    const ImU32 c = toImU32(glm::vec4(glm::vec3(it.colour), std::max(it.colour.a, 0.85f)));
    const ImVec2 mid{tl.x + pad + 8.0f * scale, y + row * 0.5f - 1.0f};
    if (it.line) {
      dl->AddLine(ImVec2(mid.x - 8.0f * scale, mid.y), ImVec2(mid.x + 8.0f * scale, mid.y), c, 2.5f * scale);
    } else {
      dl->AddCircleFilled(mid, 6.0f * scale, c);
    }
    dl->AddText(ImGui::GetFont(), fontSize, ImVec2(tl.x + pad + 24.0f * scale, y + 1.0f), IM_COL32(215, 220, 230, 255),
                fitted(it.label).c_str());
    y += row;
  }
  return {tl, br};
}

void drawErrorColourBar(ImDrawList* dl, ImVec2 topRight, float heightPx, float maxMm,
                        const char* title, float scale) {
  const float w = 14.0f * scale;
  const float pad = 8.0f * scale;
  const float labelW = ImGui::CalcTextSize("000 mm").x;
  const ImVec2 titleSize = ImGui::CalcTextSize(title);
  const float plateW = std::max(w + labelW + 3 * pad, titleSize.x + 2 * pad);
  const ImVec2 plateTl{topRight.x - plateW, topRight.y};
  dl->AddRectFilled(plateTl, ImVec2(topRight.x, topRight.y + heightPx + titleSize.y + 3 * pad),
                    IM_COL32(10, 12, 16, 150), 6.0f * scale);
  dl->AddText(ImVec2(plateTl.x + pad, plateTl.y + pad), IM_COL32(200, 206, 215, 255), title);
  const float x0 = plateTl.x + pad;
  const float y0 = plateTl.y + titleSize.y + 2 * pad;
  constexpr int kSteps = 24;
  for (int i = 0; i < kSteps; ++i) {
    // Top = max error.
    const float t0 = 1.0f - static_cast<float>(i) / kSteps;
    const float t1 = 1.0f - static_cast<float>(i + 1) / kSteps;
    const float ya = y0 + heightPx * static_cast<float>(i) / kSteps;
    const float yb = y0 + heightPx * static_cast<float>(i + 1) / kSteps;
    const ImU32 ca = toImU32(palette::errorColour(t0));
    const ImU32 cb = toImU32(palette::errorColour(t1));
    dl->AddRectFilledMultiColor(ImVec2(x0, ya), ImVec2(x0 + w, yb), ca, ca, cb, cb);
  }
  for (int i = 0; i <= 4; ++i) {
    const float t = static_cast<float>(i) / 4.0f;
    const float y = y0 + heightPx * (1.0f - t);
    dl->AddLine(ImVec2(x0 + w, y), ImVec2(x0 + w + 4.0f * scale, y), IM_COL32(200, 206, 215, 255));
    char buf[32];
    std::snprintf(buf, sizeof buf, i == 4 ? "%.0f mm" : "%.0f", static_cast<double>(t * maxMm));
    dl->AddText(ImVec2(x0 + w + 7.0f * scale, y - ImGui::GetTextLineHeight() * 0.5f),
                IM_COL32(200, 206, 215, 255), buf);
  }
}

void drawScaleBar(ImDrawList* dl, ImVec2 left, float lengthPx, const char* label, float scale) {
  const float len = lengthPx;
  const ImU32 c = IM_COL32(170, 178, 190, 220);
  dl->AddLine(left, ImVec2(left.x + len, left.y), c, 2.0f * scale);
  dl->AddLine(ImVec2(left.x, left.y - 5 * scale), ImVec2(left.x, left.y + 5 * scale), c, 2.0f * scale);
  dl->AddLine(ImVec2(left.x + len, left.y - 5 * scale), ImVec2(left.x + len, left.y + 5 * scale), c,
              2.0f * scale);
  const ImVec2 ts = ImGui::CalcTextSize(label);
  dl->AddText(ImVec2(left.x + 0.5f * (len - ts.x), left.y - ts.y - 6.0f * scale), c, label);
}

}  // namespace ew::ui
