#pragma once
// Writes 15-joint image positions as OpenPose BODY_25 JSON, one file a frame, or as AlphaPose
// COCO-17 JSON, the way a detector's output looks: the layout's points from the joints
// (BODY_25's Neck at the sternum, MidHip at the pelvis), the face around the head and the feet
// around the ankles at offsets proportional to the person's height in the image. For
// experiments and tests that must go through the whole user path (docs/KEYPOINTS.md).

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

// The same people as AlphaPose writes them in COCO-17 (`file`, one JSON list: a detection per
// person a frame, image_id "<frame>.jpg"): COCO's points from the joints as above, so no
// neck (sternum) and no mid-hip point; the reader builds both from the shoulders and hips.
// Error(Io) naming the file.
void writeAlphaPoseCoco17(const std::filesystem::path& file, const std::vector<OpenPosePerson>& people);

}  // namespace ew
