#pragma once
// A 2D track drawn over its video frame: the 14 bones and a dot per joint, the dot's
// colour from the joint's confidence (blue sure, red lost), so that a user sees at a
// glance where the tracker holds and where it guessed.

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace ew {

struct OverlayStyle {
  cv::Scalar boneColour{255, 255, 255};  // BGR
  double lineWidthShare = 1.0 / 250.0;   // of the frame's larger side
  bool confidenceColours = true;         // else every dot in boneColour
};

// `jointsPx`: 30 (x, y per joint, NaN = missing); `confidence`: 15 (0-1) or empty.
void drawTrack(cv::Mat& bgr, const Eigen::Ref<const Eigen::RowVectorXd>& jointsPx,
               const Eigen::Ref<const Eigen::RowVectorXd>& confidence,
               const OverlayStyle& style = {});

}  // namespace ew
