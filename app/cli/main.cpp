// eigenwalker-cli: the command-line face of core. Parsing only; the work is in core.
#include <iostream>

#include "app/cli/commands.h"
#include "core/common/errors.h"
#include "ew_version.h"

int main(int argc, char** argv) {
  CLI::App app{"eigenwalker-cli: load walking motion capture, build eigenwalker models, "
               "reconstruct 3D walkers from 2D views"};
  app.set_version_flag("--version", std::string("eigenwalker-cli ") + EW_VERSION + " (commit " +
                                        EW_GIT_COMMIT + ")");
  app.require_subcommand(1);
  int exitCode = 0;
  ew::cli::addInfoCommand(app, exitCode);
  ew::cli::addJointsCommand(app, exitCode);
  ew::cli::addAnglesCommand(app, exitCode);
  ew::cli::addGaitCommand(app, exitCode);
  ew::cli::addSynthCommand(app, exitCode);
  ew::cli::addBuildCommand(app, exitCode);
  ew::cli::addEvaluateCommand(app, exitCode);
  ew::cli::addReconstructCommand(app, exitCode);
  ew::cli::addExportHtmlCommand(app, exitCode);
#ifdef EW_HAVE_VIDEO
  ew::cli::addTrackCommand(app, exitCode);
  ew::cli::addDetectCommand(app, exitCode);
  ew::cli::addTrackStudyCommand(app, exitCode);
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : ew::cli::kExitUsage;
  } catch (const ew::Error& e) {
    std::cerr << "error: " << e.what() << "\n";
    return e.kind() == ew::ErrorKind::BadArgument ? ew::cli::kExitUsage : ew::cli::kExitDataError;
  }
  return exitCode;
}
