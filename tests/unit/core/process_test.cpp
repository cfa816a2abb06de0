// run_process: exit status of a program started without a shell; a missing program.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/process.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <stdexcept>
#include <string>
#include <thread>

#include "corlab/core/interrupt.hpp"

namespace corlab {
namespace {

TEST(RunProcess, ReturnsTheExitStatus) {
  EXPECT_EQ(run_process({"/bin/sh", "-c", "exit 3"}), 3);
  EXPECT_EQ(run_process({"/bin/sh", "-c", "exit 0"}), 0);
}

TEST(RunProcess, PassesArgumentsWithoutAShell) {
  // "$1" is the second argument as given: quotes and spaces reach the program unchanged.
  EXPECT_EQ(run_process({"/bin/sh", "-c", "test \"$1\" = \"a 'b' c\"", "sh", "a 'b' c"}), 0);
}

TEST(RunProcess, ReportsASignalAs128PlusItsNumber) {
  EXPECT_EQ(run_process({"/bin/sh", "-c", "kill -TERM $$"}), 128 + 15);
}

// issue 31 item 9: a SIGTERM to `corlab reproduce` during its report was ignored (report written,
// exit 0) and a Ctrl-C gave a Python traceback.
TEST(RunProcess, PassesOnASignalTheCallerCaught) {
  for (const int signal : {SIGTERM, SIGHUP, SIGINT}) {
    const InterruptScope interrupt;
    std::thread sender([signal] {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      ::kill(::getpid(), signal);
    });
    const auto start = std::chrono::steady_clock::now();
    const int status = run_process({"/bin/sleep", "20"}, interrupt);
    sender.join();
    EXPECT_TRUE(interrupt.requested());
    EXPECT_EQ(interrupt.signal_number(), signal);
    // SIGINT is passed on as SIGTERM (the child has SIGINT blocked)
    EXPECT_EQ(status, 128 + (signal == SIGINT ? SIGTERM : signal));
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  }
}

TEST(RunProcess, TheChildHasCtrlCBlockedSoPythonPrintsNoTraceback) {
  const InterruptScope interrupt;
  // A SIGINT the child sends itself stays pending: no KeyboardInterrupt, it ends with its own
  // status.
  EXPECT_EQ(run_process({"/usr/bin/python3", "-c",
                         "import os, signal, sys; os.kill(os.getpid(), signal.SIGINT); "
                         "sys.exit(7)"},
                        interrupt),
            7);
  EXPECT_FALSE(interrupt.requested());
  EXPECT_EQ(run_process({"/bin/sh", "-c", "exit 3"}, interrupt), 3);
}

TEST(RunProcess, AMissingProgramThrowsNamingIt) {
  try {
    run_process({"/nonexistent/corlab-no-such-program", "x"});
    FAIL() << "no exception";
  } catch (const std::runtime_error& err) {
    const std::string msg = err.what();
    EXPECT_NE(msg.find("/nonexistent/corlab-no-such-program"), std::string::npos) << msg;
    EXPECT_NE(msg.find("cannot start"), std::string::npos) << msg;
  }
  EXPECT_THROW(run_process({}), std::invalid_argument);
}

}  // namespace
}  // namespace corlab
