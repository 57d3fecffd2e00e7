// `eigenwalker-cli info [--json] PATH…`: one row (or JSON object) per trial.
#include <iomanip>
#include <optional>
#include <set>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli/commands.h"
#include "app/cli/video_beside_keypoints.h"
#include "app/cli/video_input.h"
#include "core/gait/dataset.h"
#include "core/gait/trial_summary.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_summary.h"

namespace ew::cli {
namespace {

struct InfoArgs {
  std::vector<std::string> paths;
  bool json = false;
  std::optional<double> rateHz;  // given: checked by the reader (checkedRateOverrideHz)
  std::string units;
  std::string mapping;  // joint mapping file (--mapping)
  std::string layout;   // keypoint layout (--layout)
  std::string imageSize;  // a MediaPipe CSV's image (--image-size)
  std::string detectModel = "full";  // the pose detector's model for a video (--detect-model)
};

std::string joined(const std::vector<std::string>& items, const char* sep) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : sep) + s;
  return out;
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

nlohmann::json segmentsJson(const TrialSummary& s) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& g : s.segments) {
    out.push_back({{"begin", g.begin}, {"end", g.end}, {"steady_begin", g.steadyBegin},
                   {"steady_end", g.steadyEnd}, {"heading_deg", g.headingDeg},
                   {"speed_mps", g.medianSpeedMps}});
  }
  return out;
}

nlohmann::json toJson(const TrialSummary& s) {
  return {{"straight_segments", segmentsJson(s)}, {"segment_used", s.segment},{"file", s.file}, {"format", s.format}, {"frames", s.frames}, {"rate_hz", s.rateHz},
          {"duration_s", s.durationS}, {"units", s.units}, {"points_found", s.pointsFound},
          {"source", s.source}, {"joints_estimated", s.estimatedJoints},
          {"joints_model_estimated", s.modelEstimatedJoints},
          {"window_frames", s.windowFrames}, {"cycles", s.cycles}, {"stride_hz", s.strideHz},
          {"cycle_method", s.cycleMethod}, {"speed_mps", s.speedMps}, {"warnings", s.warnings},
          {"ok", s.ok()}, {"error", s.error}, {"error_stage", s.errorStage}};
}

// Joints estimated by the loader's rule, then those a model will estimate ("model: …").
std::string estimatedCell(const TrialSummary& s) {
  std::string cell = joined(s.estimatedJoints, ",");
  if (!s.modelEstimatedJoints.empty())
    cell += (cell.empty() ? "model: " : "; model: ") + joined(s.modelEstimatedJoints, ",");
  return cell.empty() ? "-" : cell;
}

std::vector<std::string> tableRow(const TrialSummary& s) {
  return {s.file, s.format, std::to_string(s.frames), fixed(s.rateHz, 2), fixed(s.durationS, 2),
          s.units, std::to_string(s.pointsFound) + (s.source.empty() ? "" : " (" + s.source + ")"),
          estimatedCell(s),
          s.ok() ? fixed(s.cycles, 2) : "-", s.ok() ? fixed(s.strideHz, 3) : "-",
          s.ok() ? fixed(s.speedMps, 2) : "-",
          s.ok() ? joined(s.warnings, "; ") : "ERROR (" + s.errorStage + "): " + s.error +
                                                 (s.warnings.empty() ? "" : " | " + joined(s.warnings, "; "))};
}

void printTable(const std::vector<TrialSummary>& summaries) {
  std::vector<std::vector<std::string>> rows = {
      {"file", "format", "frames", "rate_hz", "duration_s", "units", "markers_or_joints",
       "joints_estimated", "cycles", "stride_hz", "speed_mps", "warnings"}};
  for (const auto& s : summaries) rows.push_back(tableRow(s));
  std::vector<size_t> width(rows.front().size(), 0);
  for (const auto& r : rows) {
    for (size_t c = 0; c + 1 < r.size(); ++c) width[c] = std::max(width[c], r[c].size());
  }
  for (const auto& r : rows) {
    for (size_t c = 0; c < r.size(); ++c) {
      std::cout << r[c];
      if (c + 1 < r.size()) std::cout << std::string(width[c] - r[c].size() + 2, ' ');
    }
    std::cout << "\n";
  }
}

// What `info` says of a video: the detector's clip summarised as a keypoint file is, with the
// people it followed; a video it cannot read, or the models missing, ends at stage "read".
TrialSummary videoSummary(const std::filesystem::path& video, KeypointOptions k, const std::string& model) {
  KeypointFrames frames;
  try {
    frames = detectKeypointFrames(video, {model, true, true, false}, k);
  } catch (const std::exception& e) {
    TrialSummary s;
    s.file = video.string();
    s.error = e.what();
    s.errorStage = "read";
    return s;
  }
  return summarizeKeypointFrames(frames, k);
}

