#pragma once
// Writes 15-joint image positions as OpenPose BODY_25 JSON, one file a frame, the way a
// detector's output looks: BODY_25's own points from the joints (Neck at the sternum,
// MidHip at the pelvis), the face around the head and the feet around the ankles at
// offsets proportional to the person's height in the image. For experiments and tests
// that must go through the whole user path (docs/KEYPOINTS.md).

#include <Eigen/Core>
#include <filesystem>
#include <vector>

namespace ew {

struct OpenPosePerson {
  Eigen::MatrixXd jointsPx;    // T × 30 (u, v per joint, METHOD §1 order), NaN = not detected
  Eigen::MatrixXd confidence;  // T × 15 per joint (empty: 0.9 everywhere)
};

// Writes <folder>/clip_<frame>_keypoints.json for each frame (the folder is created); a
// person whose joints are NaN in a frame is left out of it. Error(Io) naming the file.
void writeOpenPoseBody25(const std::filesystem::path& folder, const std::vector<OpenPosePerson>& people);

}  // namespace ew
