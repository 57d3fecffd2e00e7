#pragma once
// Slow work off the UI thread: one job at a time per BackgroundJob, a progress value the
// UI draws, and the result (or the error message) picked up by poll() when ready.

#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace ew::ui {

// Thrown out of JobProgress::set once the job's owner has gone: the work stops at its next
// progress report instead of running on for minutes after the window has closed.
struct JobCancelled : std::runtime_error {
  JobCancelled() : std::runtime_error("cancelled") {}
};

class JobProgress {
 public:
  void set(int done, int total, std::string what) {
    if (cancelled_) throw JobCancelled();
    std::lock_guard lock(mutex_);
    done_ = done;
    total_ = total;
    what_ = std::move(what);
  }
  // 0 … 1 (0 while the total is unknown).
  float fraction() const {
    std::lock_guard lock(mutex_);
    return total_ > 0 ? static_cast<float>(done_) / static_cast<float>(total_) : 0.0f;
  }
  std::string what() const {
    std::lock_guard lock(mutex_);
    return what_;
  }
  void cancel() { cancelled_ = true; }
  bool cancelled() const { return cancelled_; }

 private:
  mutable std::mutex mutex_;
  int done_ = 0, total_ = 0;
  std::string what_;
  std::atomic<bool> cancelled_{false};
};

template <class T>
struct JobOutcome {
  std::optional<T> value;  // set on success
  std::string error;       // set on failure
};

template <class T>
class BackgroundJob {
 public:
  BackgroundJob() = default;
  BackgroundJob(const BackgroundJob&) = delete;
  BackgroundJob& operator=(const BackgroundJob&) = delete;
  ~BackgroundJob() {
    if (progress_) progress_->cancel();
    if (future_.valid()) future_.wait();
  }

  // Starts `work` on a worker thread. Only when idle (check running()).
  void start(std::string title, std::function<T(JobProgress&)> work) {
    title_ = std::move(title);
    progress_ = std::make_shared<JobProgress>();
    future_ = std::async(std::launch::async,
                         [p = progress_, w = std::move(work)]() { return w(*p); });
  }

  bool running() const { return future_.valid(); }
  // Asks the work to stop at its next progress report (poll() then gives its error).
  void cancel() {
    if (progress_) progress_->cancel();
  }
  bool cancelled() const { return progress_ && progress_->cancelled(); }
  const std::string& title() const { return title_; }
  float fraction() const { return progress_ ? progress_->fraction() : 0.0f; }
  std::string what() const { return progress_ ? progress_->what() : std::string(); }

  // The outcome once the work has finished (once), else nothing.
  std::optional<JobOutcome<T>> poll() {
    if (!future_.valid()) return std::nullopt;
    if (future_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
    JobOutcome<T> outcome;
    try {
      outcome.value.emplace(future_.get());
    } catch (const std::exception& e) {
      outcome.error = e.what();
    } catch (...) {
      outcome.error = "unknown error";
    }
    future_ = {};
    return outcome;
  }

 private:
  std::string title_;
  std::shared_ptr<JobProgress> progress_;
  std::future<T> future_;
};

}  // namespace ew::ui
