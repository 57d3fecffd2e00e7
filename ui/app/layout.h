#pragma once
// Where each panel goes: a fixed layout computed from the window size and the UI scale.
// When everything fits:
//   header (full width)
//   notice row (full width; only while an error or warning is shown)
//   subjects | metrics strip            | coefficients
//   controls | 2D input | 3D view       |
//            | playback                 |
//            | joint errors | J(α) | log |
// The side columns narrow (down to 230 and 220 px of the scale's) so that the views keep two
// thirds of the width. When they cannot — the views would get less than a third each, or
// the bottom row would leave them less than 0.35 of the height (a small window, or a large
// UI scale: 1280×720 at scale 2) — the six side and bottom panels share one column, a
// drawer, one at a time under a row of tabs, and the views take the rest:
//   header
//   notice | metrics strip   (the notice row over the drawer only)
//   tabs   |
//   drawer | 2D input | 3D view
//          | playback
// Presentation mode (F5; computePresentationLayout) keeps only the two views, side by side
// over the whole width, and a bar under them with play / pause and the view angle:
//   notice (only while shown)
//   2D input | 3D view
//   presentation bar

#include <array>

#include "ui/panels/panel_window.h"

namespace ew::ui {

// The drawer's panels, in the order of its tabs.
enum class DrawerTab { Subjects, Controls, Coefficients, JointErrors, Profile, Log };
inline constexpr std::array<DrawerTab, 6> kDrawerTabs{DrawerTab::Subjects, DrawerTab::Controls,
                                                      DrawerTab::Coefficients, DrawerTab::JointErrors,
                                                      DrawerTab::Profile, DrawerTab::Log};
const char* drawerTabName(DrawerTab tab);  // "Subjects", "Controls", …

struct Layout {
  PanelRect header, notice, subjects, controls, metrics, input, reconstruction, playback,
      coefficients, jointErrors, profile, log;
  bool drawer = false;    // the side and bottom panels share `drawerBody`, one at a time
  PanelRect drawerTabs;   // the tab row above it (drawer only)
  bool presentation = false;  // only the views, `notice` and `presentationBar` are drawn
  PanelRect presentationBar;  // play / pause and the view angle (presentation only)
};

// Every rectangle's edges are whole pixels (layout.cpp says why).
// `noticeRow`: a row under the header for the error / warning notice, so that it covers
// nothing at any window size (the views move down by its height).
Layout computeLayout(float width, float height, float scale, bool noticeRow = false);
// Presentation mode: the two views fill the window above the presentation bar; every other
// rectangle is empty.
Layout computePresentationLayout(float width, float height, float scale, bool noticeRow = false);
// The presentation bar's height at `scale` (tall enough for the view-angle dial).
float presentationBarHeight(float scale);
// The notice row's height at `scale`.
float noticeRowHeight(float scale);
// The drawer's tab rows' height for a drawer `drawerWidth` wide at `scale`: a narrow drawer
// wraps its six tabs onto as many rows as the drawer panel will (up to six).
float drawerTabsHeight(float drawerWidth, float scale);
// The one row that replaces the tabs when they would take more than 0.45 of the height.
float drawerComboHeight(float scale);

}  // namespace ew::ui
