#pragma once
// A walk filmed by a known camera, for the camera tests and bench/bench_camera.cpp: the
// default model's mean walker (stride 0.95 Hz) crossing 6 m from a pinhole 12° above, its
// keypoints written as OpenPose BODY_25 JSON the way a detector would place them
// (core/keypoints/openpose_writer.h: the sternum is the shoulders' midpoint once read back,
// not the model's sternum, so the reprojection is not exact).

#include <filesystem>
#include <numbers>

#include "core/camera/walk_camera.h"
#include "core/eigenwalker/default_model.h"
#include "core/eigenwalker/fourier.h"
#include "core/keypoints/openpose_writer.h"

namespace ew::test {

inline constexpr double kFilmedStrideHz = 0.95;

// Azimuth 40°, elevation 12°, 6 m to the look-at point at 0.9 m height, image centre
// (960, 540); the walker at 1.3 m/s passes the look-at point half-way through `clipS`.
inline WalkCamera crossingPinhole(double focalPx, double clipS) {
  WalkCamera c;
  c.model = CameraModel::Pinhole;
  c.alphaDeg = 40;
  c.elevationDeg = 12;
  c.focalPx = focalPx;
  c.distanceMm = 6000;
  c.cxPx = 960;
  c.cyPx = 540;
  c.lookAtHeightMm = 900;
  c.speedMmS = 1300;
  c.startOffsetMm = -1300 * clipS / 2;
  return c;
}

// The mean walker's `frames` frames at `fps` through `camera`, as an OpenPose folder.
inline void writeFilmedOpenPose(const std::filesystem::path& folder, const WalkCamera& camera, int frames,
                                double fps) {
  const Eigen::VectorXd t = frameTimes(frames, fps);
  const Eigen::MatrixXd walk = synthesizeFrames(defaultRealModel().mean, 2 * std::numbers::pi * kFilmedStrideHz, 0.2, t);
  writeOpenPoseBody25(folder, {{projectWalk(walk, t, camera), Eigen::MatrixXd()}});
}

}  // namespace ew::test