int runInfo(const InfoArgs& args) {
  LoadOptions options;
  if (args.rateHz) options.rateHzOverride = *args.rateHz;
  if (!args.units.empty()) options.unitsOverride = args.units;
  if (!args.mapping.empty()) options.mappingFile = args.mapping;
  std::vector<std::filesystem::path> paths, videos;
  for (const auto& p : args.paths) (isVideoFile(p) ? videos : paths).emplace_back(p);
  std::vector<std::string> warnings;
  KeypointOptions keypoints;
  if (args.rateHz) keypoints.fps = *args.rateHz;
  if (!args.layout.empty()) keypoints.layout = args.layout;
  if (!args.mapping.empty()) keypoints.mappingFile = args.mapping;
  if (!args.imageSize.empty()) keypoints.imageSize = parseKeypointImageSize(args.imageSize, "--image-size");
  std::vector<TrialSummary> summaries;
  // Each keypoint input's own video, found beside it: its size and rate where none is given.
  const auto keypointSummary = [&](const std::filesystem::path& p) {
    KeypointOptions own = keypoints;
    takeTheVideoBeside(p, own);
    return summarizeKeypoints(p, own);
  };
  // A video: the walker found by the built-in detector (through the detection cache).
  for (const auto& v : videos) summaries.push_back(videoSummary(v, keypoints, args.detectModel));
  std::set<std::filesystem::path> summarised;  // a keypoint file both collectors find is shown once
  if (!paths.empty()) {
    for (const auto& f : collectTrialFiles(paths, warnings)) {
      const bool isKeypointFile = looksLikeKeypointInput(f.path);
      if (isKeypointFile) summarised.insert(f.path.lexically_normal());
      summaries.push_back(isKeypointFile ? keypointSummary(f.path) : summarizeTrial(f.path, options));
    }
    for (const auto& p : collectKeypointInputs(paths))
      if (summarised.insert(p.lexically_normal()).second) summaries.push_back(keypointSummary(p));
  }
  for (const auto& w : warnings) std::cerr << "warning: " << w << "\n";
  if (args.json) {
    nlohmann::json all = nlohmann::json::array();
    for (const auto& s : summaries) all.push_back(toJson(s));
    std::cout << all.dump(2) << "\n";
  } else {
    printTable(summaries);
  }
  bool anyFailed = summaries.empty();
  for (const auto& s : summaries) anyFailed = anyFailed || !s.ok();
  if (summaries.empty()) std::cerr << "error: no trial files found in the given paths\n";
  return anyFailed ? kExitDataError : 0;
}

}  // namespace

void addInfoCommand(CLI::App& app, int& exitCode) {
  auto args = std::make_shared<InfoArgs>();
  auto* cmd = app.add_subcommand("info", "One row per trial: format, frames, rate, units, "
                                         "markers/joints, estimated joints, cycles, stride "
                                         "frequency, speed, warnings. Motion capture and "
                                         "pose-estimator keypoint files (OpenPose, AlphaPose, "
                                         "MMPose JSON, MediaPipe and DeepLabCut CSV). Exit 1 if any trial is unusable.");
  cmd->add_option("paths", args->paths, "Files, folders (recursive) or manifest CSVs")->required();
  cmd->add_flag("--json", args->json, "One JSON object per trial instead of a table");
  cmd->add_option("--detect-model", args->detectModel,
                  "for a video: the built-in pose detector's model, lite, full (default) or heavy")
      ->check(CLI::IsMember({"lite", "full", "heavy"}));
  cmd->add_option("--rate", args->rateHz,
                  "Frame rate in Hz, overriding the file's (AMC and keypoint JSON have none; default 30)");
  cmd->add_option("--layout", args->layout,
                  "Keypoint layout of pose-estimator files (BODY_25, BODY_25B, COCO-18, COCO-17, "
                  "Halpe-26, MediaPipe-33); guessed when not given");
  cmd->add_option("--image-size", args->imageSize,
                  "WxH in pixels of the video behind a MediaPipe CSV or YOLO labels (their x, y are fractions "
                  "of it); else the size of a video found beside them (docs/KEYPOINTS.md)");
  cmd->add_option("--units", args->units, "Length unit overriding the file's: mm, cm, m, in, cmu");
  cmd->add_option("--mapping", args->mapping,
                  "Joint mapping file (JSON, docs/FORMATS.md): which markers make each joint, "
                  "for marker sets the program does not know, and DeepLabCut body parts");
  cmd->callback([args, &exitCode] { exitCode = runInfo(*args); });
}

}  // namespace ew::cli
