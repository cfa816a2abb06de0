// The shared utilities of core/: trim, one_line, the atomic file writer, the interrupt handler and
// the thread pool.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

#include "corlab/core/atomic_file.hpp"
#include "corlab/core/interrupt.hpp"
#include "corlab/core/text.hpp"
#include "corlab/core/thread_pool.hpp"
#include "support/scratch_files.hpp"

namespace corlab {
namespace {

namespace fs = std::filesystem;

TEST(Trim, RemovesBlanksAtBothEndsOnly) {
  EXPECT_EQ(trim("  a b \t\r\n"), "a b");
  EXPECT_EQ(trim("x"), "x");
  EXPECT_EQ(trim(" \t "), "");
  EXPECT_EQ(trim(""), "");
  static_assert(trim(" k ") == "k");
}

TEST(OneLine, ReplacesLineBreaksWithBlanks) {
  EXPECT_EQ(one_line("a\nb\r\nc"), "a b  c");
  EXPECT_EQ(one_line("no break"), "no break");
  EXPECT_EQ(one_line(""), "");
}

TEST(AtomicFile, ReplacesTheContentAndLeavesNoTemporary) {
  const fs::path dir = test::fresh_dir("atomic");
  const fs::path file = dir / "a.json";
  write_file_atomically(file, "first");
  write_file_atomically(file, "second\n");
  EXPECT_EQ(test::slurp(file), "second\n");
  EXPECT_FALSE(fs::exists(dir / "a.json.tmp"));
  EXPECT_THROW(write_file_atomically(dir / "no" / "such" / "dir.json", "x"), std::runtime_error);
  fs::remove_all(dir);
}

std::atomic<int> g_previous_calls{0};
extern "C" void previous_handler(int /*signal*/) { ++g_previous_calls; }

TEST(InterruptScope, TermHupAndIntSetTheFlagAndRestoreThePreviousHandler) {
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    std::signal(sig, previous_handler);
    {
      const InterruptScope interrupt;
      EXPECT_FALSE(interrupt.requested());
      EXPECT_EQ(interrupt.exit_code(), 0);
      std::raise(sig);
      EXPECT_TRUE(interrupt.requested());
      EXPECT_TRUE(interrupt.flag()->load());
      EXPECT_EQ(interrupt.signal_number(), sig);
      EXPECT_EQ(interrupt.exit_code(), 128 + sig);
    }
    const int before = g_previous_calls.load();
    std::raise(sig);  // the handler from before the scope is back
    EXPECT_EQ(g_previous_calls.load(), before + 1);
    std::signal(sig, SIG_DFL);
  }
  const InterruptScope fresh;  // a new scope starts unset
  EXPECT_FALSE(fresh.requested());
}

TEST(InterruptScopeDeathTest, ASecondSignalEndsTheProcess) {
  EXPECT_EXIT(
      {
        const InterruptScope interrupt;
        std::raise(SIGTERM);
        std::raise(SIGTERM);
        std::exit(0);  // not reached
      },
      testing::KilledBySignal(SIGTERM), "");
}

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
