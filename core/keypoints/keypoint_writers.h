#pragma once
// Keypoint clips written in the formats other tools read (the built-in detector's output,
// `eigenwalker-cli detect`): MediaPipe Pose CSV and OpenPose JSON, whatever the layout.
// Both read back through this project's own readers to the same points (tests).
#include <filesystem>
#include <string>
#include <vector>

#include "core/keypoints/keypoint_frames.h"

namespace ew {

// One person's points as a MediaPipe Pose CSV: "# image_size=WxH", then the header
// frame,time_s,<name>_x,<name>_y,<name>_visibility,… and a row per frame of `frames`, x and y
// as fractions of the image (what parseMediaPipeCsv reads). `person` picks the detection
// with that trackId on each frame; a frame without it is a row with empty cells.
// Error(BadArgument) without an image size or for names that do not match the points.
void writeMediaPipeCsv(const std::filesystem::path& file, const KeypointFrames& frames, int person,
                       const std::vector<std::string>& pointNames);

// Everybody as OpenPose JSON, one file a frame (<folder>/<stem>_<frame, 12 digits>_keypoints.json),
// each person with its trackId as person_id and pose_keypoints_2d (x, y, confidence per point;
// a missing point 0, 0, 0 as OpenPose writes it). The folder is written whole or not at all.
void writeOpenPoseJson(const std::filesystem::path& folder, const std::string& stem, const KeypointFrames& frames);

}  // namespace ew
