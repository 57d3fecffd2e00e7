// Reading footage (video/video_source.h, and video/frame_cache.h ahead of a viewer): frame-accurate access in any order, checked
// against a sequential decode, on a clip the test writes and on the shared real clips;
// files that are not videos, or end early, give errors naming the file.

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"
#include "video/frame_cache.h"
#include "video/video_source.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

// A clip whose frame k shows a white bar at column 4k on black (MJPG in AVI: every frame
// a keyframe, no codec we might lack).
fs::path barClip(const fs::path& dir, int frames) {
  const fs::path file = dir / "bars.avi";
  cv::VideoWriter writer(file.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                         25.0, cv::Size(320, 240));
  EXPECT_TRUE(writer.isOpened());
  for (int k = 0; k < frames; ++k) {
    cv::Mat image(240, 320, CV_8UC3, cv::Scalar(0, 0, 0));
    cv::rectangle(image, cv::Rect(4 * k, 0, 4, 240), cv::Scalar(255, 255, 255), cv::FILLED);
    writer.write(image);
  }
  return file;
}

int barColumn(const cv::Mat& bgr) {
  cv::Mat grey = toGrey(bgr), columns;
  cv::reduce(grey, columns, 0, cv::REDUCE_AVG, CV_64F);
  cv::Point best;
  cv::minMaxLoc(columns, nullptr, nullptr, nullptr, &best);
  return best.x / 4;
}

TEST(VideoSource, EveryFrameInAnyOrderIsTheFrameAskedFor) {
  const fs::path file = barClip(test::makeTempDir("video_bars"), 60);
  VideoSource video(file);
  EXPECT_EQ(video.info().widthPx, 320);
  EXPECT_EQ(video.info().heightPx, 240);
  EXPECT_DOUBLE_EQ(video.info().fps, 25.0);
  EXPECT_EQ(video.info().frameCount, 60);
  EXPECT_EQ(video.info().codec, "MJPG");
  for (const int k : {0, 1, 2, 59, 30, 31, 5, 45, 44, 43, 0, 58})
    EXPECT_EQ(barColumn(video.frame(k)), k) << "frame " << k;
  EXPECT_TRUE(
      test::throwsError([&] { video.frame(60); }, ErrorKind::BadArgument, {"frame 60", "0-59"}));
  EXPECT_TRUE(test::throwsError([&] { video.frame(-1); }, ErrorKind::BadArgument, {"frame -1"}));
}

TEST(VideoSource, SeekingInTheSharedClipsGivesTheSequentialDecodesFrames) {
  EW_REQUIRE_SHARED_DATA();
  for (const char* clip : {"video/sports2d-demo/demo.mp4", "pose2sim-balancing/videos/cam01.mp4"}) {
    const fs::path file = test::sharedDataDir() / clip;
    std::vector<cv::Mat> sequential;
    cv::VideoCapture capture(file.string(), cv::CAP_FFMPEG);
    for (cv::Mat f; capture.read(f);) sequential.push_back(f.clone());
    VideoSource video(file);
    ASSERT_EQ(video.info().frameCount, static_cast<int>(sequential.size())) << clip;
    const int last = video.info().frameCount - 1;
    for (const int k : {last, 3, last / 2, 0, last / 2 + 1, 17, last - 1})
      EXPECT_EQ(cv::norm(video.frame(k), sequential[static_cast<std::size_t>(k)], cv::NORM_INF),
                0.0)
          << clip << " frame " << k;
  }
}

TEST(VideoSource, WhatIsNotAVideoIsNamedWithTheProblem) {
  const fs::path dir = test::makeTempDir("video_bad");
  EXPECT_TRUE(test::throwsError([&] { VideoSource v(dir / "missing.mp4"); }, ErrorKind::Io,
                                {"missing.mp4", "no such"}));
  EXPECT_TRUE(
      test::throwsError([&] { VideoSource v(dir); }, ErrorKind::Io, {"no such video file"}));
  test::writeBinaryFile(dir / "text.mp4", "this is not a video\n");
  EXPECT_TRUE(test::throwsError([&] { VideoSource v(dir / "text.mp4"); }, ErrorKind::Malformed,
                                {"text.mp4"}));
  // A photo handed in as a video: FFmpeg opens it, with no frame count.
  cv::imwrite((dir / "photo.png").string(), cv::Mat(48, 64, CV_8UC3, cv::Scalar(40, 90, 200)));
  fs::rename(dir / "photo.png", dir / "photo.mp4");
  EXPECT_TRUE(test::throwsError([&] { VideoSource v(dir / "photo.mp4"); }, ErrorKind::BadData,
                                {"photo.mp4", "does not say how many frames"}));
  test::writeBinaryFile(dir / "empty.avi", "");
  EXPECT_TRUE(test::throwsError([&] { VideoSource v(dir / "empty.avi"); }, ErrorKind::Malformed,
                                {"empty.avi"}));
  // A hostile header: an AVI whose stream says it holds 2^31 - 1 frames (strh's dwLength).
  std::string bytes = test::readTextFile(barClip(dir, 4));
  const std::size_t strh = bytes.find("strh");
  ASSERT_NE(strh, std::string::npos);
  const std::uint32_t huge = 0x7fffffff;
  for (int b = 0; b < 4; ++b) bytes[strh + 8 + 32 + b] = static_cast<char>((huge >> (8 * b)) & 0xff);
  test::writeBinaryFile(dir / "huge.avi", bytes);
  EXPECT_TRUE(test::throwsError([&] { VideoSource v(dir / "huge.avi"); }, ErrorKind::BadData,
                                {"huge.avi", "the header's frame count 2147483647 is outside"}));
}

