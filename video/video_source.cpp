#include "video/video_source.h"

#include <cmath>
#include <sstream>
#include <opencv2/imgproc.hpp>

#include "core/common/errors.h"

namespace ew {
namespace {

// A header's number as a person writes it: 2147483647, 29.97 (std::to_string gives six decimals).
std::string plainNumber(double x) {
  std::ostringstream s;
  s.precision(10);
  s << x;
  return s.str();
}

// Seeking costs a decode from the previous keyframe; reading forward up to this many
// frames is cheaper than that for the clips we see (a keyframe every 1-10 s).
constexpr int kReadAheadInsteadOfSeek = 30;

std::string fourccText(double value) {
  const auto code = static_cast<unsigned>(value);
  std::string text;
  for (int shift = 0; shift < 32; shift += 8) {
    const char c = static_cast<char>((code >> shift) & 0xFFu);
    if (c < 32 || c > 126) return "";
    text += c;
  }
  return text;
}

}  // namespace

VideoSource::VideoSource(const std::filesystem::path& path) {
  info_.file = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(ErrorKind::Io, info_.file, "", "no such video file");
  if (!capture_.open(info_.file, cv::CAP_FFMPEG))
    throwMalformed(info_.file, "", "not a video the FFmpeg backend can decode");
  info_.widthPx = static_cast<int>(capture_.get(cv::CAP_PROP_FRAME_WIDTH));
  info_.heightPx = static_cast<int>(capture_.get(cv::CAP_PROP_FRAME_HEIGHT));
  info_.fps = capture_.get(cv::CAP_PROP_FPS);
  const double count = capture_.get(cv::CAP_PROP_FRAME_COUNT);
  info_.codec = fourccText(capture_.get(cv::CAP_PROP_FOURCC));
  if (info_.widthPx <= 0 || info_.heightPx <= 0 || info_.widthPx > kMaxVideoSidePx ||
      info_.heightPx > kMaxVideoSidePx)
    throwBadData(info_.file, "",
                 "frame size " + std::to_string(info_.widthPx) + "x" +
                     std::to_string(info_.heightPx) + " is outside 1-" +
                     std::to_string(kMaxVideoSidePx) + " px");
  if (!std::isfinite(info_.fps) || info_.fps < 1.0 || info_.fps > 10000.0)
    throwBadData(info_.file, "",
                 "frame rate " + plainNumber(info_.fps) + " is outside 1-10000 fps");
  // FFmpeg estimates the count from the container's duration; a still image or a raw stream
  // has none, and the estimate comes back negative or not a number.
  if (!std::isfinite(count) || count < 1.0)
    throwBadData(info_.file, "",
                 "it does not say how many frames it holds (a still image, or a raw stream "
                 "without a container: put the stream in an MP4, MKV or AVI)");
  if (count > kMaxVideoFrames)
    throwBadData(info_.file, "",
                 "the header's frame count " + plainNumber(count) + " is outside 1-" +
                     std::to_string(kMaxVideoFrames) + " (a damaged header?)");
  info_.frameCount = static_cast<int>(count);
  cv::Mat first;
  if (!capture_.read(first) || first.empty())
    throwMalformed(info_.file, "frame 0", "cannot be decoded");
  // The pictures' own size, which every frame is checked against: the FFmpeg backend turns a
  // phone's video by the rotation in its header (and reports the turned size too; test
  // VideoSource.AVideoWithARotationInItsHeaderIsReadTurnedUpright).
  info_.widthPx = first.cols;
  info_.heightPx = first.rows;
  next_ = 1;
}

void VideoSource::seekTo(int index) {
  if (index == next_) return;
  if (next_ >= 0 && index > next_ && index - next_ <= kReadAheadInsteadOfSeek) {
    while (next_ < index) {
      if (!capture_.grab()) break;
      ++next_;
    }
    if (next_ == index) return;
  }
  capture_.set(cv::CAP_PROP_POS_FRAMES, static_cast<double>(index));
  next_ = index;
}

cv::Mat VideoSource::frame(int index) {
  if (index < 0 || index >= info_.frameCount)
    throw Error(ErrorKind::BadArgument, info_.file, "frame " + std::to_string(index),
                "outside the video's frames 0-" + std::to_string(info_.frameCount - 1));
  seekTo(index);
  cv::Mat image;
  if (!capture_.read(image) || image.empty()) {
    info_.frameCount = std::min(info_.frameCount, index);
    next_ = -1;  // unknown: the next request seeks
    throwBadData(info_.file, "frame " + std::to_string(index),
                 "the stream ends before this frame (the container announced more frames)");
  }
  ++next_;
  // A defence: the backend scales a stream whose pictures change size to the first's, in
  // the cases tried (an MJPG frame's header given another height).
  if (image.cols != info_.widthPx || image.rows != info_.heightPx)
    throwBadData(info_.file, "frame " + std::to_string(index),
                 "is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                     " px where the first is " + std::to_string(info_.widthPx) + "x" +
                     std::to_string(info_.heightPx) + " (a stream that changes size is not read)");
  if (image.type() != CV_8UC3) {
    cv::Mat converted;
    if (image.channels() == 1)
      cv::cvtColor(image, converted, cv::COLOR_GRAY2BGR);
    else if (image.channels() == 4)
      cv::cvtColor(image, converted, cv::COLOR_BGRA2BGR);
    else
      throwMalformed(info_.file, "frame " + std::to_string(index), "unsupported pixel format");
    image = converted;
  }
  return image;
}

cv::Mat toGrey(const cv::Mat& bgr) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  return grey;
}

}  // namespace ew
