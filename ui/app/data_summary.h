#pragma once
// The data table of the Data window (like `eigenwalker-cli info`): one core TrialSummary per
// file of the opened paths, with each file's overrides; computed off the UI thread.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/gait/trial_summary.h"
#include "ui/app/population.h"

namespace ew::ui {

struct DataSummary {
  std::uint64_t generation = 0;            // of the document it describes
  std::vector<TrialSummary> rows;          // one per file
  std::vector<std::string> warnings;       // from collecting the files (skipped, unknown type)
};

// Summarises every trial file the paths name (folders, manifests, files) with its overrides.
DataSummary summarizeData(const std::vector<std::filesystem::path>& paths, const FileOverrides& overrides,
                          const ProgressFn& progress = {});

// The table as JSON (the fields of `eigenwalker-cli info --json`), written atomically.
void writeDataSummaryJson(const DataSummary& summary, const std::filesystem::path& file);

// Files and folders the viewer can open: .c3d .bvh .asf .amc .trc .csv .tsv (case-insensitive).
bool isSupportedDataFile(const std::filesystem::path& file);

}  // namespace ew::ui
