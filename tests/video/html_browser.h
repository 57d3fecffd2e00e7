#pragma once
// Headless Chromium for the tests that open the HTML walker (core/teaching/html_walker.h) in a
// real browser: the page screenshotted at 800 × 600, held at a frame by its #t= address, and
// the dots found in the PNG. Header-only; the including test links OpenCV.

#include <chrono>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "core/teaching/html_walker.h"
#include "tests/common/test_support.h"

namespace ew::test {

inline constexpr int kBrowserWidth = 800, kBrowserHeight = 600;

inline cv::Vec3d rgbOf(const std::string& hex) {
  const auto channel = [&](int i) {
    return static_cast<double>(std::stoi(hex.substr(1 + 2 * i, 2), nullptr, 16));
  };
  return {channel(0), channel(1), channel(2)};
}

// The page at `timeS` as Chromium draws it: the screenshot (BGR), and how long it took.
struct Screenshot {
  cv::Mat image;
  double seconds = 0.0;
  std::string log;
};

inline Screenshot screenshot(const std::filesystem::path& page, double timeS,
                      const std::filesystem::path& dir) {
  const auto png = dir / (page.stem().string() + ".png");
  const auto start = std::chrono::steady_clock::now();
  const test::ProgramRun run = test::runProgram(
      test::findProgram("timeout").string(),
      {"60", test::headlessChromium().string(), "--headless", "--no-sandbox", "--disable-gpu",
       "--hide-scrollbars", "--force-device-scale-factor=1", "--no-first-run",
       "--user-data-dir=" + (dir / "profile").string(), "--screenshot=" + png.string(),
       "--window-size=" + std::to_string(kBrowserWidth) + "," + std::to_string(kBrowserHeight),
       "file://" + std::filesystem::absolute(page).string() + htmlFrozenFragment(timeS)},
      dir);
  Screenshot s;
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.image = cv::imread(png.string(), cv::IMREAD_COLOR);
  s.log = run.output;
  return s;
}

struct Blob {
  cv::Point2d centre;  // in canvas pixels: pixel (i, j) covers [i, i + 1) × [j, j + 1)
  int area = 0;
};

// The dots: pixels nearer the dot colour than the background (along the line between
// them, so the bones' grey stays out), in connected blobs, each blob's centre of mass.
inline std::vector<Blob> findDots(const cv::Mat& bgr, const HtmlColours& colours) {
  const cv::Vec3d bg = rgbOf(colours.background), dot = rgbOf(colours.dot), along = dot - bg;
  cv::Mat mask(bgr.size(), CV_8U);
  for (int y = 0; y < bgr.rows; ++y)
    for (int x = 0; x < bgr.cols; ++x) {
      const cv::Vec3b p = bgr.at<cv::Vec3b>(y, x);
      const cv::Vec3d rgb(p[2], p[1], p[0]);
      mask.at<uchar>(y, x) = (rgb - bg).dot(along) / along.dot(along) > 0.5 ? 255 : 0;
    }
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8);
  std::vector<Blob> blobs;
  for (int i = 1; i < n; ++i)
    blobs.push_back({{centroids.at<double>(i, 0) + 0.5, centroids.at<double>(i, 1) + 0.5},
                     stats.at<int>(i, cv::CC_STAT_AREA)});
  return blobs;
}

}  // namespace ew::test
