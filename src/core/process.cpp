// run_process: posix_spawn + waitpid, no shell.
#include "corlab/core/process.hpp"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>  // environ (declared with _GNU_SOURCE, which g++ and clang++ define)

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace corlab {

int run_process(const std::vector<std::string>& argv) {
  if (argv.empty()) throw std::invalid_argument("run_process: no program given");
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int err = ::posix_spawn(&pid, argv[0].c_str(), nullptr, nullptr, args.data(), environ);
  if (err != 0) {
    throw std::runtime_error("cannot start '" + argv[0] + "': " + std::strerror(err));
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      throw std::runtime_error("waiting for '" + argv[0] + "' failed: " + std::strerror(errno));
    }
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 1;
}

}  // namespace corlab
