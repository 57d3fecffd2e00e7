#pragma once
// A video's frames decoded ahead on a worker thread into a cache bounded in bytes, for a
// viewer that scrubs and plays: asking for a frame never blocks; the worker decodes it and
// the frames after it (playback goes forward), and drops the frames furthest from the one
// asked for when the cache is full. A 10-minute 1080p clip is 36 000 frames of 6 MB: only
// the budget's worth (256 MB by default, ~40 frames) is ever held.

#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <opencv2/core.hpp>

#include "video/video_source.h"

namespace ew {

class FrameCache {
 public:
  // Opens the video on the calling thread (VideoSource's errors are thrown here), then starts
  // the worker. `budgetBytes` bounds the frames held; at least two are always kept.
  explicit FrameCache(const std::filesystem::path& path,
                      std::size_t budgetBytes = std::size_t{256} << 20, int aheadFrames = 60);
  ~FrameCache();
  FrameCache(const FrameCache&) = delete;
  FrameCache& operator=(const FrameCache&) = delete;

  const VideoInfo& info() const { return info_; }
  // The frames the stream really has (lowered when it ends before the container's count).
  int frameCount() const;

  // Frame `index` (8-bit BGR, shared, never changed) when decoded; else nullptr, and the
  // worker is asked for it. An index outside [0, frameCount()) is clamped.
  std::shared_ptr<const cv::Mat> frame(int index);
  // Blocks until frame `index` is decoded or failed (tests, scripted screenshots).
  std::shared_ptr<const cv::Mat> waitFrame(int index);
  // True while the frame last asked for is not decoded yet (nor failed).
  bool pending() const;

  std::size_t bytesHeld() const;
  std::size_t budgetBytes() const { return budget_; }
  // The last decoding error ("" when none): the file, the frame, the reason.
  std::string error() const;

 private:
  void run();
  void decodeAround(int wanted, std::unique_lock<std::mutex>& lock);
  void evictFarFrom(int wanted);

  VideoSource source_;  // used by the worker only, after construction
  VideoInfo info_;
  std::size_t budget_;
  int ahead_;

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::map<int, std::shared_ptr<const cv::Mat>> frames_;
  std::size_t bytes_ = 0;
  int wanted_ = 0;
  int frameCount_ = 0;
  std::uint64_t request_ = 0;  // bumped on each new wanted frame: the worker restarts around it
  std::string error_;
  int failedFrame_ = -1;
  bool stop_ = false;
  std::thread worker_;
};

}  // namespace ew
