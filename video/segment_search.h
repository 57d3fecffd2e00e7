#pragma once
// Each joint placed where its body segment looks as it did on the keyframe (after Zou et
// al. 2009 §5.2–5.3, who model the body as rectangles around the segments and search
// joint positions depth-first down the tree). A segment's look is its rectangle resampled
// into a fixed strip in the segment's own axes (along the bone × across it), so a limb that
// turned or swung still lines up with its keyframe strip; strips are compared by normalised
// cross-correlation. Starting at the pelvis, each child joint is sought in a square around
// its predicted position (from the optical flow or the motion filter), its parent already
// placed. The strip holds the limb and not the background beside it, which the optical
// flow of a thin limb's joint window cannot avoid.

#include <array>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>

#include "core/common/skeleton.h"

namespace ew {

// A point not placed (a joint not tracked or not found).
inline constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
inline bool valid(cv::Point2f p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Parent → child in search order (depth-first from the pelvis). (Not core's TreeBone of
// skeleton_tree.h: two classes of one name in one program break the one-definition rule —
// measured: the sanitized CLI indexed one's array with the other's stride.)
struct SearchBone {
  Joint parent, child;
  double halfWidthShare;  // the segment's half-width, share of the person's height
  double beyondShare;  // how far the strip reaches past the child (hand, foot, head), share of the
                       // bone
};
extern const std::array<SearchBone, kBones.size()> kSearchTree;

// A segment's look: its strip, zero mean and unit norm (empty when off the frame or degenerate).
using SegmentStrip = cv::Mat;  // CV_32F, kStripAlong × kStripAcross

SegmentStrip segmentStrip(const cv::Mat& grey, cv::Point2f parent, cv::Point2f child,
                          const SearchBone& bone, double personPx);

// Normalised cross-correlation of two strips (−1-1); −1 when either is empty.
double stripMatch(const SegmentStrip& a, const SegmentStrip& b);

struct SegmentSearchOptions {
  double personPx = 300.0;
  double radiusPx = 20.0;  // the square the pelvis is sought in (the others: a sector)
};

// Default: nothing found (every joint NaN, every match −1).
struct SearchResult {
  SearchResult();
  std::array<cv::Point2f, kJointCount> at;  // NaN where not searched
  // The strip's match at the answer (the pelvis: the trunk's).
  std::array<double, kJointCount> match;
};

// `predicted`: each joint's predicted position in `grey` (NaN: not tracked); `strips`: the
// keyframe's strip per search-tree bone (empty: that bone is not tracked).
SearchResult searchSegments(const cv::Mat& grey,
                            const std::array<cv::Point2f, kJointCount>& predicted,
                            const std::array<SegmentStrip, kBones.size()>& strips,
                            const SegmentSearchOptions& options);

}  // namespace ew
