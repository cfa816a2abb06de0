// The interrupt handler (interrupt.hpp): SIGINT, SIGTERM and SIGHUP set the flag, the previous
// handlers come back, a second signal ends the process.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/interrupt.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <csignal>
#include <cstdlib>

namespace corlab {
namespace {

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

}  // namespace
}  // namespace corlab
