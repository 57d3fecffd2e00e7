#pragma once
// What a pose estimator's keypoints do not store, when the user gave none: the image size and
// frame rate of the video they were made from, found beside them (video/video_beside.h).

#include <filesystem>

#include "core/keypoints/keypoint_trial.h"

namespace ew::cli {

// Sets k.video to the video beside `keypoints` when such a video opens (its size and rate
// then stand in for what neither the options nor the file give: KeypointOptions::video) and
// says so on stderr. Without the video library (a build without OpenCV) none is looked for.
void takeTheVideoBeside(const std::filesystem::path& keypoints, KeypointOptions& k);

}  // namespace ew::cli
