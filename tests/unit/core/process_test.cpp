// run_process: exit status of a program started without a shell; a missing program.
#include "corlab/core/process.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

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
