#pragma once
// A video file read frame by frame (OpenCV's FFmpeg backend: MP4 with H.264 or VP9, AVI
// MJPG, MOV). Frame numbers count from 0 in decoding order; `frame(i)` is frame-accurate
// (sequential reads when moving forward a little, a seek otherwise — checked against a
// sequential decode of the shared clips in tests/video/test_video_source.cpp).

#include <filesystem>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <string>

namespace ew {

struct VideoInfo {
  std::string file;
  int widthPx = 0, heightPx = 0;
  double fps = 0.0;
  int frameCount = 0;  // what the container says; a shorter stream is found when read
  std::string codec;   // FourCC as text ("avc1", "vp09", "MJPG"), "" when unknown
};

// Bounds on what we open: a side of 16384 px is beyond any camera's; 10 million frames is
// over 90 hours at 30 fps.
inline constexpr int kMaxVideoSidePx = 16384;
inline constexpr int kMaxVideoFrames = 10'000'000;

class VideoSource {
 public:
  // Throws Error(Io) for a path that does not exist, Error(Malformed) naming the file when
  // no decoder opens it or its first frame cannot be decoded, Error(BadData) for a frame
  // size, rate or count outside the bounds above.
  explicit VideoSource(const std::filesystem::path& path);

  const VideoInfo& info() const { return info_; }

  // Frame `index` as 8-bit BGR. Error(BadArgument) for an index outside [0, frameCount);
  // Error(BadData) naming the file and frame when the stream ends before it (the
  // container's count was too high: info().frameCount is lowered to what was found).
  cv::Mat frame(int index);

 private:
  void seekTo(int index);

  cv::VideoCapture capture_;
  VideoInfo info_;
  int next_ = 0;  // the frame the next read() returns; −1 unknown (after a failed read)
};

// Frames as 8-bit grey, the tracker's input.
cv::Mat toGrey(const cv::Mat& bgr);

}  // namespace ew
