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

}  // namespace corlab
