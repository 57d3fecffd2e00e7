#pragma once
// Which joints a walker's own body hides from the camera: a 3D walker seen through a fitted
// camera, its segments as capsules (a trunk, limbs, the girdles), and a joint hidden where a
// segment nearer the camera covers its image. A tracker cannot see such a joint (the far
// shoulder behind the trunk, the pelvis under the near thigh's top): its patch shows the
// segment in front and moves with it. The model loop (video/model_loop.h) places such joints
// where the walk puts them instead.

#include <Eigen/Core>

#include "core/camera/walk_camera.h"

namespace ew {

// framesMm: T × 45 canonical frames, timesS: T, the camera the walk was fitted through.
// Returns T × 15: 1 where the joint is hidden at that frame, else 0.
Eigen::MatrixXd hiddenJoints(const Eigen::Ref<const Eigen::MatrixXd>& framesMm,
                             const Eigen::Ref<const Eigen::VectorXd>& timesS,
                             const WalkCamera& camera);

}  // namespace ew
