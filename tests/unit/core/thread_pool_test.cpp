// The thread pool (thread_pool.hpp): parallel_for, worker_count and the sweep's StreamingPool.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/thread_pool.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <vector>

namespace corlab {
namespace {

TEST(ParallelFor, RunsEveryJobOnceOnSeveralThreads) {
  std::vector<std::atomic<int>> runs(1000);
  parallel_for(runs.size(), 4, [&](std::size_t i) { ++runs[i]; });
  for (const auto& r : runs) EXPECT_EQ(r.load(), 1);
  parallel_for(0, 4, [](std::size_t) { FAIL() << "no job to run"; });
  EXPECT_EQ(worker_count(3), 3);
  EXPECT_GE(worker_count(0), 1);
}

TEST(ParallelFor, StopsWhenCancelledAndRethrowsTheFirstError) {
  std::atomic<bool> cancel{true};
  std::atomic<int> ran{0};
  parallel_for(
      100, 2, [&](std::size_t) { ++ran; }, &cancel);
  EXPECT_EQ(ran.load(), 0);
  EXPECT_THROW(parallel_for(100, 3,
                            [](std::size_t i) {
                              if (i == 7) throw std::runtime_error("job 7");
                            }),
               std::runtime_error);
}

// The sweep's pool: every index from the source is run once, its result reaches the owning thread
// through take(), and stopped() turns true once the source is empty and the workers are done.
TEST(StreamingPool, HandsEveryResultToTheOwnerOnce) {
  std::mutex mutex;
  std::size_t next = 0;
  const auto source = [&]() -> std::optional<std::size_t> {
    const std::lock_guard lock(mutex);
    if (next >= 200) return std::nullopt;
    return next++;
  };
  StreamingPool<std::size_t> pool(3, source, [](std::size_t i) { return 10 * i; });
  std::vector<int> seen(200, 0);
  while (true) {
    const bool stopped = pool.stopped();  // read before taking: no result can be missed
    for (std::size_t r : pool.take(std::chrono::milliseconds(50))) ++seen.at(r / 10);
    if (stopped) break;
  }
  pool.join();
  for (int count : seen) EXPECT_EQ(count, 1);
  StreamingPool<int> idle(0, source, [](std::size_t) { return 0; });
  EXPECT_TRUE(idle.stopped());
  EXPECT_TRUE(idle.take(std::chrono::milliseconds(1)).empty());
}

}  // namespace
}  // namespace corlab
