#pragma once
// Ultralytics YOLO pose labels of a filmed walk, written the way Ultralytics writes them
// (results.save_txt: "%g"-style numbers, fractions of the image, a file per frame from 1,
// none where nobody was detected), for the reader's tests and the CLI's.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include "core/common/skeleton.h"
#include "core/keypoints/keypoint_frames.h"
#include "tests/camera/filmed_walk.h"
#include "tests/common/test_support.h"

namespace ew::test {

inline constexpr KeypointImageSize kImage{1920, 1080};

// COCO-17's points from 15 joint positions (u, v per joint): the face around the head (the
// ears' midpoint is the head, as the layout reads it back), the limbs at their joints.
inline Eigen::MatrixX2d coco17From(const Eigen::RowVectorXd& joints) {
  const auto at = [&](Joint j) { return Eigen::RowVector2d(joints(2 * index(j)), joints(2 * index(j) + 1)); };
  const Eigen::RowVector2d head = at(Joint::Head), side(12.0, 0.0), up(0.0, -6.0);
  Eigen::MatrixX2d p(17, 2);
  p.row(0) = head + 2 * up;                                          // nose
  p.row(1) = head + up - side / 2, p.row(2) = head + up + side / 2;  // eyes
  p.row(3) = head - side, p.row(4) = head + side;                    // ears
  const Joint limbs[12] = {Joint::LShoulder, Joint::RShoulder, Joint::LElbow, Joint::RElbow, Joint::LWrist, Joint::RWrist,
                           Joint::LHip,      Joint::RHip,      Joint::LKnee,  Joint::RKnee,  Joint::LAnkle, Joint::RAnkle};
  for (int i = 0; i < 12; ++i) p.row(5 + i) = at(limbs[i]);
  return p;
}

// One Ultralytics label line: class, box, then x y v per point as fractions, then `extra`.
inline std::string labelLine(const Eigen::MatrixX2d& px, const std::string& extra = "") {
  std::string line = "0 0.5 0.5 0.2 0.6";
  char buf[64];
  for (Eigen::Index i = 0; i < px.rows(); ++i) {
    std::snprintf(buf, sizeof buf, " %.9g %.9g %g", px(i, 0) / kImage.width, px(i, 1) / kImage.height, 0.93);
    line += buf;
  }
  return line + extra + "\n";
}

// The filmed walk of tests/camera/filmed_walk.h (the default model's mean walker crossing a
// 1400 px camera's view), 150 frames at 30 fps, with nobody detected in `empty` frames.
struct FilmedCoco {
  std::vector<Eigen::MatrixX2d> frames;
  std::vector<bool> seen;
};

inline FilmedCoco filmedCoco(const std::vector<int>& empty) {
  const Eigen::VectorXd t = frameTimes(150, 30.0);
  const Eigen::MatrixXd walk =
      synthesizeFrames(defaultRealModel().mean, 2 * std::numbers::pi * kFilmedStrideHz, 0.2, t);
  const Eigen::MatrixXd px = projectWalk(walk, t, crossingPinhole(1400, 5.0));
  FilmedCoco out;
  for (Eigen::Index f = 0; f < px.rows(); ++f) {
    out.frames.push_back(coco17From(px.row(f)));
    out.seen.push_back(std::find(empty.begin(), empty.end(), static_cast<int>(f)) == empty.end());
  }
  return out;
}

// As `yolo pose predict save_txt=True` writes a video "walk.mp4": labels/walk_<frame>.txt,
// frames from 1, no file where nobody was detected.
inline std::filesystem::path writeYoloRun(const FilmedCoco& clip, const std::string& stem) {
  const std::filesystem::path run = makeTempDir(stem);
  std::filesystem::create_directories(run / "labels");
  for (std::size_t f = 0; f < clip.frames.size(); ++f) {
    if (clip.seen[f]) std::ofstream(run / "labels" / ("walk_" + std::to_string(f + 1) + ".txt")) << labelLine(clip.frames[f]);
  }
  return run;
}

}  // namespace ew::test
