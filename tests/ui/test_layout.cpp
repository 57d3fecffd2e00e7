// The viewer's layout (ui/app/layout.h) over the window sizes and UI scales teaching happens
// at: every panel inside the window, no two panels overlapping, and the two views at least a
// third of the width and 0.35 of the height each — by narrowing the side columns, and by
// switching to the drawer (the side and bottom panels one at a time) when even that would not
// leave them that.

#include "ui/app/layout.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace ew::ui {
namespace {

struct Named {
  std::string name;
  PanelRect rect;
};

// The panels drawn at once: in the drawer only one of the six side and bottom panels is.
std::vector<Named> drawnPanels(const Layout& l, bool notice) {
  std::vector<Named> p{{"header", l.header},   {"metrics", l.metrics},   {"input", l.input},
                       {"reconstruction", l.reconstruction}, {"playback", l.playback}};
  if (notice) p.push_back({"notice", l.notice});
  if (l.drawer) {
    p.push_back({"drawer tabs", l.drawerTabs});
    p.push_back({"drawer", l.controls});
  } else {
    for (const Named& n : std::vector<Named>{{"subjects", l.subjects}, {"controls", l.controls},
                                             {"coefficients", l.coefficients}, {"joint errors", l.jointErrors},
                                             {"profile", l.profile}, {"log", l.log}})
      p.push_back(n);
  }
  return p;
}

bool overlap(const PanelRect& a, const PanelRect& b) {
  // Edges are whole pixels (PanelsMeetOnWholePixels): a shared edge is no overlap, one pixel is.
  return a.pos.x + a.size.x > b.pos.x && b.pos.x + b.size.x > a.pos.x &&
         a.pos.y + a.size.y > b.pos.y && b.pos.y + b.size.y > a.pos.y;
}

TEST(Layout, HoldsAtEveryTeachingSizeAndScale) {
  const std::pair<float, float> sizes[] = {{1024, 768}, {1280, 720}, {1366, 768}, {1600, 900}, {1920, 1080}, {3840, 2160}};
  // UI scales 1, 1.5 and 2, and the projector theme's 1.3 on top of each (kProjectorScale).
  const float scales[] = {1.0f, 1.3f, 1.5f, 1.95f, 2.0f, 2.6f};
  int drawers = 0;
  for (const auto& [w, h] : sizes)
    for (float scale : scales)
      for (bool notice : {false, true}) {
        const std::string cell = std::to_string(static_cast<int>(w)) + "x" + std::to_string(static_cast<int>(h)) +
                                 " at " + std::to_string(scale) + (notice ? " with the notice row" : "");
        const Layout l = computeLayout(w, h, scale, notice);
        drawers += l.drawer ? 1 : 0;
        const auto panels = drawnPanels(l, notice);
        for (const Named& p : panels) {
          EXPECT_GE(p.rect.pos.x, 0.0f) << cell << ": " << p.name;
          EXPECT_GE(p.rect.pos.y, 0.0f) << cell << ": " << p.name;
          EXPECT_GT(p.rect.size.x, 0.0f) << cell << ": " << p.name;
          EXPECT_LE(p.rect.pos.x + p.rect.size.x, w + 0.5f) << cell << ": " << p.name;
          EXPECT_LE(p.rect.pos.y + p.rect.size.y, h + 0.5f) << cell << ": " << p.name;
        }
        for (size_t i = 0; i < panels.size(); ++i)
          for (size_t j = i + 1; j < panels.size(); ++j)
            EXPECT_FALSE(overlap(panels[i].rect, panels[j].rect)) << cell << ": " << panels[i].name << " and "
                                                                  << panels[j].name;
        for (const PanelRect& view : {l.input, l.reconstruction}) {
          // Less a pixel: each edge is rounded to a whole pixel, by up to half a pixel.
          EXPECT_GE(view.size.x, w / 3.0f - 1.0f) << cell;
          EXPECT_GE(view.size.y, 0.35f * h) << cell;
        }
      }
  // The drawer is for tight windows only: 1366×768 and up at scale 1 keep the full layout;
  // 1024×768, whose side columns would leave the views less than a third each, and 1280×720
  // at scale 2 take the drawer.
  EXPECT_GT(drawers, 0);
  for (const auto& [w, h] : {std::pair{1366.0f, 768.0f}, std::pair{1600.0f, 900.0f}, std::pair{1920.0f, 1080.0f}})
    EXPECT_FALSE(computeLayout(w, h, 1.0f).drawer) << w << "x" << h;
  EXPECT_TRUE(computeLayout(1024, 768, 1.0f).drawer);
  EXPECT_TRUE(computeLayout(1280, 720, 2.0f).drawer);
}

// Presentation mode (F5): the two views and the bar under them (and the notice row while it is
// shown) are all there is; the views fill the width between them, each at least a third of it.
TEST(Layout, PresentationKeepsOnlyTheViewsAndTheirBar) {
  const std::pair<float, float> sizes[] = {{1024, 768}, {1280, 720}, {1366, 768}, {1600, 900}, {1920, 1080}, {3840, 2160}};
  const float scales[] = {1.0f, 1.3f, 1.5f, 1.95f, 2.0f, 2.6f};
  for (const auto& [w, h] : sizes)
    for (float scale : scales)
      for (bool notice : {false, true}) {
        const std::string cell = std::to_string(static_cast<int>(w)) + "x" + std::to_string(static_cast<int>(h)) +
                                 " at " + std::to_string(scale) + (notice ? " with the notice row" : "");
        const Layout l = computePresentationLayout(w, h, scale, notice);
        EXPECT_TRUE(l.presentation) << cell;
        EXPECT_FALSE(l.drawer) << cell;
        std::vector<Named> drawn{{"input", l.input}, {"reconstruction", l.reconstruction}, {"bar", l.presentationBar}};
        if (notice) drawn.push_back({"notice", l.notice});
        float area = 0.0f;
        for (const Named& p : drawn) {
          EXPECT_GE(p.rect.pos.x, 0.0f) << cell << ": " << p.name;
          EXPECT_GE(p.rect.pos.y, 0.0f) << cell << ": " << p.name;
          EXPECT_GT(p.rect.size.y, 0.0f) << cell << ": " << p.name;
          EXPECT_LE(p.rect.pos.x + p.rect.size.x, w + 0.5f) << cell << ": " << p.name;
          EXPECT_LE(p.rect.pos.y + p.rect.size.y, h + 0.5f) << cell << ": " << p.name;
          area += p.rect.size.x * p.rect.size.y;
        }
        for (size_t i = 0; i < drawn.size(); ++i)
          for (size_t j = i + 1; j < drawn.size(); ++j)
            EXPECT_FALSE(overlap(drawn[i].rect, drawn[j].rect)) << cell << ": " << drawn[i].name << " and "
                                                                << drawn[j].name;
        // Nothing else has room, and what is drawn covers the window.
        EXPECT_NEAR(area, w * h, 1.0f) << cell;
        for (const PanelRect& hidden : {l.header, l.subjects, l.controls, l.metrics, l.playback, l.coefficients,
                                        l.jointErrors, l.profile, l.log, l.drawerTabs})
          EXPECT_EQ(hidden.size.x * hidden.size.y, 0.0f) << cell;
        for (const PanelRect& view : {l.input, l.reconstruction}) {
          EXPECT_GE(view.size.x, w / 3.0f) << cell;
          EXPECT_GE(view.size.y, 0.6f * h) << cell;  // far more than the workspace's 0.35
        }
        EXPECT_GE(l.presentationBar.size.x, w - 0.5f) << cell;
      }
}

bool onWholePixels(const PanelRect& r) {
  for (float edge : {r.pos.x, r.pos.y, r.pos.x + r.size.x, r.pos.y + r.size.y})
    if (edge != std::round(edge)) return false;
  return true;
}

// Every panel's edges on whole pixels, in every layout. A panel's fill and its Dear ImGui window
// rounded a fractional edge differently, so neighbours both painted the pixels between them
// and the repaint of one reached the other, and on through the window: during playback every
// frame was repainted whole (issue 54).
TEST(Layout, PanelsMeetOnWholePixels) {
  const std::pair<float, float> sizes[] = {{1024, 768},  {1280, 720},  {1366, 768},
                                           {1600, 900}, {1920, 1080}, {3840, 2160}};
  const float scales[] = {1.0f, 1.3f, 1.5f, 1.95f, 2.0f, 2.6f};
  for (const auto& [w, h] : sizes)
    for (float scale : scales)
      for (bool notice : {false, true})
        for (const Layout& l :
             {computeLayout(w, h, scale, notice), computePresentationLayout(w, h, scale, notice)})
          for (const PanelRect& r :
               {l.header, l.notice, l.subjects, l.controls, l.metrics, l.input, l.reconstruction,
                l.playback, l.coefficients, l.jointErrors, l.profile, l.log, l.drawerTabs,
                l.presentationBar})
            EXPECT_TRUE(onWholePixels(r))
                << w << "x" << h << " at " << scale << (notice ? " with the notice row" : "")
                << (l.presentation ? ", presenting" : "") << ": [" << r.pos.x << ", " << r.pos.y
                << ", " << r.size.x << ", " << r.size.y << "]";
}

TEST(Layout, TheDrawersTabsWrapOntoMoreRowsWhenNarrow) {
  EXPECT_LT(drawerTabsHeight(700.0f, 1.0f), drawerTabsHeight(400.0f, 1.0f));
  EXPECT_LT(drawerTabsHeight(400.0f, 1.0f), drawerTabsHeight(250.0f, 1.0f));
  EXPECT_FLOAT_EQ(drawerTabsHeight(800.0f, 2.0f), 2.0f * drawerTabsHeight(400.0f, 1.0f));
  // 1024×768 at scale 2: a drawer of 341 px holds the tabs on five rows (Subjects, Controls,
  // Coefficients, Errors and View, Log), as the drawer panel wraps them.
  EXPECT_FLOAT_EQ(drawerTabsHeight(1024.0f / 3.0f, 2.0f), (5 * 30.0f + 14.0f) * 2.0f);
}

}  // namespace
}  // namespace ew::ui
