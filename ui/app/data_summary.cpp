#include "ui/app/data_summary.h"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>

#include "core/gait/dataset.h"
#include "core/io/atomic_write.h"

namespace ew::ui {

DataSummary summarizeData(const std::vector<std::filesystem::path>& paths, const FileOverrides& overrides,
                          const ProgressFn& progress) {
  DataSummary d;
  const auto files = collectTrialFiles(paths, d.warnings);
  const int total = static_cast<int>(files.size());
  for (int i = 0; i < total; ++i) {
    const auto& f = files[static_cast<std::size_t>(i)];
    if (progress) progress(i, total, f.path.filename().string());
    const auto it = overrides.find(fileKey(f.path));
    d.rows.push_back(summarizeTrial(f.path, it == overrides.end() ? LoadOptions{} : it->second));
  }
  if (progress) progress(total, total, "");
  return d;
}

void writeDataSummaryJson(const DataSummary& summary, const std::filesystem::path& file) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& s : summary.rows)
    rows.push_back({{"file", s.file}, {"format", s.format}, {"frames", s.frames}, {"rate_hz", s.rateHz},
                    {"duration_s", s.durationS}, {"units", s.units}, {"points_found", s.pointsFound},
                    {"source", s.source}, {"joints_estimated", s.estimatedJoints}, {"cycles", s.cycles},
                    {"stride_hz", s.strideHz}, {"speed_mps", s.speedMps}, {"warnings", s.warnings},
                    {"ok", s.ok()}, {"error", s.error}, {"error_stage", s.errorStage}});
  const nlohmann::json all = {{"trials", rows}, {"warnings", summary.warnings}};
  const std::string text = all.dump(2) + "\n";
  writeFileAtomically(file, [&text](std::ostream& out) { out << text; });
}

bool isSupportedDataFile(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".c3d" || ext == ".bvh" || ext == ".asf" || ext == ".amc" || ext == ".trc" || ext == ".csv" || ext == ".tsv";
}

}  // namespace ew::ui
