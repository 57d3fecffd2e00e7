#pragma once
// The classroom stage (issue 56): the classic displays of biological motion
// (core/teaching/biological_motion.h) drawn in both views over the walker each view already
// shows (the 2D view: the measured walker in reconstruct mode, the synthesised one in explore
// mode; the 3D view: the reconstruction, or the synthesised walker), the depth-reversed
// walker beside the true one, and the turning stage. A clip or a video is not a Fourier
// walker: the stage leaves the clip view as it is.
//
// Everything here is a pure function of the settings, the walker and the playback's time, so
// a script, a test and the audience window see the same dots.

#include <Eigen/Core>
#include <optional>
#include <string>

#include "core/teaching/biological_motion.h"

namespace ew::ui {

inline constexpr double kStageMaxTurnDegPerS = 180.0;
inline constexpr double kStageMaxElevationDeg = 60.0;
// How far beside the true walker the depth-reversed one stands in 3D: along the 2D view's
// depth axis, so that both still project to the same image.
inline constexpr double kDepthReversedApartMm = 1100.0;
// Overground walkers walk across this span and come back in at its other end (mm).
inline constexpr double kStageWrapMm = 5000.0;
inline constexpr int kDefaultMaskDots = 100;

struct StageFeature {
  BiologicalMotionOptions display;  // `translating` is applied here, wrapped (stageDots)
  bool depthReversed = false;       // the depth-reversed walker beside (3D) and over (2D) the true one
  bool turning = false;             // the view's azimuth turning at turnDegPerS
  double turnDegPerS = 30.0;
  double turnedDeg = 0.0;           // how far it has turned, in (−180, 180]
  double elevationDeg = 0.0;        // the 2D view's elevation (> 0 looks down)
  int maskSlider = kDefaultMaskDots;  // the N the mask key and checkbox switch on

  // Whether the views draw the stage rather than their usual figures.
  bool shown() const;
};

// What one view shows of the stage at one moment.
struct StageDots {
  Eigen::Matrix3Xd walker;           // the display's walker dots (15 joints, or the lifetime dots)
  Eigen::Matrix3Xd noise;            // the mask's dots
  bool keepsForm = true;             // 15 joints in their places: bones may be drawn between them
  std::optional<Eigen::Matrix3Xd> reversed;  // the depth-reversed walker's dots (not moved aside)
};

// The stage's display of walker w (225) walking at strideHz, at playback time `cycles` (gait
// cycles since the start; the viewer's phase is its fraction), at `speedMmS` when it walks
// overground; the depth reversal at view `alphaDeg`. Throws ew::Error for a walker the
// display refuses (core/teaching/biological_motion.h).
StageDots stageDots(const StageFeature& stage, const Eigen::VectorXd& w, double strideHz, double cycles,
                    double speedMmS, double alphaDeg);

// Orthographic projection at azimuth α and elevation ε (METHOD §5, docs/CAMERA.md; the HTML
// walker's): u = x cos α + y sin α, v = z cos ε + d sin ε with d = −x sin α + y cos α.
Eigen::Matrix2Xd stageProjection(const Eigen::Matrix3Xd& pointsMm, double azimuthDeg, double elevationDeg);

// The 3D offset that puts the depth-reversed walker beside the true one at view α (along the
// depth axis, which the projection at α does not see).
Eigen::Vector3d depthReversedOffset(double alphaDeg);

// The turning stage's angle after `seconds` (wrapped into (−180, 180]).
double turnedAfter(const StageFeature& stage, double seconds);

// What the stage shows, in words: "inverted · phase-scrambled · 100 noise dots", or "" when
// it shows the walker plainly.
std::string stageDescription(const StageFeature& stage);

const char* scrambleName(Scramble s);  // "none", "phase", "position"
Scramble scrambleFromName(const std::string& name);  // throws std::invalid_argument

}  // namespace ew::ui
