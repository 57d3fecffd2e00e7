#include "ui/app/layout.h"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace ew::ui {

namespace {

struct Rows {
  float header, notice, metrics, playback, bottom;
};

Rows rowsAt(float height, float scale, bool noticeRow) {
  return {46.0f * scale, noticeRow ? noticeRowHeight(scale) : 0.0f, 66.0f * scale, 44.0f * scale,
          std::clamp(height * 0.24f, 170.0f * scale, 300.0f * scale)};
}

// The centre: metrics strip, the two views side by side, playback under them; `bottom` is
// what is left under the playback row.
void placeCentre(Layout& l, float x, float width, float top, float height, const Rows& r) {
  l.metrics = {{x, top}, {width, r.metrics}};
  const float viewsY = top + r.metrics;
  const float viewsH = std::max(60.0f, height - r.metrics - r.playback);
  const float halfW = width * 0.5f;
  l.input = {{x, viewsY}, {halfW, viewsH}};
  l.reconstruction = {{x + halfW, viewsY}, {width - halfW, viewsH}};
  l.playback = {{x, viewsY + viewsH}, {width, r.playback}};
}

// The side columns' narrowest (the subjects table's three columns, the coefficients' sliders).
constexpr float kMinSideW = 230.0f, kMinRightW = 220.0f;

Layout fullLayout(float width, float height, float scale, const Rows& r) {
  Layout l;
  float sideW = std::clamp(width * 0.19f, 250.0f * scale, 360.0f * scale);
  float rightW = std::clamp(width * 0.18f, 240.0f * scale, 340.0f * scale);
  // The two views keep two thirds of the width: the columns give up what they must, down to
  // their narrowest (below that `fits` sends the panels to the drawer).
  const float excess = sideW + rightW - width / 3.0f;
  if (excess > 0.0f) {
    const float sideShare = sideW / (sideW + rightW);
    sideW = std::max(kMinSideW * scale, sideW - excess * sideShare);
    rightW = std::max(kMinRightW * scale, rightW - excess * (1.0f - sideShare));
  }
  const float centreW = std::max(100.0f, width - sideW - rightW);
  const float bodyY = r.header + r.notice;
  const float bodyH = height - bodyY;
  const float subjectsH = bodyH * 0.46f;
  l.subjects = {{0, bodyY}, {sideW, subjectsH}};
  l.controls = {{0, bodyY + subjectsH}, {sideW, bodyH - subjectsH}};
  l.coefficients = {{width - rightW, bodyY}, {rightW, bodyH - r.bottom}};
  l.log = {{width - rightW, height - r.bottom}, {rightW, r.bottom}};
  placeCentre(l, sideW, centreW, bodyY, bodyH - r.bottom, r);
  const float bottomY = height - r.bottom;
  const float errorsW = centreW * 0.42f;
  l.jointErrors = {{sideW, bottomY}, {errorsW, r.bottom}};
  l.profile = {{sideW + errorsW, bottomY}, {centreW - errorsW, r.bottom}};
  return l;
}

// Each view at least a third of the width (half a pixel of rounding allowed) and 0.35 of the height.
bool fits(const Layout& l, float width, float height) {
  return l.input.size.x + l.reconstruction.size.x >= 2.0f * width / 3.0f - 0.5f && l.input.size.y >= 0.35f * height;
}

Layout drawerLayout(float width, float height, float scale, const Rows& r) {
  Layout l;
  l.drawer = true;
  // A third of the width: the views keep two thirds, a third each, whatever the scale.
  const float drawerW = width / 3.0f;
  // The notice row heads the drawer's column, not the whole width: the views keep its height.
  l.notice = {{0, r.header}, {drawerW, r.notice}};
  const float bodyY = r.header + r.notice;
  const float bodyH = height - bodyY;
  // Tab rows that would take more than 0.45 of the height give way to one row with a list of
  // the panels (the drawer panel draws a combo box when its rows do not fit).
  float tabsH = drawerTabsHeight(drawerW, scale);
  if (tabsH > bodyH * 0.45f) tabsH = std::min(drawerComboHeight(scale), bodyH * 0.45f);
  l.drawerTabs = {{0, bodyY}, {drawerW, tabsH}};
  const PanelRect body{{0, bodyY + tabsH}, {drawerW, bodyH - tabsH}};
  l.subjects = l.controls = l.coefficients = l.jointErrors = l.profile = l.log = body;
  placeCentre(l, drawerW, width - drawerW, r.header, height - r.header, r);
  return l;
}

// A rectangle with each edge rounded to the nearest whole pixel: neighbours that share an edge
// still do, and no pixel belongs to two of them.
PanelRect onWholePixels(const PanelRect& r) {
  const float x0 = std::round(r.pos.x), y0 = std::round(r.pos.y);
  return {{x0, y0}, {std::round(r.pos.x + r.size.x) - x0, std::round(r.pos.y + r.size.y) - y0}};
}

// Panels meet on whole pixels. Dear ImGui puts a window at whole pixels (it floors its position
// and size) while the backdrop rounds the window's fill to the nearest, so on a fractional edge
// both neighbours painted the pixels between them. Repainting what changed spreads to every
// item touching what it repaints (ui/render/damage.h): from the views, through those shared
// pixels, panel by panel over the whole window — every frame of playback (issue 54).
Layout onWholePixels(Layout l) {
  for (PanelRect* r : {&l.header, &l.notice, &l.subjects, &l.controls, &l.metrics, &l.input,
                       &l.reconstruction, &l.playback, &l.coefficients, &l.jointErrors, &l.profile,
                       &l.log, &l.drawerTabs, &l.presentationBar})
    *r = onWholePixels(*r);
  return l;
}

}  // namespace

