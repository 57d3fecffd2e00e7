#pragma once
// What the layout tests ask of one exported state (issue 18): no window or table column has
// content cut at its edge, and no caption, legend or colour bar covers the walker of its view
// (export_state's layout.overflow and layout.overlays).

#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ew::test::gui {

// [x, y, w, h] rectangles.
inline bool overlap(const nlohmann::json& a, const nlohmann::json& b) {
  const double ax = a[0], ay = a[1], aw = a[2], ah = a[3], bx = b[0], by = b[1], bw = b[2], bh = b[3];
  return ax < bx + bw && bx < ax + aw && ay < by + bh && by < ay + ah;
}

// What one exported state shows: nothing cut, nothing over the walker of `views`.
inline void expectLayoutHolds(const nlohmann::json& state, const std::string& where,
                              std::initializer_list<const char*> views = {"input", "reconstruction"}) {
  const auto& layout = state.at("layout");
  for (const auto& [window, px] : layout.at("overflow").items())
    ADD_FAILURE() << where << ": " << window << " is cut by " << px.get<double>() << " px";
  const auto& o = layout.at("overlays");
  for (const char* view : views) {
    const std::string v(view);
    // The views asked about draw a walker: its rectangle must be there to check against.
    if (!o.contains(v + ".walker")) {
      ADD_FAILURE() << where << ": no " << v << ".walker reported";
      continue;
    }
    for (const char* what : {"caption", "legend", "colour_bar"}) {
      const std::string key = v + "." + what;
      if (o.contains(key)) {
        EXPECT_FALSE(overlap(o.at(key), o.at(v + ".walker"))) << where << ": the " << key << " covers the walker";
      }
    }
  }
}

// The sizes where the layout is tightest, as issue 18's matrix has them.
struct LayoutCell {
  const char* size;
  const char* scale;
  const char* theme;
};
inline const std::vector<LayoutCell>& teachingCells() {
  static const std::vector<LayoutCell> cells = {{"1024x768", "2", "projector"},
                                                {"1280x720", "2", "dark"},
                                                {"1366x768", "1", "light"},
                                                {"1920x1080", "1.5", "projector"}};
  return cells;
}
inline const std::vector<std::string>& drawerTabs() {
  static const std::vector<std::string> tabs = {"subjects", "controls", "coefficients", "errors", "view", "log"};
  return tabs;
}

// Script steps showing each drawer tab in turn and exporting the state as DIR/PREFIX_TAB.json.
inline nlohmann::json everyTabStates(const std::filesystem::path& dir, const std::string& prefix) {
  nlohmann::json steps = nlohmann::json::array();
  for (const auto& tab : drawerTabs()) {
    steps.push_back({{"drawer_tab", tab}});
    steps.push_back({{"wait_frames", 2}});
    steps.push_back({{"export_state", (dir / (prefix + "_" + tab + ".json")).string()}});
  }
  return steps;
}

}  // namespace ew::test::gui
