// `eigenwalker-cli export-html --out walker.html [--input FILE | --walker ID] [--model M]
// [--angle DEG] [--theme …] [--lines] [--translate] …`: one walker as a self-contained HTML
// page that animates it in any browser (core/teaching/html_walker.h).
#include <iostream>
#include <optional>

#include "app/cli/commands.h"
#include "core/common/errors.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/joint_completion.h"
#include "core/eigenwalker/model_file.h"
#include "core/gait/dataset.h"
#include "core/teaching/html_walker.h"

namespace ew::cli {
namespace {

struct ExportHtmlArgs {
  std::string out;
  std::string input;   // a 3D trial, fitted as `joints` prepares it
  std::string walker;  // a walker of the model: its id or its 1-based number
  std::string model;   // empty: the default model of real walkers
  std::optional<double> rateHz;  // given: checked by the reader (checkedRateOverrideHz)
  std::string units, mapping;
  std::optional<double> translateSpeedMps;
  std::string size = "800x600";
  std::string theme = "dark";
  std::string framing = "fit";
  HtmlWalkerSettings settings;
};

// The walker chosen, and its own speed when known (the default progression speed).
struct ChosenWalker {
  HtmlWalker walker;
  std::optional<double> speedMps;
  std::string speedSource;  // what speedMps is, for the report
};

std::optional<double> meanKnownSpeed(const EigenwalkerModel& model) {
  double sum = 0.0;
  int n = 0;
  for (int r = 0; r < model.walkerCount(); ++r)
    if (const auto v = model.speedMpsOf(r); v && std::isfinite(*v) && *v > 0.0) sum += *v, ++n;
  if (n == 0) return std::nullopt;
  return sum / n;
}

int walkerIndex(const EigenwalkerModel& model, const std::string& key,
                const std::string& modelName) {
  for (int r = 0; r < model.walkerCount(); ++r)
    if (model.walkerIds[static_cast<std::size_t>(r)] == key) return r;
  try {
    std::size_t used = 0;
    const int n = std::stoi(key, &used);
    if (used == key.size() && n >= 1 && n <= model.walkerCount()) return n - 1;
  } catch (const std::exception&) {
  }
  throw Error(ErrorKind::BadArgument, "--walker", "",
              "\"" + key + "\" is no walker's id, nor a number from 1 to " +
                  std::to_string(model.walkerCount()) + ", in the model " + modelName +
                  " (its walkers: " + listForMessage(model.walkerIds, 6) + ")");
}

ChosenWalker chooseWalker(const ExportHtmlArgs& args) {
  const EigenwalkerModel model = args.model.empty() ? defaultRealModel() : loadModel(args.model);
  const std::string modelName = args.model.empty() ? defaultRealModelName() : args.model;
  ChosenWalker c;
  if (!args.input.empty()) {
    LoadOptions options;
    if (args.rateHz) options.rateHzOverride = *args.rateHz;
    if (!args.units.empty()) options.unitsOverride = args.units;
    if (!args.mapping.empty()) options.mappingFile = args.mapping;
    const CompletedTrial t = completeWalkingTrial(loadWalkingTrial(args.input, options), model);
    for (const auto& w : t.trial.joints.warnings)
      std::cerr << "warning: " << args.input << ": " << w << "\n";
    c.walker = {t.fit.w, t.fit.omegaRadS, t.fit.phaseRad, args.input};
    if (t.trial.speedMps > 0.0) c.speedMps = t.trial.speedMps;
    c.speedSource = "the trial's own";
    return c;
  }
  if (!args.walker.empty()) {
    const int r = walkerIndex(model, args.walker, modelName);
    c.walker = {storedWalkerVectors(model).col(r), model.omegasRadS(r), 0.0,
                model.walkerIds[static_cast<std::size_t>(r)] + ", one of " + modelName};
    c.speedMps = model.speedMpsOf(r);
    c.speedSource = "the walker's own";
    return c;
  }
  // The mean walker: the walkers are phase-aligned (METHOD §3), so their mean is a walk; its
  // ω is the mean of theirs.
  c.walker = {model.mean, model.omegasRadS.mean(), 0.0,
              "the mean walker of " + modelName};
  c.speedMps = meanKnownSpeed(model);
  c.speedSource = "the mean of the model's walkers";
  return c;
}

template <class T>
T pickName(const std::string& value, const std::string& option,
           std::initializer_list<std::pair<const char*, T>> names) {
  std::string known;
  for (const auto& [name, v] : names) {
    if (value == name) return v;
    known += std::string(known.empty() ? "" : ", ") + name;
  }
  throw Error(ErrorKind::BadArgument, option, "", "\"" + value + "\" is not one of " + known);
}

void parseSize(const std::string& size, HtmlWalkerSettings& s) {
  const std::size_t x = size.find('x');
  try {
    std::size_t a = 0, b = 0;
    if (x != std::string::npos) {
      s.widthPx = std::stoi(size.substr(0, x), &a);
      s.heightPx = std::stoi(size.substr(x + 1), &b);
      if (a == x && b == size.size() - x - 1) return;
    }
  } catch (const std::exception&) {
  }
  throw Error(ErrorKind::BadArgument, "--size", "",
              "\"" + size + "\": expected WIDTHxHEIGHT in pixels, e.g. 800x600");
}

int runExportHtml(ExportHtmlArgs args) {
  HtmlWalkerSettings& s = args.settings;
  s.theme = pickName<HtmlTheme>(args.theme, "--theme",
                                {{"dark", HtmlTheme::Dark},
                                 {"light", HtmlTheme::Light},
                                 {"projector", HtmlTheme::Projector}});
  s.framing = pickName<HtmlFraming>(args.framing, "--framing",
                                    {{"fit", HtmlFraming::Fit}, {"viewer", HtmlFraming::Viewer}});
  parseSize(args.size, s);
  const ChosenWalker c = chooseWalker(args);
  std::string speedSource = "given";
  if (args.translateSpeedMps) {
    s.translateSpeedMps = *args.translateSpeedMps;
  } else if (c.speedMps) {
    s.translateSpeedMps = *c.speedMps;
    speedSource = c.speedSource;
  } else {
    speedSource = "a typical adult's, the walker's own unknown";
  }
  writeWalkerHtml(args.out, c.walker, s);
  std::cerr << "wrote " << args.out << ": " << c.walker.name << ", view angle " << s.viewAngleDeg
            << " deg, " << s.widthPx << "x" << s.heightPx << " px";
  if (s.translate)
    std::cerr << ", walking overground at " << s.translateSpeedMps << " m/s (" << speedSource
              << ")";
  std::cerr << "\n";
  return 0;
}

}  // namespace

void addExportHtmlCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<ExportHtmlArgs>();
  HtmlWalkerSettings& s = args->settings;
  auto* cmd =
      app.add_subcommand("export-html",
                         "Write one walker as a self-contained HTML page that animates it as point "
                         "lights in any browser (no server, nothing fetched)");
  cmd->add_option("--out", args->out, "Output .html (written atomically)")->required();
  auto* input =
      cmd->add_option(
             "--input", args->input,
             "A 3D trial (.c3d .bvh .amc .trc .csv .tsv) to fit, as `joints` prepares it; joints "
             "it lacks come from the model")
          ->check(CLI::ExistingFile);
  cmd->add_option(
         "--walker", args->walker,
         "A walker of the model, by id or 1-based number (an unknown one is answered with the ids); "
         "default: the model's mean walker")
      ->excludes(input);
  cmd->add_option("--model", args->model,
                  "Model (.ewm) whose walker is shown or that completes a trial; "
                  "default: the model of real walkers shipped with the program")
      ->check(CLI::ExistingFile);
  cmd->add_option("--rate", args->rateHz, "With --input: frame rate in Hz, overriding the file's")
      ->needs(input);
  cmd->add_option("--units", args->units,
                  "With --input: length unit overriding the file's: mm, cm, m, in, cmu")
      ->needs(input);
  cmd->add_option("--mapping", args->mapping,
                  "With --input: joint mapping file (JSON, docs/FORMATS.md)")
      ->needs(input);
  cmd->add_option("--angle", s.viewAngleDeg,
                  "View angle α in degrees (docs/METHOD.md §5): 0 from behind, 90 the "
                  "walker's right side")
      ->capture_default_str();
  cmd->add_option("--elevation", s.elevationDeg,
                  "Camera elevation in degrees, -90 to 90 (> 0 looks down)")
      ->capture_default_str();
  cmd->add_option("--speed", s.playbackSpeed,
                  "Playback speed, -5 to 5 (1 real time; < 0 walks backwards)")
      ->capture_default_str();
  cmd->add_option("--phase", s.startPhase01,
                  "Where in the gait cycle the page starts, 0 to 1 (the viewer's phase)")
      ->capture_default_str();
  cmd->add_flag("--lines", s.lines, "Draw the 14 bones between the dots (a stick figure)");
  cmd->add_flag("--translate", s.translate,
                "Walk overground across the page (default: on a treadmill)");
  cmd->add_option("--translate-speed", args->translateSpeedMps,
                  "Overground speed in m/s; default: the walker's own where known, else 1.3");
  cmd->add_option("--size", args->size, "Canvas size in pixels, WIDTHxHEIGHT")
      ->capture_default_str();
  cmd->add_option("--dot-radius", s.dotRadiusPx, "Dot radius in pixels")->capture_default_str();
  cmd->add_option("--theme", args->theme, "dark, light or projector")->capture_default_str();
  cmd->add_option("--dot-colour", s.dotColour, "Dot colour #rrggbb (default: the theme's)");
  cmd->add_option("--background", s.backgroundColour,
                  "Background colour #rrggbb (default: the theme's)");
  cmd->add_option(
         "--framing", args->framing,
         "How millimetres map to pixels: fit (the walker fills the canvas) or viewer (the viewer's "
         "2D view: 2.35 m high, every walker to one scale)")
      ->capture_default_str();
  cmd->add_option("--title", s.title, "The page's title")->capture_default_str();
  cmd->add_option("--caption", s.caption, "A caption under the title");
  cmd->callback([args, &exitCode] { exitCode = runExportHtml(*args); });
}

}  // namespace ew::cli
