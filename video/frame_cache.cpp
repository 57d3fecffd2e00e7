#include "video/frame_cache.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <utility>
#include <vector>

namespace ew {

FrameCache::FrameCache(const std::filesystem::path& path, std::size_t budgetBytes, int aheadFrames)
    : source_(path), info_(source_.info()), budget_(budgetBytes), ahead_(std::max(aheadFrames, 1)) {
  frameCount_ = info_.frameCount;
  worker_ = std::thread([this] { run(); });
}

FrameCache::~FrameCache() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

int FrameCache::frameCount() const {
  std::lock_guard lock(mutex_);
  return frameCount_;
}

std::shared_ptr<const cv::Mat> FrameCache::frame(int index) {
  std::lock_guard lock(mutex_);
  index = std::clamp(index, 0, std::max(frameCount_ - 1, 0));
  if (index != wanted_) {
    wanted_ = index;
    ++request_;
    changed_.notify_all();
  }
  const auto it = frames_.find(index);
  return it == frames_.end() ? nullptr : it->second;
}

std::shared_ptr<const cv::Mat> FrameCache::waitFrame(int index) {
  auto f = frame(index);
  std::unique_lock lock(mutex_);
  index = std::clamp(index, 0, std::max(frameCount_ - 1, 0));
  changed_.wait(lock, [&] { return frames_.count(index) > 0 || failedFrame_ == index || stop_; });
  const auto it = frames_.find(index);
  return it == frames_.end() ? nullptr : it->second;
}

bool FrameCache::pending() const {
  std::lock_guard lock(mutex_);
  return frames_.count(wanted_) == 0 && failedFrame_ != wanted_;
}

std::size_t FrameCache::bytesHeld() const {
  std::lock_guard lock(mutex_);
  return bytes_;
}

std::string FrameCache::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

void FrameCache::run() {
  std::unique_lock lock(mutex_);
  while (!stop_) {
    const std::uint64_t request = request_;
    decodeAround(wanted_, lock);
    changed_.wait(lock, [&] { return stop_ || request_ != request; });
  }
}

// Decodes `wanted` and the frames after it until the look-ahead or the budget is reached,
// the lock released while decoding; returns early when another frame is asked for.
void FrameCache::decodeAround(int wanted, std::unique_lock<std::mutex>& lock) {
  const std::uint64_t request = request_;
  const std::size_t frameBytes =
      static_cast<std::size_t>(info_.widthPx) * static_cast<std::size_t>(info_.heightPx) * 3;
  const int budgetFrames =
      static_cast<int>(std::max<std::size_t>(budget_ / std::max<std::size_t>(frameBytes, 1), 2));
  const int last = std::min({wanted + ahead_, wanted + budgetFrames - 1, frameCount_ - 1});
  for (int i = wanted; i <= last && !stop_ && request_ == request; ++i) {
    if (frames_.count(i) > 0) continue;
    std::shared_ptr<const cv::Mat> decoded;
    std::string failure;
    lock.unlock();
    try {
      decoded = std::make_shared<const cv::Mat>(source_.frame(i));
    } catch (const std::exception& e) {
      failure = e.what();
    }
    lock.lock();
    if (!decoded) {
      // The stream ends early (VideoSource lowered its count) or the frame is damaged.
      error_ = failure;
      failedFrame_ = i;
      frameCount_ = std::min(frameCount_, source_.info().frameCount);
      changed_.notify_all();
      return;
    }
    bytes_ += decoded->total() * decoded->elemSize();
    frames_.emplace(i, std::move(decoded));
    evictFarFrom(request_ == request ? wanted : wanted_);
    changed_.notify_all();
  }
}

// Drops the frames furthest from `wanted` (those behind it count double: playback goes
// forward) until the cache fits its budget; two frames always stay.
void FrameCache::evictFarFrom(int wanted) {
  while (bytes_ > budget_ && frames_.size() > 2) {
    auto far = frames_.begin();
    const auto distance = [wanted](int i) { return i < wanted ? 2 * (wanted - i) : i - wanted; };
    for (auto it = frames_.begin(); it != frames_.end(); ++it)
      if (distance(it->first) > distance(far->first)) far = it;
    bytes_ -= far->second->total() * far->second->elemSize();
    frames_.erase(far);
  }
}

}  // namespace ew
