#include "ui/app/screenshot.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "ui/gl/gl.h"

namespace ew::ui {

void writeScreenshot(const std::filesystem::path& file, int width, int height) {
  std::vector<unsigned char> rgb = gl::readPixelsRgb(width, height);
  cv::Mat image(height, width, CV_8UC3, rgb.data());
  cv::Mat flipped, bgr;
  cv::flip(image, flipped, 0);  // GL rows start at the bottom
  cv::cvtColor(flipped, bgr, cv::COLOR_RGB2BGR);
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  bool ok = false;
  try {
    ok = cv::imwrite(file.string(), bgr);
  } catch (const cv::Exception& e) {
    throw std::runtime_error(file.string() + ": cannot write the screenshot: " + e.what());
  }
  if (!ok) throw std::runtime_error(file.string() + ": cannot write the screenshot");
}

}  // namespace ew::ui
