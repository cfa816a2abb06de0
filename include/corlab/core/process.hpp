// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file process.hpp
/// Starting another program without a shell.

#include <string>
#include <vector>

namespace corlab {

/// Runs the program argv[0] (a path; no PATH search, no shell: the arguments reach it as they
/// are) with the arguments argv[1..], the environment of this process and its stdin, stdout and
/// stderr; waits for it and returns its exit status (0-255), or 128 + the signal number when a
/// signal ended it. Throws std::runtime_error naming the program and the reason when it cannot be
/// started (missing, not executable) and std::invalid_argument when argv is empty.
int run_process(const std::vector<std::string>& argv);

class InterruptScope;

/// run_process, stoppable: when `interrupt` catches a signal (SIGINT, SIGTERM, SIGHUP) while the
/// program runs, it is passed on to the program once (SIGINT as SIGTERM) and its end awaited, so
/// the caller can exit 128 + signal instead of finishing after it (a SIGTERM during the report was
/// ignored). The program starts with those three signals at their default action and SIGINT
/// blocked: a Ctrl-C, which reaches the whole process group, never meets a Python
/// KeyboardInterrupt handler (it printed a traceback); the caller ends the program instead.
int run_process(const std::vector<std::string>& argv, const InterruptScope& interrupt);

}  // namespace corlab
