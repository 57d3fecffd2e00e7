#include "core/keypoints/keypoint_summary.h"

#include <algorithm>

#include "core/common/errors.h"
#include "core/keypoints/image_gait.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

bool holdsJson(const fs::path& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (e.is_regular_file(ec) && e.path().extension() == ".json") return true;
  }
  return false;
}

void collect(const fs::path& p, int depth, std::vector<fs::path>& out) {
  std::error_code ec;
  if (fs::is_regular_file(p, ec)) {
    if (p.extension() == ".json" || (p.extension() == ".txt" && yoloLabelsFolder(p))) out.push_back(p);
    return;
  }
  if (!fs::is_directory(p, ec) || depth > 8) return;
  if (holdsJson(p) || yoloLabelsFolder(p)) {
    out.push_back(p);
    return;
  }
  std::vector<fs::path> children;
  for (const auto& e : fs::directory_iterator(p, ec)) {
    if (e.is_directory(ec)) children.push_back(e.path());
  }
  std::sort(children.begin(), children.end());
  for (const auto& c : children) collect(c, depth + 1, out);
}

void fillFromTrial(TrialSummary& s, const KeypointTrial& t) {
  s.rateHz = t.rateHz;
  s.durationS = t.frameCount / t.rateHz;
  s.source = t.layout->name;
  for (int j = 0; j < kJointCount; ++j) {
    const auto name = std::string(jointName(static_cast<Joint>(j)));
    if (t.missing[static_cast<std::size_t>(j)]) s.modelEstimatedJoints.push_back(name);
    else if (t.derived[static_cast<std::size_t>(j)]) s.estimatedJoints.push_back(name);
  }
  s.warnings.push_back("layout " + t.layout->name + ": " + t.layoutSource);
  s.warnings.push_back(std::to_string(t.maxPeople) + (t.maxPeople == 1 ? " person" : " people at most") +
                       " per frame; following " + t.chosenReason);
  if (t.rateAssumed)
    s.warnings.push_back("frame rate assumed " + std::to_string(static_cast<int>(t.rateHz)) +
                         " fps (the file stores none): give the video's with --rate");
  for (const auto& w : t.warnings) s.warnings.push_back(w);
}

// The trial's joints and warnings, and its gait cycles in the image.
template <class Stage>
TrialSummary summarizeWalking(TrialSummary& s, const KeypointTrial& trial, Stage& stage) {
  fillFromTrial(s, trial);
  stage("walking", [&] {
    const ImageGait g = imageGaitCycles(trial);
    s.cycles = g.cycles;
    s.strideHz = g.strideHz;
    s.cycleMethod = g.inPlace ? "foot contacts (image), walking in place" : "foot contacts (image)";
    s.windowFrames = trial.frameCount;
  });
  return s;
}

}  // namespace

std::vector<fs::path> collectKeypointInputs(const std::vector<fs::path>& paths) {
  std::vector<fs::path> out;
  for (const auto& p : paths) collect(p, 0, out);
  return out;
}

namespace {

// Runs `step`; an error ends the summary at stage `name` (s.error, s.errorStage).
template <typename Step>
bool runStage(TrialSummary& s, const char* name, Step&& step) {
  try {
    step();
    return true;
  } catch (const Error& e) {
    s.error = e.what();
    s.errorStage = name;
  } catch (const std::exception& e) {
    s.error = s.file + ": " + e.what();
    s.errorStage = name;
  }
  return false;
}

}  // namespace

TrialSummary summarizeKeypoints(const fs::path& path, const KeypointOptions& options) {
  TrialSummary s;
  s.file = path.string();
  s.units = "px";
  const auto stage = [&](const char* name, auto&& step) { return runStage(s, name, step); };
  KeypointTrial trial;
  if (isPlanarTrc(path)) {
    if (!stage("read", [&] { trial = readPlanarTrc(path, options); })) return s;
    s.format = trial.format;
    s.frames = trial.frameCount;
    s.pointsFound = kJointCount;
    return summarizeWalking(s, trial, stage);
  }
  KeypointFrames frames;
  if (!stage("read", [&] { frames = readKeypointFrames(path, options.imageSize, options.videoSize()); })) return s;
  return summarizeKeypointFrames(frames, options);
}

TrialSummary summarizeKeypointFrames(const KeypointFrames& frames, const KeypointOptions& options) {
  TrialSummary s;
  s.file = frames.file;
  s.units = "px";
  const auto stage = [&](const char* name, auto&& step) { return runStage(s, name, step); };
  s.format = frames.format;
  s.frames = frames.frameCount();
  s.pointsFound = frames.pointCount;
  KeypointTrial trial;
  if (!stage("joints", [&] { trial = cleanKeypoints(frames, options); })) return s;
  return summarizeWalking(s, trial, stage);
}

}  // namespace ew
