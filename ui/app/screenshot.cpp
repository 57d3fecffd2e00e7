#include "ui/app/screenshot.h"

#include <algorithm>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

#include "core/io/atomic_write.h"
#include "ui/gl/gl.h"

namespace ew::ui {

void writeScreenshot(const std::filesystem::path& file, int width, int height, std::optional<PixelRect> crop) {
  writeRgbPng(file, gl::readPixelsRgb(width, height), width, height, crop);
}

void writeRgbPng(const std::filesystem::path& file, std::vector<unsigned char> rgb, int width, int height,
                 std::optional<PixelRect> crop) {
  if (rgb.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3)
    throw std::runtime_error(file.string() + ": no image to write");
  cv::Mat image(height, width, CV_8UC3, rgb.data());
  cv::Mat flipped, bgr;
  cv::flip(image, flipped, 0);  // GL rows start at the bottom
  cv::cvtColor(flipped, bgr, cv::COLOR_RGB2BGR);
  if (crop) {
    const int x0 = std::clamp(crop->x0, 0, width - 1), y0 = std::clamp(crop->y0, 0, height - 1);
    const int x1 = std::clamp(crop->x1, x0 + 1, width);
    const int y1 = std::clamp(crop->y1, y0 + 1, height);
    bgr = bgr(cv::Rect(x0, y0, x1 - x0, y1 - y0)).clone();
  }
  std::vector<unsigned char> png;
  try {
    if (!cv::imencode(".png", bgr, png)) throw std::runtime_error(file.string() + ": cannot encode the PNG");
  } catch (const cv::Exception& e) {
    throw std::runtime_error(file.string() + ": cannot encode the PNG: " + e.what());
  }
  std::error_code ec;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ec);
  try {
    writeFileAtomically(file, [&png](std::ostream& out) {
      out.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
    });
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("cannot write the screenshot: ") + e.what());
  }
}

}  // namespace ew::ui
