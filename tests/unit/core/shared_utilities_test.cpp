// The shared utilities of core/: trim, one_line, the atomic file writer, the interrupt handler and
// the thread pool.
#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "corlab/core/atomic_file.hpp"
#include "corlab/core/interrupt.hpp"
#include "corlab/core/text.hpp"
#include "corlab/core/thread_pool.hpp"

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
  const fs::path dir = fs::temp_directory_path() / "corlab_atomic_file_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path file = dir / "a.json";
  write_file_atomically(file, "first");
  write_file_atomically(file, "second\n");
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "second\n");
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

}  // namespace
}  // namespace corlab