float noticeRowHeight(float scale) { return 34.0f * scale; }

float presentationBarHeight(float scale) { return 60.0f * scale; }

Layout computePresentationLayout(float width, float height, float scale, bool noticeRow) {
  Layout l;
  l.presentation = true;
  const float noticeH = noticeRow ? noticeRowHeight(scale) : 0.0f;
  // The bar never takes more than an eighth of a short window (a large scale on 1280×720).
  const float barH = std::min(presentationBarHeight(scale), 0.12f * height);
  const float viewsH = std::max(60.0f, height - noticeH - barH);
  const float halfW = width * 0.5f;
  l.notice = {{0, 0}, {width, noticeH}};
  l.input = {{0, noticeH}, {halfW, viewsH}};
  l.reconstruction = {{halfW, noticeH}, {width - halfW, viewsH}};
  l.presentationBar = {{0, noticeH + viewsH}, {width, height - noticeH - viewsH}};
  return onWholePixels(l);
}

float drawerComboHeight(float scale) { return 44.0f * scale; }

float drawerTabsHeight(float drawerWidth, float scale) {
  // The tabs wrap as the drawer panel places them: each button is its label (about 7.6 px of
  // the scale's per character in the body font) plus 16 px of padding, 8 px apart, in the
  // drawer's width less 16 px of window padding. Rows of 30 px, plus 14 px around them.
  const float available = drawerWidth / scale - 16.0f;
  int rows = 1;
  float x = 0.0f;
  for (DrawerTab tab : kDrawerTabs) {
    const float w = 7.6f * static_cast<float>(std::string_view(drawerTabName(tab)).size()) + 16.0f;
    if (x > 0.0f && x + 8.0f + w > available) {
      ++rows;
      x = 0.0f;
    }
    x += (x > 0.0f ? 8.0f : 0.0f) + w;
  }
  return (30.0f * static_cast<float>(rows) + 14.0f) * scale;
}

const char* drawerTabName(DrawerTab tab) {
  switch (tab) {
    case DrawerTab::Subjects: return "Subjects";
    case DrawerTab::Controls: return "Controls";
    case DrawerTab::Coefficients: return "Coefficients";
    case DrawerTab::JointErrors: return "Errors";
    case DrawerTab::Profile: return "View";
    case DrawerTab::Log: return "Log";
  }
  return "";
}

Layout computeLayout(float width, float height, float scale, bool noticeRow) {
  const Rows rows = rowsAt(height, scale, noticeRow);
  Layout l = fullLayout(width, height, scale, rows);
  l.header = {{0, 0}, {width, rows.header}};
  l.notice = {{0, rows.header}, {width, rows.notice}};
  if (fits(l, width, height)) return onWholePixels(l);
  Layout d = drawerLayout(width, height, scale, rows);
  d.header = l.header;
  return onWholePixels(d);
}

}  // namespace ew::ui
