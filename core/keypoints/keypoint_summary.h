#pragma once
// What `info` shows for a keypoint file or folder (core/gait/trial_summary.h's fields):
// format, frames, rate (assumed when the file has none), "px" as the unit, points per
// person and the layout with how it was decided, people, joints derived or never seen,
// and the gait cycles found in the image (image_gait.h). Stages: "read", "joints"
// (cleaning), "walking".

#include <filesystem>

#include "core/gait/trial_summary.h"
#include "core/keypoints/keypoint_trial.h"

namespace ew {

TrialSummary summarizeKeypoints(const std::filesystem::path& path, const KeypointOptions& options = {});

// The same for a clip already read (the built-in detector's, from a video).
TrialSummary summarizeKeypointFrames(const KeypointFrames& frames, const KeypointOptions& options = {});

// Keypoint inputs under `paths`: .json files, folders holding .json files directly (an
// OpenPose folder), YOLO pose labels (a folder of them, or Ultralytics' run folder holding
// labels/); other folders are searched below, sorted, to a depth of 8.
std::vector<std::filesystem::path> collectKeypointInputs(const std::vector<std::filesystem::path>& paths);

}  // namespace ew
