#include "core/gait/dataset.h"

#include <algorithm>
#include <set>

#include "core/common/errors.h"
#include "core/gait/prepare.h"
#include "core/io/asf_amc_reader.h"
#include "core/io/file_bytes.h"
#include "core/io/load_trial.h"
#include "core/io/text_table.h"
#include "core/mapping/joint_mapping.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

using PendingTrial = TrialFile;

TrialInfo infoFromFileName(const fs::path& file) {
  TrialInfo info;
  info.file = file.string();
  info.subject = subjectFromFileName(file);
  info.source = "";
  info.condition = kUnspecifiedCondition;
  return info;
}

bool isTrialFile(const fs::path& p) {
  static const std::set<std::string> kExtensions = {".c3d", ".bvh", ".amc", ".trc", ".csv", ".tsv"};
  return kExtensions.count(toLower(p.extension().string())) > 0;
}

std::vector<PendingTrial> manifestTrials(const fs::path& manifest,
                                         std::vector<std::string>& warnings) {
  const std::string text = readFileText(manifest);
  const auto lines = splitLines(text);
  auto header = splitFields(lines.front().text, ',');
  std::vector<std::string> columns;
  for (auto h : header) columns.push_back(toLower(h));
  for (const char* needed : {"file", "subject"}) {
    if (std::find(columns.begin(), columns.end(), needed) == columns.end()) {
      throwMalformed(manifest.string(), linePosition(1),
                     std::string("manifest has no '") + needed + "' column");
    }
  }
  std::vector<PendingTrial> trials;
  for (size_t i = 1; i < lines.size(); ++i) {
    if (trim(lines[i].text).empty() || trim(lines[i].text).front() == '#') continue;
    auto fields = splitFields(lines[i].text, ',');
    if (fields.size() != columns.size()) {
      throwMalformed(
          manifest.string(), linePosition(lines[i].number),
          std::to_string(fields.size()) + " fields, header has " + std::to_string(columns.size()));
    }
    PendingTrial t;
    for (size_t c = 0; c < columns.size(); ++c) {
      const std::string value(fields[c]);
      if (columns[c] == "file")
        t.path = manifest.parent_path() / value;
      else if (columns[c] == "subject")
        t.info.subject = value;
      else if (columns[c] == "source")
        t.info.source = value;
      else if (columns[c] == "condition")
        t.info.condition = value;
      else
        t.info.attributes[std::string(header[c])] = value;
    }
    if (t.path.empty() || t.info.subject.empty()) {
      throwMalformed(manifest.string(), linePosition(lines[i].number), "empty file or subject");
    }
    if (t.info.condition.empty()) t.info.condition = kUnspecifiedCondition;
    t.info.file = t.path.string();
    trials.push_back(std::move(t));
  }
  if (trials.empty()) warnings.push_back(manifest.string() + ": manifest lists no trials");
  return trials;
}

std::vector<PendingTrial> folderTrials(const fs::path& folder, std::vector<std::string>& warnings,
                                       const FolderLimits& limits) {
  std::vector<fs::path> files;
  std::error_code ec;
  long entries = 0;
  for (fs::recursive_directory_iterator
           it(folder, fs::directory_options::skip_permission_denied, ec),
       end;
       it != end; it.increment(ec)) {
    if (ec) break;
    if (++entries > limits.entries)
      throw Error(ErrorKind::BadArgument, folder.string(), "",
                  "more than " + std::to_string(limits.entries) +
                      " files and folders under it: open the folder that holds the trials");
    if (it->is_regular_file(ec) && isTrialFile(it->path())) files.push_back(it->path());
    if (static_cast<long>(files.size()) > limits.trialFiles)
      throw Error(ErrorKind::BadArgument, folder.string(), "",
                  "more than " + std::to_string(limits.trialFiles) +
                      " trial files (.c3d, .bvh, .amc, .trc, .csv, .tsv) under it: open the folder that holds the trials");
  }
  if (ec) warnings.push_back(folder.string() + ": " + ec.message());
  std::sort(files.begin(), files.end());
  std::vector<PendingTrial> trials;
  for (const auto& f : files) {
    if (toLower(f.extension().string()) == ".csv" && isManifest(f)) {
      warnings.push_back(f.string() +
                         ": a manifest inside a folder is not followed; open it directly");
      continue;
    }
    trials.push_back({f, infoFromFileName(f), false});
  }
  return trials;
}

bool hasExtension(const fs::path& p, const char* ext) {
  return toLower(p.extension().string()) == ext;
}

