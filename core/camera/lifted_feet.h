#pragma once
// The image's heels and toes lifted into the reconstruction's 3D frames. The 15-joint walker
// has no feet, but a detector's clip often does (BODY_25's heels and big toes, MediaPipe's heel
// and foot index: KeypointTrial::feetPx). Each foot point lies on its pixel's ray through the
// fitted camera; where along the ray is what one view does not say. We put it in the vertical
// plane through its own ankle along the walking direction (the canonical frame's x = the
// reconstructed ankle's x): a foot points forward, give or take its toe-out, and the plane is
// where a sagittal gait analysis measures the foot (Stenum et al. 2021). That is exact in
// profile and degrades as the ray turns into the plane: a point δ mm off the plane lands
// δ·cot θ mm off along the walk, θ the ray's angle to the plane. Rays within kMinRayToPlaneDeg
// of the plane (views from the front or the back) are not lifted.
//
// What the lift keeps: each foot's forward and vertical motion — the heel strikes and the toe
// offs (core/gait/gait_events.h gaitEventsFromFeet) and the sagittal ankle angle. What it
// cannot keep: the foot's turn out of the plane, so a lifted foot has no foot progression angle
// (it reads 0 by construction; reports leave it out).

#include <Eigen/Core>
#include <string>

#include "core/camera/walk_camera.h"

namespace ew {

// The ray must meet the ankle's sagittal plane at least this steeply: the same bound as a
// camera fit's end-on views (kEndOnViewDeg), which puts the forward error of a point 2 cm off
// the plane (a toe turned out 7°) at most 3.5 cm.
inline constexpr double kMinRayToPlaneDeg = 30.0;
// A lifted point further than this from its ankle is not that foot's (a detector glitch, a
// bystander's foot, the feet's labels swapped in a frame): the heel is 5–10 cm from the ankle
// centre and the toe 15–22 cm in adult feet; 400 mm leaves room for a ray's error.
inline constexpr double kMaxFootPointFromAnkleMm = 400.0;

struct LiftedFeet {
  // T × 12 (FootPoint order, x y z), the reconstruction's canonical frame (progression removed),
  // mm; NaN where the image has no point or the point could not be lifted. Empty (0 × 0) when
  // nothing was lifted.
  Eigen::MatrixXd feetMm;
  int pointsSeen = 0;       // foot samples (point × frame) the image has
  int pointsLifted = 0;     // of those, put in 3D
  int pointsEndOn = 0;      // not lifted: the ray too close to the plane
  int pointsFarFromAnkle = 0;  // not lifted: further than kMaxFootPointFromAnkleMm
  std::string note;         // one sentence for reports: what was lifted, or why nothing
};

// feetPx: T × 8 (u, v per FootPoint, pixels, y down; NaN unseen) in the image the camera was
// fitted to (undistorted as the joints were); framesMm: T × 45 the reconstruction at timesS (T).
// Empty feetPx (a layout without feet) gives empty feet and says so.
LiftedFeet liftFeetOntoSagittalPlanes(const Eigen::MatrixXd& feetPx, const Eigen::MatrixXd& framesMm,
                                      const Eigen::VectorXd& timesS, const WalkCamera& camera);

// The foot points' pixels through the camera (T × 12 → T × 8; NaN in, NaN out): the lift's
// inverse, for checks and overlays.
Eigen::MatrixXd projectFootPoints(const Eigen::MatrixXd& feetMm, const Eigen::VectorXd& timesS,
                                  const WalkCamera& camera);

}  // namespace ew
