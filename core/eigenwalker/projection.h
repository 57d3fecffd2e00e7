#pragma once
// Orthographic projection at a horizontal view angle (METHOD §5; Zhang & Troje 2007, eq. 3.5).
//
// α in degrees: 0 = frontal, ±90 = profiles. For every block (p0, p1, q1, p2, q2) and joint:
//   u = x cos α + y sin α,   v = z,   depth d = −x sin α + y cos α.
// 3D Fourier vectors w have 225 values (block-major, joint, then x,y,z); 2D ones ŵ have 150
// (block-major, joint, then u,v); depth vectors have 75 (block-major, then joint).
// The projection acts on every (x,y,z) triple alike, so it is applied as a 2 × 3 rotation
// per triple; the dense 150 × 225 matrix C(α) is built only for tests and documentation.
// Every function throws Error(BadArgument) "projection: …" for a wrong row or column count
// or a non-finite α; NaN coordinates (missing samples) pass through as NaN on purpose.

#include <Eigen/Core>

namespace ew {

inline constexpr int kPointsPerWalker = 75;  // 5 blocks × 15 joints: one (x,y,z) triple each

double degToRad(double deg);

// C(α), 150 × 225. Not for hot paths.
Eigen::MatrixXd projectionMatrix(double alphaDeg);

// C(α) w for each column: 225 × n → 150 × n.
Eigen::MatrixXd projectToView(const Eigen::Ref<const Eigen::MatrixXd>& w, double alphaDeg);

// Depth of each triple: 225 × n → 75 × n.
Eigen::MatrixXd depthAtView(const Eigen::Ref<const Eigen::MatrixXd>& w, double alphaDeg);

// The inverse: 3D vectors from image coordinates (150 × n) and depths (75 × n) at α.
Eigen::MatrixXd composeFromView(const Eigen::Ref<const Eigen::MatrixXd>& uv,
                                const Eigen::Ref<const Eigen::MatrixXd>& depth, double alphaDeg);

// Frames (T × 45, joint-major x,y,z) → image frames (T × 30, joint-major u,v).
Eigen::MatrixXd projectFramesToView(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                    double alphaDeg);

// Frames (T × 45) → depth per joint (T × 15).
Eigen::MatrixXd depthFramesAtView(const Eigen::Ref<const Eigen::MatrixXd>& frames,
                                  double alphaDeg);

// Angle wrapped to (−180, 180]; NaN for a non-finite angle.
double wrapDeg(double deg);

}  // namespace ew
