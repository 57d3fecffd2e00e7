#pragma once
// Data loading (load_actions.cpp): opening files and folders, the models built for them, the
// model held.
// Part of the viewer's actions (ui/app/actions.h): each validates its argument and throws
// std::invalid_argument with a readable message when it cannot apply.

#include <filesystem>
#include <string>
#include <vector>

#include "core/mapping/mapping_file.h"
#include "ui/app/app_state.h"

namespace ew::ui::actions {

// Starts loading `paths` (empty = the synthetic default population) in the background.
// The data on screen stays until the new data has loaded; a load that fails leaves it, and
// everything the user chose, as it was, and says why (reportOpenError).
void open(AppState& s, std::vector<std::filesystem::path> paths);
// Picks up finished background jobs; starts the model build after a load. Call once a frame.
// A model build that fails puts back the data shown before the load.
void pollJobs(AppState& s);

// [SECTION] Opening data
// Files or folders dropped on the window (or the script action "drop"): the items that exist
// and are a folder or a supported file (.c3d .bvh .asf .amc .trc .csv .tsv) are opened, the others
// skipped with a warning; throws std::invalid_argument (and opens nothing) when none is.
void drop(AppState& s, const std::vector<std::filesystem::path>& paths);
// Unit ("" = the file's; mm, cm, m, in, cmu) and frame rate (0 = the file's) for one file;
// takes effect at the next open (reloadWithOverrides reopens the current data).
void setFileOverride(AppState& s, const std::filesystem::path& file, const std::string& units,
                     double rateHz);
void reloadWithOverrides(AppState& s);
// Writes `mapping` (core/mapping/mapping_file.h) to `out` and makes it `file`'s mapping for the
// next open (a per-file override); `openNow`: opens `file` with it at once. Throws ew::Error
// naming the file when it cannot be written.
void writeJointMapping(AppState& s, const std::filesystem::path& file,
                       const std::filesystem::path& out, const JointMapping& mapping, bool openNow);
// The data table for the current data: started in the background / computed now (scripts).
void requestDataSummary(AppState& s);
std::shared_ptr<const DataSummary> dataSummaryNow(AppState& s);
void exportDataSummary(AppState& s, const std::filesystem::path& path);

// [SECTION] The model held (docs/VIEWER.md, "Models and walkers")
// "population" (the loaded population's leave-one-out models), "default" (the default model
// of real walkers), or an opened .ewm by file name or path (a path not opened yet is read).
// Every walker is then inspected against it. Throws std::invalid_argument with the reason.
void setModelSource(AppState& s, const std::string& which);

}  // namespace ew::ui::actions
