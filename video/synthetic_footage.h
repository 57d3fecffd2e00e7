#pragma once
// Footage with known truth: a 15-joint walker filmed by a pinhole camera and painted as
// textured limbs over a textured background, written as a video file. The tracker's tests
// and benchmark film it and know where every joint is in every frame.

#include <Eigen/Core>
#include <filesystem>

namespace ew {

struct FootageCamera {
  Eigen::Matrix3d worldToCamera =
      Eigen::Matrix3d::Identity();  // rows: camera x (right), y (down), z (forward)
  Eigen::Vector3d centreMm = Eigen::Vector3d::Zero();
  double focalPx = 1000.0;
  int widthPx = 1280, heightPx = 720;
};

// A level camera `distanceMm` from the middle of the walk (the mean pelvis), at azimuth
// `azimuthDeg` from the walker's right (0: a side view from the right), 1.1 m high.
FootageCamera cameraBeside(const Eigen::Ref<const Eigen::MatrixXd>& framesMm, double azimuthDeg,
                           double distanceMm);

// T × 30: each joint's pixel (x right, y down) through the camera; NaN behind it.
Eigen::MatrixXd filmJoints(const Eigen::Ref<const Eigen::MatrixXd>& framesMm,
                           const FootageCamera& camera);

// Paints the frames (T × 45, mm, z up) and writes them to `file` (MJPG in AVI, `fps`). The
// limbs carry a noise texture in their own axes and a colour each (left and right told apart),
// drawn far to near, over a background of blurred noise fixed by `seed`. Error(Io) when the file
// cannot be written. Returns the joints' true pixels (filmJoints).
Eigen::MatrixXd writeFootage(const std::filesystem::path& file,
                             const Eigen::Ref<const Eigen::MatrixXd>& framesMm,
                             const FootageCamera& camera, double fps, unsigned seed = 7);

}  // namespace ew
