// eigenwalker: the viewer. Parses the command line and runs the app (ui/app/app.h).
//   eigenwalker [DATA…] [--size WxH] [--script FILE.json] [--screenshot OUT.png]
//               [--bench-frames N] [--ui-scale S] [--no-settings] [--full-redraw]
//               [--check-repaint]
// docs/VIEWER.md describes the views, the controls and the script format.

#include <CLI/CLI.hpp>

#include <cstdio>
#include <regex>
#include <string>
#include <vector>

#include "ui/app/app.h"

int main(int argc, char** argv) {
  CLI::App cli{"Eigenwalker viewer: the 2D view of a walker beside its 3D reconstruction"};
  std::vector<std::string> data;
  std::string size = "1600x900";
  std::string script, screenshot;
  int benchFrames = 0;
  float uiScale = 1.0f;
  cli.add_option(
      "data", data,
      "Manifest CSV, folders or motion-capture files (default: the synthetic population); "
      "one or two trials are inspected against the default model of real walkers; a "
      ".ewm model file is held and the trials are inspected against it");
  auto* sizeOption = cli.add_option("--size", size, "Window size WxH in screen coordinates")->capture_default_str();
  cli.add_option("--script", script, "JSON script of actions to run, then exit (docs/VIEWER.md)")
      ->check(CLI::ExistingFile);
  cli.add_option("--screenshot", screenshot, "Write the final frame to this PNG, then exit");
  cli.add_option("--bench-frames", benchFrames,
                 "Render N frames with playback running, print frame times as JSON, exit")
      ->check(CLI::NonNegativeNumber);
  bool noSettings = false;
  cli.add_flag("--no-settings", noSettings,
               "Neither read nor write the saved settings (also EIGENWALKER_NO_SETTINGS=1)");
  bool fullRedraw = false;
  cli.add_flag("--full-redraw", fullRedraw,
               "Repaint the whole window every frame instead of only what changed (for comparison)");
  bool checkRepaint = false;
  cli.add_flag("--check-repaint", checkRepaint,
               "Compare every frame with a full redraw; report, and fail on, any difference (slow; for tests)");
  auto* scaleOption = cli.add_option("--ui-scale", uiScale, "UI scale on top of the monitor's content scale")
      ->check(CLI::Range(0.5f, 4.0f))
      ->capture_default_str();
  CLI11_PARSE(cli, argc, argv);

  ew::ui::AppOptions options;
  for (const auto& d : data) options.data.emplace_back(d);
  std::smatch m;
  const std::regex sizePattern(R"((\d{2,5})[xX](\d{2,5}))");
  if (!std::regex_match(size, m, sizePattern)) {
    std::fprintf(stderr, "eigenwalker: --size expects WxH, e.g. 1600x900 (got \"%s\")\n", size.c_str());
    return 2;
  }
  options.width = std::stoi(m[1].str());
  options.height = std::stoi(m[2].str());
  if (!script.empty()) options.script = script;
  if (!screenshot.empty()) options.screenshot = screenshot;
  options.benchFrames = benchFrames;
  options.uiScale = uiScale;
  options.sizeGiven = sizeOption->count() > 0;
  options.uiScaleGiven = scaleOption->count() > 0;
  options.useSettings = !noSettings;
  options.fullRedraw = fullRedraw;
  options.checkRepaint = checkRepaint;
  return ew::ui::runApp(options);
}
