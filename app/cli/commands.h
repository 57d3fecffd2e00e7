#pragma once
// Each sub-command registers itself on the CLI11 app; main() only dispatches.
// Exit codes: 0 success, 1 a data or I/O problem (message on stderr), 2 bad arguments.

#include <CLI/CLI.hpp>

namespace ew::cli {

inline constexpr int kExitDataError = 1;
inline constexpr int kExitUsage = 2;

void addInfoCommand(CLI::App& app, int& exitCode);
void addJointsCommand(CLI::App& app, int& exitCode);
void addAnglesCommand(CLI::App& app, int& exitCode);
void addGaitCommand(CLI::App& app, int& exitCode);
void addSynthCommand(CLI::App& app, int& exitCode);
void addBuildCommand(CLI::App& app, int& exitCode);
void addEvaluateCommand(CLI::App& app, int& exitCode);
void addReconstructCommand(CLI::App& app, int& exitCode);
void addExportHtmlCommand(CLI::App& app, int& exitCode);
// Only when the video library was built (OpenCV found): EW_HAVE_VIDEO.
void addTrackCommand(CLI::App& app, int& exitCode);
void addTrackStudyCommand(CLI::App& app, int& exitCode);
void addDetectCommand(CLI::App& app, int& exitCode);

}  // namespace ew::cli