TEST(VideoSource, AClipCutShortEndsWithAnErrorAtTheFirstMissingFrame) {
  const fs::path dir = test::makeTempDir("video_cut");
  const std::string whole = test::readTextFile(barClip(dir, 60));
  const fs::path cut = dir / "cut.avi";
  test::writeBinaryFile(cut,
                        whole.substr(0, whole.size() / 2));  // the index at the end is gone too
  VideoSource video(cut);
  const int announced = video.info().frameCount;
  int decoded = 0;
  for (; decoded < announced; ++decoded) {
    try {
      EXPECT_EQ(barColumn(video.frame(decoded)), decoded);
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadData) << e.what();
      EXPECT_NE(std::string(e.what()).find("cut.avi"), std::string::npos) << e.what();
      break;
    }
  }
  // Half the bytes hold about half the frames; whatever the container announced, the
  // frames read are the right ones and the end is an error, not a crash or a repeat.
  EXPECT_GE(decoded, 20);
  EXPECT_LE(decoded, 40);
  EXPECT_LE(video.info().frameCount, std::max(decoded, announced));
  // After the failed read, the frames before it still decode, sought to from anywhere.
  for (const int k : {decoded - 1, 3, decoded / 2, 0})
    EXPECT_EQ(barColumn(video.frame(k)), k) << "frame " << k << " after the end was met";
  EXPECT_GE(video.info().frameCount, decoded);
}

// A phone held upright writes its video landscape with a rotation in the track header; the
// frames come out turned upright, and the video's size is theirs (the marks and the tracker
// work in it). Here the header of an MP4 the test writes (64 x 48, a white square at the top
// left) is given a quarter turn, as a phone's is.
TEST(VideoSource, AVideoWithARotationInItsHeaderIsReadTurnedUpright) {
  const fs::path dir = test::makeTempDir("video_rotated");
  const fs::path plain = dir / "plain.mp4";
  {
    cv::VideoWriter writer(plain.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), 30.0,
                           cv::Size(64, 48));
    ASSERT_TRUE(writer.isOpened());
    for (int k = 0; k < 6; ++k) {
      cv::Mat image(48, 64, CV_8UC3, cv::Scalar(0, 0, 0));
      cv::rectangle(image, cv::Rect(0, 0, 16, 16), cv::Scalar(255, 255, 255), cv::FILLED);
      writer.write(image);
    }
  }
  std::string bytes = test::readTextFile(plain);
  const std::size_t tkhd = bytes.find("tkhd");
  ASSERT_NE(tkhd, std::string::npos);
  // ISO/IEC 14496-12 tkhd, version 0: after the type, 4 bytes version and flags, 20 of times,
  // ids and duration, 8 reserved, layer, group, volume, 2 reserved: then the 3 x 3 matrix.
  std::size_t at = tkhd + 4 + 4 + 20 + 8 + 8;
  for (const std::uint32_t v : {0u, 0x00010000u, 0u, 0xFFFF0000u, 0u, 0u, 0u, 0u, 0x40000000u}) {
    for (int b = 3; b >= 0; --b) bytes[at++] = static_cast<char>((v >> (8 * b)) & 0xFF);
  }
  const fs::path turned = dir / "turned.mp4";
  test::writeBinaryFile(turned, bytes);

  VideoSource video(turned);
  EXPECT_EQ(video.info().widthPx, 48);
  EXPECT_EQ(video.info().heightPx, 64);
  const cv::Mat frame = video.frame(3);
  ASSERT_EQ(frame.cols, 48);
  ASSERT_EQ(frame.rows, 64);
  // The white square left the top left corner for another: the picture was turned.
  const auto bright = [&](int x, int y) { return toGrey(frame).at<unsigned char>(y, x) > 128; };
  EXPECT_FALSE(bright(4, 4));
  EXPECT_TRUE(bright(4, 59) || bright(43, 4) || bright(43, 59));
}

TEST(FrameCache, FramesComeBackRightWithinTheBudget) {
  const fs::path file = barClip(test::makeTempDir("video_cache"), 60);
  const std::size_t frameBytes = 320 * 240 * 3;
  FrameCache cache(file, 5 * frameBytes, 8);
  EXPECT_EQ(cache.frameCount(), 60);
  // Scrubbing forward, then back, then jumping: every frame is the one asked for, and the
  // cache never holds more than its budget.
  for (const int k : {0, 1, 2, 3, 10, 11, 59, 58, 30, 0, 45}) {
    const auto f = cache.waitFrame(k);
    ASSERT_TRUE(f) << "frame " << k << ": " << cache.error();
    EXPECT_EQ(barColumn(*f), k) << "frame " << k;
    EXPECT_LE(cache.bytesHeld(), 5 * frameBytes) << "after frame " << k;
  }
  // Asking does not block: a frame far from the last one asked for is not there yet (the
  // worker cannot add it while frame() holds the lock), then comes.
  EXPECT_FALSE(cache.frame(20));
  EXPECT_TRUE(cache.waitFrame(20));
  // Outside the clip: the last frame.
  const auto end = cache.waitFrame(1000);
  ASSERT_TRUE(end);
  EXPECT_EQ(barColumn(*end), 59);
  EXPECT_EQ(cache.error(), "");
}

}  // namespace
}  // namespace ew
