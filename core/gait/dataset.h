#pragma once
// Datasets (METHOD §4): a folder (recursive), a list of files, or a manifest CSV
// (`file,subject,source,condition[,extra…]`, paths relative to the manifest). Extra
// manifest columns are kept as walker attributes.

#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/gait/prepare.h"
#include "core/gait/walking_trial.h"
#include "core/io/load_trial.h"

namespace ew {

// The condition of a trial whose manifest names none (or that has no manifest).
inline constexpr const char* kUnspecifiedCondition = "unspecified";

struct TrialInfo {
  std::string file;       // resolved path
  std::string subject;    // manifest subject, else derived from the file name
  std::string source;     // manifest source, else the format
  std::string condition;  // manifest condition, else "unspecified"
  std::map<std::string, std::string> attributes;  // extra manifest columns
};

struct DatasetTrial {
  TrialInfo info;
  WalkingTrial trial;
};

struct Dataset {
  std::vector<DatasetTrial> trials;
  std::vector<std::string> warnings;          // files skipped and why, odd manifest rows, …
  std::vector<std::string> subjects() const;  // distinct, in first-seen order
};

// A folder walked for trials may hold this many entries (files and folders, at any depth) and
// this many trial files at most: past them the user opened the wrong folder (a home or the
// whole disk), and the walk stops with an error rather than read everything there. (CMU's
// whole motion capture database is 2,605 trials.)
struct FolderLimits {
  long entries = 200000;
  long trialFiles = 20000;
};

// The trial files the paths name (folders recursively, manifests row by row), in order,
// without loading them. `required` is false for files found by walking a folder. Throws
// Error(BadArgument) naming a folder past the limits.
struct TrialFile {
  std::filesystem::path path;
  TrialInfo info;
  bool required = true;
};
std::vector<TrialFile> collectTrialFiles(const std::vector<std::filesystem::path>& paths,
                                         std::vector<std::string>& warnings,
                                         const FolderLimits& limits = {});

// Items opened one by one (the viewer's drop): an .asf given with an .amc of its own folder
// is not an item of its own (the .amc opens with it), so "x.asf + y.amc" dropped together
// is the one trial y, not y plus every motion beside x. Other paths are kept, in order.
std::vector<std::filesystem::path> withoutSkeletonsOfGivenMotions(
    const std::vector<std::filesystem::path>& paths);

// One file through the whole path: read, map to 15 joints, prepare (METHOD §1-2).
WalkingTrial loadWalkingTrial(const std::filesystem::path& file, const LoadOptions& options = {},
                              const PrepareOptions& prepare = {});

// The subject a file names when no manifest says: its stem before the first underscore
// ("2014001_C4_05" → "2014001", "07_02" → "07"), else the whole stem.
std::string subjectFromFileName(const std::filesystem::path& file);

// True when a .csv file's first line is a manifest header (starts with "file,").
bool isManifest(const std::filesystem::path& file);

using ProgressFn = std::function<void(int done, int total, const std::string& current)>;

// Loads every trial. A manifest's unreadable file is an error (the manifest promised it);
// in a folder, files of unknown type are ignored and unreadable trials become warnings.
Dataset loadDataset(const std::vector<std::filesystem::path>& paths,
                    const LoadOptions& options = {}, const ProgressFn& progress = {});
// The same with options chosen per file (the viewer's per-file unit and rate overrides).
using LoadOptionsFn = std::function<LoadOptions(const std::filesystem::path& file)>;
Dataset loadDatasetPerFile(const std::vector<std::filesystem::path>& paths,
                           const LoadOptionsFn& optionsFor, const ProgressFn& progress = {});

}  // namespace ew
