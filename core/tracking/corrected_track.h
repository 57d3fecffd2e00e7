#pragma once
// A detector's track corrected by hand (issue 52: "marking and tracking become correction").
// The user moves a joint on a frame where the detector was wrong; the correction is a keyframe
// (core/tracking/keyframes.h). A detector's errors last a few frames (a leg labelled as the
// other one, a wrist lost against the trunk), so the track is redone around it: the joint's
// offset from the detection at the correction is carried to the frames around it with a weight
// falling linearly to zero over `spanFrames`, and between two corrections of the same joint
// nearer than that the offsets are interpolated. Outside every correction's span the detection
// stands; on a corrected frame the correction does.
#include <Eigen/Core>

#include "core/keypoints/keypoint_trial.h"
#include "core/tracking/keyframes.h"

namespace ew {

// `detectedPx`: T × 30 (frames × u, v per joint, NaN = missing). A corrected joint the
// detection lacks on its frame is the mark there and nowhere else. Keyframes beyond the track
// are ignored. Error(BadArgument) for a span under 0 or a track that is not T × 30.
Eigen::MatrixXd correctTrack(const Eigen::Ref<const Eigen::MatrixXd>& detectedPx, const Keyframes& corrections,
                             int spanFrames);

// How far a correction reaches either side of its frame: a detector's errors last a few
// frames (a swapped leg, a wrist lost against the trunk).
inline constexpr double kCorrectionSpanS = 0.25;

// A pose estimator's trial (frames numbered as its video's) corrected by hand, as
// `reconstruct --corrections` and the viewer do it: correctTrack over its 15 joints with a
// span of kCorrectionSpanS at its rate, and each corrected joint as sure as can be there
// (jointConfidence 1). Returns the span in frames. Throws what correctTrack throws.
int correctTrial(KeypointTrial& trial, const Keyframes& corrections);

}  // namespace ew
