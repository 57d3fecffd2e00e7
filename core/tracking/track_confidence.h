#pragma once
// Where a track is least sure, and where to mark next: the frames to look at first, and the
// frame whose marks would help the track most (the viewer's *Least sure frame* and *Mark next*,
// `eigenwalker-cli track`'s report).

#include <Eigen/Core>
#include <vector>

namespace ew {

// Up to `count` frames, none of them in `keyframes`, in order of the track's mean confidence
// over the joints (lowest first; the earlier frame of two equal), each at least `apart` frames
// from the ones before it (so that one bad stretch does not fill the list).
// `meanConfidence`: one value a frame (a JointTrack's confidence, row means), from `firstFrame`.
// A pass over the frames per frame chosen: the viewer asks every drawn frame.
std::vector<int> leastSureFrames(const Eigen::Ref<const Eigen::VectorXd>& meanConfidence, int firstFrame,
                                 std::vector<int> keyframes, int count, int apart);

// How far the joints have moved by each frame of a track: the mean over the joints seen in
// both frames of their displacement from the frame before, summed from the first frame (px).
// `trackPx`: frames × 30 (u, v a joint; NaN = missing).
Eigen::VectorXd cumulativeMotionPx(const Eigen::Ref<const Eigen::MatrixXd>& trackPx);

// Up to `count` frames to mark next, the best first, none in `keyframes`. A frame-to-frame
// tracker drifts with the motion it follows, not with the time it has tracked (a man standing
// still for a second drifts nowhere; a lunge of a few frames can lose an arm). So each frame's
// distance from its nearest keyframe is measured in `cumulativeMotionPx`, and the frame chosen
// is the one that, made a keyframe, leaves the least of that distance summed over the track;
// each next frame is chosen with the ones before it counted as keyframes. Keyframes outside
// the track are ignored; without one in it, every frame counts its distance from the new one.
// O(frames · log frames) a frame chosen.
std::vector<int> framesToMarkNext(const Eigen::Ref<const Eigen::MatrixXd>& trackPx, int firstFrame,
                                  const std::vector<int>& keyframes, int count);

// The same from a track's `cumulativeMotionPx`, kept by a caller that asks again and again
// (the viewer, every drawn frame, with the keyframes as they are now).
std::vector<int> framesToMarkNextAlong(const Eigen::VectorXd& cumulativeMotion, int firstFrame,
                                       const std::vector<int>& keyframes, int count);

}  // namespace ew
