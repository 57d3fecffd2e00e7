#pragma once
// The viewer application: window, GL context, Dear ImGui, the frame loop, scripted runs,
// screenshots and the frame-time benchmark. app/gui/main.cpp parses the command line
// into AppOptions and calls runApp.

#include <filesystem>
#include <optional>
#include <vector>

namespace ew::ui {

struct AppOptions {
  std::vector<std::filesystem::path> data;         // empty: the synthetic default population
  int width = 1600, height = 900;                  // window size (screen coordinates)
  std::optional<std::filesystem::path> script;     // JSON actions, then exit
  std::optional<std::filesystem::path> screenshot; // PNG of the final frame, then exit
  int benchFrames = 0;                             // render N frames with playback, print JSON, exit
  float uiScale = 1.0f;
  bool sizeGiven = false;     // --size given: wins over the saved window size
  bool uiScaleGiven = false;  // --ui-scale given: wins over the saved UI scale
  bool useSettings = true;    // --no-settings (or EIGENWALKER_NO_SETTINGS=1): neither read nor write
  bool fullRedraw = false;    // --full-redraw: repaint the whole window every frame
  bool checkRepaint = false;  // --check-repaint: compare every frame with a full redraw
};

// Runs the viewer; returns the process exit code (0 = fine, 1 = an error, reported on
// stderr: no GL context, a shader that does not compile, a failed script action, …).
int runApp(const AppOptions& options);

}  // namespace ew::ui
