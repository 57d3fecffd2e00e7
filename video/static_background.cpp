#include "video/static_background.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

namespace ew {
namespace {

// A camera that held still leaves most of the picture as it was; a person rarely fills more.
constexpr double kMaxForegroundShare = 0.25;
// The keyframe's skeleton must stand out from the background (the person moved away from where
// they were marked): points along its bones, nearly all of them. A walker crossing the picture
// scores 100 % (the synthetic footage, the sports2d demo); the balancing trial's cam01, whose
// man stands on one leg through most of it, 94 %.
constexpr double kMinSkeletonStandingOut = 0.97;
// Compression noise is a few grey levels; a limb against the background differs by more.
constexpr double kMinThresholdGrey = 10.0;
constexpr double kNoiseSigmas = 5.0;
// A still scene's frames differ from their median by compression noise alone (measured 3.0 grey
// levels on the sports2d demo, under 2 on cam01 and on MJPG); a panning camera's by far more.
constexpr double kMaxStillNoiseGrey = 6.0;
// A point along a keyframe's bone stands out when a foreground pixel lies this near it (marks
// are good to a few pixels).
constexpr int kPointRadiusPx = 3;

std::vector<int> sampledFrames(int first, int last, int samples) {
  const int count = last - first + 1;
  const int n = std::clamp(samples, 1, count);
  std::vector<int> frames;
  for (int k = 0; k < n; ++k) frames.push_back(n == 1 ? first : first + (count - 1) * k / (n - 1));
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  return frames;
}

// Each pixel's median over the frames (a loop over pixels: OpenCV's column sort took seconds on
// a 1080×1920 clip).
cv::Mat medianOf(const std::vector<cv::Mat>& greys) {
  cv::Mat median(greys.front().size(), CV_8U);
  std::vector<unsigned char> values(greys.size());
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  for (int y = 0; y < median.rows; ++y) {
    std::vector<const unsigned char*> rows;
    for (const cv::Mat& g : greys) rows.push_back(g.ptr<unsigned char>(y));
    unsigned char* out = median.ptr<unsigned char>(y);
    for (int x = 0; x < median.cols; ++x) {
      for (std::size_t k = 0; k < rows.size(); ++k) values[k] = rows[k][x];
      std::nth_element(values.begin(), middle, values.end());
      out[x] = *middle;
    }
  }
  return median;
}

double medianValue(const cv::Mat& m) {
  std::vector<unsigned char> v(m.begin<unsigned char>(), m.end<unsigned char>());
  auto middle = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), middle, v.end());
  return *middle;
}

cv::Mat foregroundMask(const cv::Mat& grey, const StaticBackground& b) {
  cv::Mat difference, mask;
  cv::absdiff(grey, b.grey, difference);
  cv::threshold(difference, mask, b.thresholdGrey, 255, cv::THRESH_BINARY);
  const cv::Mat square = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
  cv::morphologyEx(mask, mask, cv::MORPH_OPEN, square);  // lone noisy pixels out
  cv::dilate(mask, mask, square);
  return mask;
}

double foregroundShare(const cv::Mat& grey, const StaticBackground& b) {
  return cv::countNonZero(foregroundMask(grey, b)) / static_cast<double>(grey.total());
}

// The share of points along the key's marked bones with foreground within `radiusPx` of them:
// all of a walker who moved through the range; less of one who stood on a leg through most of it.
double skeletonStandingOut(const cv::Mat& keyGrey, const StaticBackground& b, const Keyframe& key,
                           int radiusPx) {
  const cv::Mat mask = foregroundMask(keyGrey, b);
  const auto foregroundNear = [&](double x, double y) {
    const cv::Rect around(static_cast<int>(std::lround(x)) - radiusPx,
                          static_cast<int>(std::lround(y)) - radiusPx, 2 * radiusPx + 1,
                          2 * radiusPx + 1);
    const cv::Rect inside = around & cv::Rect(0, 0, mask.cols, mask.rows);
    return inside.area() > 0 && cv::countNonZero(mask(inside)) > 0;
  };
  constexpr int kPointsPerBone = 8;
  int points = 0, out = 0;
  for (const auto& [from, to] : kBones) {
    const Eigen::Vector2d a = key.jointsPx.segment<2>(2 * index(from)),
                          c = key.jointsPx.segment<2>(2 * index(to));
    if (!a.allFinite() || !c.allFinite()) continue;
    for (int k = 0; k <= kPointsPerBone; ++k) {
      const Eigen::Vector2d p = a + (c - a) * (static_cast<double>(k) / kPointsPerBone);
      if (!(p.x() >= 0 && p.y() >= 0 && p.x() < mask.cols && p.y() < mask.rows))
        continue;  // out of the picture
      ++points;
      if (foregroundNear(p.x(), p.y())) ++out;
    }
  }
  return points ? static_cast<double>(out) / points : 0.0;
}

std::string percent(double share) {
  return std::to_string(static_cast<int>(std::lround(100.0 * share))) + " %";
}

}  // namespace

BackgroundCheck estimateStaticBackground(VideoSource& video, int first, int last,
                                         const Keyframe& key, std::size_t maxBytes, int samples) {
  const std::size_t frameBytes = std::max<std::size_t>(
      1, static_cast<std::size_t>(video.info().widthPx) * video.info().heightPx);
  samples = static_cast<int>(
      std::min<std::size_t>(static_cast<std::size_t>(samples), maxBytes / frameBytes));
  if (samples < 3)
    return {std::nullopt,
            "the frames are too large to sample for a background in the frame buffer"};
  std::vector<cv::Mat> greys;
  for (int f : sampledFrames(first, last, samples)) greys.push_back(toGrey(video.frame(f)));
  if (greys.size() < 3) return {std::nullopt, "too few frames for a background"};
  StaticBackground b;
  b.grey = medianOf(greys);
  b.fillGrey = static_cast<unsigned char>(medianValue(b.grey));
  std::vector<double> noise, shares;
  for (const cv::Mat& g : greys) {
    cv::Mat difference;
    cv::absdiff(g, b.grey, difference);
    noise.push_back(1.4826 * medianValue(difference));
  }
  std::nth_element(noise.begin(), noise.begin() + static_cast<std::ptrdiff_t>(noise.size() / 2),
                   noise.end());
  const double sigma = noise[noise.size() / 2];
  if (sigma > kMaxStillNoiseGrey)
    return {std::nullopt, "the camera moves (its frames differ from their median by " +
                              std::to_string(static_cast<int>(std::lround(sigma))) +
                              " grey levels)"};
  b.thresholdGrey = std::max(kMinThresholdGrey, kNoiseSigmas * sigma);
  for (const cv::Mat& g : greys) shares.push_back(foregroundShare(g, b));
  std::sort(shares.begin(), shares.end());
  const double share = shares[shares.size() / 2];
  if (share > kMaxForegroundShare)
    return {std::nullopt,
            "the camera moves (" + percent(share) + " of the picture differs from the median)"};
  const double standing =
      skeletonStandingOut(toGrey(video.frame(key.frame)), b, key, kPointRadiusPx);
  if (standing < kMinSkeletonStandingOut)
    return {std::nullopt, "the person stays in place (" + percent(standing) +
                              " of the keyframe's skeleton stands out from the median)"};
  return {b, ""};
}

cv::Mat withoutBackground(const cv::Mat& grey, const StaticBackground& b) {
  cv::Mat out(grey.size(), CV_8U, cv::Scalar(b.fillGrey));
  grey.copyTo(out, foregroundMask(grey, b));
  return out;
}

}  // namespace ew