// An .asf is a skeleton: given together with .amc files it adds no trial (the reader pairs
// each .amc with the .asf in its folder); given alone it stands for the .amc files beside it
// that pair with it.
std::vector<PendingTrial> asfTrials(const fs::path& asf, const std::vector<fs::path>& paths,
                                    std::vector<std::string>& warnings) {
  std::vector<PendingTrial> out;
  bool withAmc = false;
  for (const auto& q : paths) {
    if (!hasExtension(q, ".amc")) continue;
    withAmc = true;
    std::error_code ec;
    const fs::path paired = asfSkeletonFor(q);
    if (!fs::equivalent(paired, asf, ec)) {
      warnings.push_back(q.string() + ": opened with the skeleton beside it, " + paired.string() +
                         ", not " + asf.string() + " (an .amc pairs with the .asf in its folder)");
    }
  }
  if (withAmc) return out;
  for (const auto& amc : amcMotionsFor(asf)) out.push_back({amc, infoFromFileName(amc), true});
  if (out.empty()) {
    throw Error(ErrorKind::Io, asf.string(), "",
                "an .asf file is a skeleton only, and no .amc motion file beside it pairs with "
                "it (open the .amc, or both files)");
  }
  return out;
}

}  // namespace

std::string subjectFromFileName(const fs::path& file) {
  const std::string stem = file.stem().string();
  const auto cut = stem.find('_');
  return cut == 0 || cut == std::string::npos ? stem : stem.substr(0, cut);
}

std::vector<TrialFile> collectTrialFiles(const std::vector<fs::path>& paths,
                                         std::vector<std::string>& warnings,
                                         const FolderLimits& limits) {
  std::vector<PendingTrial> all;
  for (const auto& p : paths) {
    std::error_code ec;
    std::vector<PendingTrial> more;
    if (fs::is_directory(p, ec) && isTrialFile(p)) {
      throw Error(ErrorKind::Io, p.string(), "",
                  "is a folder, not a " + p.extension().string() + " file");
    }
    if (fs::is_directory(p, ec))
      more = folderTrials(p, warnings, limits);
    else if (hasExtension(p, ".asf") && fs::exists(p, ec))
      more = asfTrials(p, paths, warnings);
    else if (toLower(p.extension().string()) == ".csv" && fs::exists(p, ec) && isManifest(p))
      more = manifestTrials(p, warnings);
    else
      more = {{p, infoFromFileName(p), true}};
    all.insert(all.end(), more.begin(), more.end());
  }
  return all;
}

std::vector<fs::path> withoutSkeletonsOfGivenMotions(const std::vector<fs::path>& paths) {
  std::vector<fs::path> out;
  for (const auto& p : paths) {
    const bool skeletonOfAGivenMotion =
        hasExtension(p, ".asf") && std::any_of(paths.begin(), paths.end(), [&](const fs::path& q) {
          return hasExtension(q, ".amc") && q.parent_path() == p.parent_path();
        });
    if (!skeletonOfAGivenMotion) out.push_back(p);
  }
  return out;
}

std::vector<std::string> Dataset::subjects() const {
  std::vector<std::string> out;
  for (const auto& t : trials) {
    if (std::find(out.begin(), out.end(), t.info.subject) == out.end())
      out.push_back(t.info.subject);
  }
  return out;
}

bool isManifest(const fs::path& file) {
  const std::string text = readFileText(file);
  const auto lines = splitLines(std::string_view(text).substr(0, 4096));
  return !lines.empty() && toLower(trim(lines.front().text)).rfind("file,", 0) == 0;
}

WalkingTrial loadWalkingTrial(const fs::path& file, const LoadOptions& options,
                              const PrepareOptions& prepare) {
  JointTrial joints = mapRawTrial(readRawTrial(file, options), options);  // raw points gone here
  return prepareWalkingTrial(joints, prepare);
}

Dataset loadDataset(const std::vector<fs::path>& paths, const LoadOptions& options,
                    const ProgressFn& progress) {
  return loadDatasetPerFile(
      paths, [&options](const fs::path&) { return options; }, progress);
}

Dataset loadDatasetPerFile(const std::vector<fs::path>& paths, const LoadOptionsFn& optionsFor,
                           const ProgressFn& progress) {
  Dataset dataset;
  const auto pending = collectTrialFiles(paths, dataset.warnings);
  const int total = static_cast<int>(pending.size());
  for (int i = 0; i < total; ++i) {
    const auto& p = pending[static_cast<size_t>(i)];
    if (progress) progress(i, total, p.path.string());
    try {
      DatasetTrial trial{p.info, loadWalkingTrial(p.path, optionsFor(p.path))};
      if (trial.info.source.empty()) trial.info.source = trial.trial.joints.format;
      dataset.trials.push_back(std::move(trial));
    } catch (const Error& e) {
      if (p.required) throw;
      dataset.warnings.push_back(std::string("skipped: ") + e.what());
    }
  }
  if (progress) progress(total, total, "");
  return dataset;
}

}  // namespace ew
