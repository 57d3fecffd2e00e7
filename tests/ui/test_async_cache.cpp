// AsyncCache: work runs once per key, its value is kept by key (the last few), a key that
// failed is not tried again until retry(), and poll() gives each outcome once.

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>

#include "ui/app/async_cache.h"

namespace ew::ui {
namespace {

using Cache = AsyncCache<int, std::string>;

Cache::Done waitFor(Cache& cache) {
  for (;;) {
    if (auto done = cache.poll()) return *done;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
}

Cache::Work text(std::string t) {
  return [t](JobProgress&) { return std::make_shared<const std::string>(t); };
}

TEST(AsyncCache, KeepsTheValueByItsKey) {
  Cache cache;
  EXPECT_EQ(cache.latest(), nullptr);
  EXPECT_TRUE(cache.request(1, "one", text("a")));
  EXPECT_TRUE(cache.running());
  EXPECT_EQ(cache.runningKey(), 1);
  EXPECT_EQ(cache.title(), "one");
  const auto done = waitFor(cache);
  EXPECT_TRUE(done.ok());
  EXPECT_EQ(done.key, 1);
  EXPECT_EQ(*done.value, "a");
  EXPECT_FALSE(cache.running());
  EXPECT_FALSE(cache.poll().has_value());  // once
  ASSERT_NE(cache.find(1), nullptr);
  EXPECT_EQ(*cache.latest(), "a");
  EXPECT_EQ(cache.find(2), nullptr);
  EXPECT_FALSE(cache.request(1, "one again", text("b")));  // kept: not computed again
}

TEST(AsyncCache, StartsNothingWhileRunning) {
  Cache cache;
  ASSERT_TRUE(cache.request(1, "one", [](JobProgress&) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    return std::make_shared<const std::string>("a");
  }));
  EXPECT_FALSE(cache.request(2, "two", text("b")));
  waitFor(cache);
  EXPECT_TRUE(cache.request(2, "two", text("b")));
  waitFor(cache);
  EXPECT_EQ(*cache.latest(), "b");
}

TEST(AsyncCache, KeepsTheLastFewKeys) {
  Cache cache(2);
  for (int k = 1; k <= 3; ++k) {
    ASSERT_TRUE(cache.request(k, "k", text(std::to_string(k))));
    waitFor(cache);
  }
  EXPECT_EQ(cache.find(1), nullptr);
  EXPECT_NE(cache.find(2), nullptr);
  EXPECT_NE(cache.find(3), nullptr);
  cache.put(2, std::make_shared<const std::string>("again"));  // now the newest
  EXPECT_EQ(*cache.latest(), "again");
  cache.reset();
  EXPECT_EQ(cache.latest(), nullptr);
}

TEST(AsyncCache, AFailedKeyWaitsForRetry) {
  Cache cache;
  ASSERT_TRUE(cache.request(7, "seven", [](JobProgress&) -> Cache::Value {
    throw std::runtime_error("no walk fits");
  }));
  const auto done = waitFor(cache);
  EXPECT_FALSE(done.ok());
  EXPECT_EQ(done.key, 7);
  EXPECT_EQ(done.error, "no walk fits");
  EXPECT_TRUE(cache.failed(7));
  EXPECT_FALSE(cache.failed(8));
  EXPECT_EQ(cache.error(), "no walk fits");
  EXPECT_FALSE(cache.request(7, "seven", text("x")));  // not tried again
  cache.retry();
  EXPECT_EQ(cache.error(), "no walk fits");  // still said until the next outcome
  EXPECT_TRUE(cache.request(7, "seven", text("x")));
  waitFor(cache);
  EXPECT_FALSE(cache.failedKey().has_value());
  EXPECT_EQ(cache.error(), "");  // a success clears the failure
}

TEST(AsyncCache, AFailureBeforeTheWork) {
  Cache cache;
  cache.fail(3, "cannot read the inputs");
  EXPECT_TRUE(cache.failed(3));
  EXPECT_EQ(cache.runningKey(), 3);
  EXPECT_FALSE(cache.running());
  cache.clearFailure();
  EXPECT_FALSE(cache.failed(3));
  EXPECT_EQ(cache.error(), "");
}

}  // namespace
}  // namespace ew::ui
