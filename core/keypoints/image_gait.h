#pragma once
// Gait cycles of a walker seen in an image (pixels), before any 3D: the walker's progression
// across the image gives the walking direction d (a 2D unit vector; for a walker coming
// towards the camera it points down the image); each ankle's lead (ankle − pelvis)·d peaks
// at its foot strikes (Zeni et al. 2008, as core/gait/gait_cycles.h does in 3D), and the
// strikes give the stride frequency.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "core/keypoints/keypoint_trial.h"

namespace ew {

// The pelvis crosses at least this share of the walker's height in the image when it walks across it.
inline constexpr double kMinImageTravelOfHeight = 0.5;
// A walker that does not cross the picture walks towards or away from the camera when its
// size in the image changes by more than this share from the clip's start to its end, else in
// place (a treadmill). 10 %: 1.3 m/s for 2 s at 25 m from the camera, the farthest a
// single camera films a walker this project reads.
inline constexpr double kMaxInPlaceSizeChange = 0.10;
// Each ankle's lead must span this share of the walker's height (150 mm of ~1.7 m).
inline constexpr double kMinImageAnkleLeadOfHeight = 0.08;
// … and this share for a walker that does not cross the picture: seen from the front or behind
// the feet swing in depth and show mostly as their lift (the shared walkers on the spot, filmed
// from behind: 0.07–0.08 of their height; a person standing: 0.00).
inline constexpr double kMinImageAnkleLeadInPlaceOfHeight = 0.05;

// The shortest clip read as walking, in gait cycles at the stride frequency found: a person
// sees a walker in a stride and a bit, and one step's strikes misread the stride by a tenth.
inline constexpr double kMinImageCycles = 0.8;

struct ImageGait {
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // progression in the image, unit
  double travelPx = 0.0;                                // pelvis, first to last tenth
  // Walking in place (a treadmill): the pelvis does not cross the picture nor does the walker
  // grow or shrink in it (kMaxInPlaceSizeChange). Whenever the pelvis does not cross the
  // picture (also walking towards or away from the camera), the direction is the ankles'
  // swing about the pelvis, forward the way they move the shorter part of the time (a swing
  // is quicker than a stance).
  bool inPlace = false;
  std::vector<double> rightStrikesS, leftStrikesS;      // seconds from frame 0
  double strideHz = 0.0;
  double strikesStrideHz = 0.0;  // what the strikes alone read (0: none), held stride or not
  double cycles = 0.0;           // clip duration × stride frequency
};

// Throws Error(BadData) naming the file with "not walking: …" when an ankle does not swing
// about the pelvis (whether the pelvis crosses the image or not), or the strikes give no
// stride frequency in kMinStrideHz-kMaxStrideHz, and "shorter than a gait cycle" below
// kMinImageCycles. The strikes read the frequency from each foot's strikes; in a clip shorter
// than 2.5 strides of a walker who travels (a person balancing on the spot moves a foot once
// or twice) also from
// the step between one strike a side, or from the ankles' leads' opposed swing (a sinusoid
// over strides of 0.5-1.6 Hz explaining at least half of it).
// `heldStrideHz`: the stride frequency known otherwise (the trunk's bob, below), which then
// stands for the strikes' (a tracker's lost ankles may strike irregularly or not at all).
ImageGait imageGaitCycles(const KeypointTrial& trial,
                          std::optional<double> heldStrideHz = std::nullopt);

// The stride frequency from the trunk's bob: the head, the sternum and the shoulders rise and
// fall twice a stride (once a step), in any view (the pelvis and hips too, but a tracker's
// slip under the thigh tops once a stride; docs/TRACKING_DESIGN.md). The vertical image paths of
// those seen in at least 60 % of the frames, each detrended by a parabola in time (a walker
// nearing the camera sinks along a curve), are fitted with a sinusoid over
// step frequencies 1.0 … 3.2 Hz (strides of 0.5 … 1.6 Hz, 0.005 Hz apart); the frequency whose
// fit takes the largest share of their summed variance among the band's inner peaks (not its
// edges), halved. Unset when fewer than two such joints, no inner peak, the clip is shorter
// than two steps at that frequency, or the best fit takes less than `minShare` of the variance
// (no clear bob). For a joint tracker's output, whose trunk holds
// where the feet are lost (docs/TRACKING_DESIGN.md, "The model loop").
std::optional<double> trunkBobStrideHz(const KeypointTrial& trial, double minShare = 0.3);

// The least-squares line p0 + p1 t through the finite samples of x (t: the same length).
Eigen::Vector2d lineThroughFinite(const Eigen::VectorXd& x, const Eigen::VectorXd& t);

// The walker's head-to-ankles height in each frame (px; the head stood in for by the sternum
// raised by the model's usual ratio where unseen), NaN where unknown. jointsPx: T × 30.
Eigen::VectorXd imageHeightsPx(const Eigen::MatrixXd& jointsPx);

// The walker's depth along the clip, up to scale: a pinhole images a walker at depth Z(t) at a
// height ∝ 1/Z(t), and a straight walk at a steady speed has Z linear in t, so the line
// p0 + p1 t through the inverse heights (1/px) is Z(t) / (f · the walker's height). nullopt with
// fewer than 8 heights or a line that does not stay positive over the clip (heights too noisy
// to tell). A walker leaving the camera from a metre to ten shrinks tenfold: a line through
// the heights themselves crosses zero there.
std::optional<Eigen::Vector2d> imageDepthLine(const Eigen::MatrixXd& jointsPx, const Eigen::VectorXd& timesS);

}  // namespace ew
