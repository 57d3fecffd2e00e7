#pragma once
// Where a track is least sure: the frames to look at first, and to mark again when the joints
// strayed there (the viewer's *Least sure frame*, `eigenwalker-cli track`'s report).

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

}  // namespace ew
