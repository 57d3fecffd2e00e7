#pragma once
// Zou et al.'s tracker (2009, §3.2, §4.2, §5.2–5.3): the body as rectangles around its
// segments, each with the colour histogram it had on the marked frame. Frame by frame, the
// root joint is found by template matching (the patch around it on the marked frame); then,
// depth-first down the tree, each child joint is sought in the square A around where the
// segment would be had it kept last frame's angle to its parent (eq. 18: half-side
// h = 1.5 × the joint's last move), and placed where the rectangle from its parent to the
// candidate holds the colours most like the marked frame's (Bhattacharyya distance, eq. 16;
// eq. 17). The 2D rectangle from the parent to the candidate is what eq. 14–15 project for
// the candidate's Euler angles: a segment turned in depth is shorter in the image, not
// narrower.
//
// Beyond the paper, said where it is done: the half-side h has a floor (the paper's h is 0
// for a joint that stood still for a frame, and would freeze it), and a joint whose parent
// is not marked is found by template matching like the root.

#include <array>
#include <memory>
#include <opencv2/core.hpp>

#include "core/tracking/keyframes.h"
#include "video/segment_search.h"
#include "video/tracking_pass.h"

namespace ew {

// 8 levels per colour channel (B, G, R): 512 bins, summing to 1 (all zero when empty).
inline constexpr int kColourLevels = 8;
using ColourHistogram = std::array<float, kColourLevels * kColourLevels * kColourLevels>;

// The colours of the rectangle around a segment (its bone from `parent` to `child`,
// reaching `bone.beyondShare` past the child, `bone.halfWidthShare` × the person's height
// to either side), sampled on a grid in the segment's axes in an 8-bit BGR image. Empty when
// fewer than half the samples fall in the image or the segment is under a pixel long.
ColourHistogram segmentHistogram(const cv::Mat& bgr, cv::Point2f parent, cv::Point2f child,
                                 const SearchBone& bone, double personPx);

// Eq. 16: sqrt(1 − Σ sqrt(H1·H2)), 0 for the same colours, 1 for none in common or an
// empty histogram.
double bhattacharyyaDistance(const ColourHistogram& a, const ColourHistogram& b);

struct AppearanceOptions {
  double personPx = 300.0;           // the person's height in the image (head to ankles)
  double rootPatchShare = 0.12;      // the root's template, share of the person's height
  double minSearchShare = 0.02;      // h's floor, share of the person's height
  double maxSearchShare = 0.12;      // h's ceiling
};

// A pass of the appearance tracker from one keyframe (video/tracking_pass.h); images are
// 8-bit BGR frames.
std::unique_ptr<TrackingPass> makeAppearancePass(const Keyframe& key, const cv::Mat& keyBgr,
                                                 const AppearanceOptions& options);

}  // namespace ew
