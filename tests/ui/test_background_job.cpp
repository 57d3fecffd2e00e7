// BackgroundJob: results and errors reach poll(); a job still running when its owner goes
// away is cancelled at its next progress report rather than waited out.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

#include "ui/app/background_job.h"

namespace ew::ui {
namespace {

template <class T>
JobOutcome<T> waitFor(BackgroundJob<T>& job) {
  for (;;) {
    if (auto outcome = job.poll()) return *outcome;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

TEST(BackgroundJob, DeliversTheResultOnce) {
  BackgroundJob<int> job;
  job.start("answer", [](JobProgress& p) {
    p.set(1, 1, "done");
    return 42;
  });
  EXPECT_TRUE(job.running());
  const auto outcome = waitFor(job);
  ASSERT_TRUE(outcome.value);
  EXPECT_EQ(*outcome.value, 42);
  EXPECT_FALSE(job.running());
  EXPECT_FALSE(job.poll());
}

TEST(BackgroundJob, DeliversTheErrorMessage) {
  BackgroundJob<int> job;
  job.start("fails", [](JobProgress&) -> int { throw std::runtime_error("walkers.csv: no walkers"); });
  const auto outcome = waitFor(job);
  EXPECT_FALSE(outcome.value);
  EXPECT_EQ(outcome.error, "walkers.csv: no walkers");
}

TEST(BackgroundJob, DestroyingARunningJobCancelsItAtTheNextProgressReport) {
  std::atomic<int> reports{0};
  std::atomic<bool> started{false};
  const auto t0 = std::chrono::steady_clock::now();
  {
    BackgroundJob<int> job;
    // Without cancellation this runs 100 000 reports × 1 ms ≈ 100 s.
    job.start("long", [&](JobProgress& p) {
      for (int i = 0; i < 100000; ++i) {
        p.set(i, 100000, "step");
        ++reports;
        started = true;
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
      return 0;
    });
    while (!started) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_LT(reports.load(), 100000);
  EXPECT_LT(seconds, 50.0);  // generous for a loaded sanitizer build; the uncancelled job takes ~100 s
}

}  // namespace
}  // namespace ew::ui
