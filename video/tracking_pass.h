#pragma once
// One pass of a tracker: from a keyframe's marks, frame after frame in one direction. The
// range tracker (video/joint_tracker.h) runs a pass forward and one backward from every
// keyframe and blends them; the passes are the optical-flow tracker's and Zou et al.'s
// appearance tracker's (video/appearance_tracker.h).

#include <array>
#include <opencv2/core.hpp>

#include "core/common/skeleton.h"

namespace ew {

class TrackingPass {
 public:
  virtual ~TrackingPass() = default;
  // Whether joint j is followed (marked on the keyframe and not yet out of the picture).
  virtual bool tracks(int j) const = 0;
  virtual cv::Point2f position(int j) const = 0;
  // Moves every followed joint onto `image`, video frame `frame` (the next frame in the pass's
  // direction, in the pass's image kind); a confidence per joint, 0-1.
  virtual std::array<double, kJointCount> advance(const cv::Mat& image, int frame) = 0;
};

}  // namespace ew
