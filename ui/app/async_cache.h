#pragma once
// Slow derived work (a keypoint clip's camera fit, the analysis curves, the Data window's
// table) computed off the UI thread and kept by the inputs it was computed from: the one
// pattern behind every "running key, failed key, error" the viewer needs.
//
//   AsyncCache<Key, T> cache{capacity};
//   cache.request(key, title, work);   // starts unless cached, running or failed for key
//   if (auto done = cache.poll()) …    // once a frame: the outcome, once; kept in the cache
//   cache.find(key), cache.latest()    // what was computed
//   cache.failed(key), cache.error()   // a key that failed is not retried until retry()
//
// Key needs operator==. Values are shared_ptr<const T>: a panel keeps what it draws alive.

#include <algorithm>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ui/app/background_job.h"

namespace ew::ui {

template <class Key, class T>
class AsyncCache {
 public:
  using Value = std::shared_ptr<const T>;
  using Work = std::function<Value(JobProgress&)>;

  // What poll() picked up: the key the work ran for, and its value or why it failed.
  struct Done {
    Key key;
    Value value;        // null when the work failed
    std::string error;  // "" on success
    bool ok() const { return value != nullptr; }
  };

  // Keeps the values of the last `capacity` keys (at least one).
  explicit AsyncCache(std::size_t capacity = 1) : capacity_(std::max<std::size_t>(capacity, 1)) {}

  // [SECTION] The values computed
  // The value computed for `key`, else null.
  Value find(const Key& key) const {
    for (const auto& [k, v] : values_)
      if (k == key) return v;
    return nullptr;
  }
  // The value computed last, whatever its key (null: none yet, or reset()).
  const Value& latest() const {
    static const Value none;
    return values_.empty() ? none : values_.back().second;
  }
  // A value computed elsewhere (on the UI thread, for a script that cannot wait).
  void put(Key key, Value value) {
    std::erase_if(values_, [&](const auto& kv) { return kv.first == key; });
    values_.emplace_back(std::move(key), std::move(value));
    if (values_.size() > capacity_) values_.erase(values_.begin());
  }
  // Forgets the values (a running job still delivers its outcome).
  void reset() { values_.clear(); }

  // [SECTION] The work
  bool running() const { return job_.running(); }
  // The key the running (or last started) work is for.
  const Key& runningKey() const { return running_; }
  // The key whose work failed last and why; not started again until retry() or a success.
  const std::optional<Key>& failedKey() const { return failed_; }
  bool failed(const Key& key) const { return failed_ && *failed_ == key; }
  const std::string& error() const { return error_; }
  // The failed key may be tried again; its error stays until the next outcome.
  void retry() { failed_.reset(); }
  void clearFailure() {
    failed_.reset();
    error_.clear();
  }
  // A failure found before any work started (the inputs could not be read).
  void fail(Key key, std::string error) {
    failed_ = key;
    running_ = std::move(key);
    error_ = std::move(error);
  }

  // Starts `work` for `key` unless its value is kept, it is running, or it failed; true when
  // started. Only one job at a time: while another key runs, nothing starts.
  bool request(const Key& key, std::string title, Work work) {
    if (running() || find(key) || failed(key)) return false;
    start(key, std::move(title), std::move(work));
    return true;
  }
  // Starts `work` for `key` (only when idle: check running()).
  void start(Key key, std::string title, Work work) {
    running_ = std::move(key);
    job_.start(std::move(title), std::move(work));
  }

  // The outcome once the work has finished (once), else nothing. A value is kept and clears
  // the failure; a failure records the key and the error.
  std::optional<Done> poll() {
    auto outcome = job_.poll();
    if (!outcome) return std::nullopt;
    Done done{running_, nullptr, std::move(outcome->error)};
    if (outcome->value && *outcome->value) {
      done.value = std::move(*outcome->value);
      put(running_, done.value);
      failed_.reset();
      error_.clear();
    } else {
      if (done.error.empty()) done.error = "no result";
      failed_ = running_;
      error_ = done.error;
    }
    return done;
  }

  // The running work's progress, as BackgroundJob's.
  void cancel() { job_.cancel(); }
  const std::string& title() const { return job_.title(); }
  float fraction() const { return job_.fraction(); }
  std::string what() const { return job_.what(); }

 private:
  std::size_t capacity_;
  std::vector<std::pair<Key, Value>> values_;  // oldest first
  BackgroundJob<Value> job_;
  Key running_{};
  std::optional<Key> failed_;
  std::string error_;
};

}  // namespace ew::ui
