#include "video/track_overlay.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/skeleton.h"
#include "video/confidence_colour.h"

namespace ew {
namespace {

bool seen(const Eigen::Ref<const Eigen::RowVectorXd>& p, int j) {
  return !std::isnan(p(2 * j)) && !std::isnan(p(2 * j + 1));
}

cv::Point at(const Eigen::Ref<const Eigen::RowVectorXd>& p, int j) {
  return {static_cast<int>(std::lround(p(2 * j))), static_cast<int>(std::lround(p(2 * j + 1)))};
}

// Red (lost) to blue (sure), BGR: the viewer's ramp (video/confidence_colour.h).
cv::Scalar confidenceColour(double c) {
  const ConfidenceRgb rgb = confidenceRgb(c);
  return {255.0 * rgb.b, 255.0 * rgb.g, 255.0 * rgb.r};
}

}  // namespace

void drawTrack(cv::Mat& bgr, const Eigen::Ref<const Eigen::RowVectorXd>& jointsPx,
               const Eigen::Ref<const Eigen::RowVectorXd>& confidence, const OverlayStyle& style) {
  const int width = std::max(
      1, static_cast<int>(std::lround(std::max(bgr.cols, bgr.rows) * style.lineWidthShare)));
  for (const auto& [a, b] : kBones) {
    if (!seen(jointsPx, index(a)) || !seen(jointsPx, index(b))) continue;
    cv::line(bgr, at(jointsPx, index(a)), at(jointsPx, index(b)), style.boneColour, width,
             cv::LINE_AA);
  }
  for (int j = 0; j < kJointCount; ++j) {
    if (!seen(jointsPx, j)) continue;
    const bool coloured = style.confidenceColours && confidence.size() == kJointCount;
    const cv::Scalar colour = coloured ? confidenceColour(confidence(j)) : style.boneColour;
    cv::circle(bgr, at(jointsPx, j), 2 * width, colour, cv::FILLED, cv::LINE_AA);
    cv::circle(bgr, at(jointsPx, j), 2 * width, cv::Scalar(0, 0, 0), std::max(1, width / 2),
               cv::LINE_AA);
  }
}

}  // namespace ew
