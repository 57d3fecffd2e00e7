#include "video/track_overlay.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "core/common/skeleton.h"

namespace ew {
namespace {

bool seen(const Eigen::Ref<const Eigen::RowVectorXd>& p, int j) {
  return !std::isnan(p(2 * j)) && !std::isnan(p(2 * j + 1));
}

cv::Point at(const Eigen::Ref<const Eigen::RowVectorXd>& p, int j) {
  return {static_cast<int>(std::lround(p(2 * j))), static_cast<int>(std::lround(p(2 * j + 1)))};
}

// Red (lost) to blue (sure), BGR: the viewer's palette::confidenceColour
// (ui/render/palette.h, whose order the colour deficiencies keep; tests/ui/test_colour_vision.cpp
// checks that the two agree).
cv::Scalar confidenceColour(double c) {
  c = std::clamp(c, 0.0, 1.0);
  const auto mix = [c](double lost, double sure) { return 255.0 * (lost + (sure - lost) * c); };
  return {mix(0.02, 0.98), mix(0.12, 0.51), mix(0.86, 0.34)};
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
