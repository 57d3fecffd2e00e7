#pragma once
// The still background of footage from a fixed camera, and frames with it taken out. A thin
// limb fills little of the flow's window around its joint: the rest is background, which
// does not move, and pulls the joint's flow towards standing still (measured on the synthetic
// footage and the sports2d demo: docs/TRACKING_DESIGN.md, "The still background"). With the
// background flattened to one grey, only the person's own texture and outline move the flow.
//
// The background is each pixel's median over frames spread through the tracked range. It is
// trusted only when the camera held still (most pixels agree with it on every sampled frame)
// and the person moved through the range (the keyframe's joints stand out from it): a person
// who stays in place becomes part of the median, and would be flattened away.

#include <cstddef>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "core/common/skeleton.h"
#include "core/tracking/keyframes.h"
#include "video/video_source.h"

namespace ew {

struct StaticBackground {
  cv::Mat grey;                  // CV_8U, each pixel's median over the sampled frames
  double thresholdGrey = 0;      // a pixel further than this from the background is foreground
  unsigned char fillGrey = 128;  // what background pixels become (the background's median)
};

struct BackgroundCheck {
  std::optional<StaticBackground> background;
  std::string why;  // when there is none: the reason, for the track's report
};

// Samples up to `samples` frames evenly over [first, last] (grey; no more than fit in
// `maxBytes`, the tracker's frame buffer) and checks the two conditions above against `key` (the
// first keyframe's marks, on its own frame).
BackgroundCheck estimateStaticBackground(VideoSource& video, int first, int last,
                                         const Keyframe& key,
                                         std::size_t maxBytes = std::size_t{512} << 20,
                                         int samples = 15);

// `grey` with every pixel near the background set to its fill grey (foreground kept as is,
// its outline grown by a pixel so the person's edge stays whole).
cv::Mat withoutBackground(const cv::Mat& grey, const StaticBackground& background);

}  // namespace ew
