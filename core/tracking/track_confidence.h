#pragma once
// Where a track is least sure: the frames to look at first, and to mark again when the joints
// strayed there (the viewer's *Least sure frame*, `eigenwalker-cli track`'s report).

#include <Eigen/Core>
#include <vector>

namespace ew {

// Up to `count` frames, none of them in `keyframes`, in order of the track's mean confidence
// over the joints (lowest first), each at least `apart` frames from the ones before it (so
// that one bad stretch does not fill the list). `confidence`: frames × joints, rows from
// `firstFrame`.
std::vector<int> leastSureFrames(const Eigen::Ref<const Eigen::MatrixXd>& confidence, int firstFrame,
                                 const std::vector<int>& keyframes, int count, int apart);

}  // namespace ew
