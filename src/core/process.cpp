// run_process: posix_spawn + waitpid, no shell.
// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/process.hpp"

#include <pthread.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>  // environ (declared with _GNU_SOURCE, which g++ and clang++ define)

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "corlab/core/interrupt.hpp"

namespace corlab {

namespace {

/// Starts argv; `attributes` may be null (the child inherits this process's signal state).
pid_t spawn(const std::vector<std::string>& argv, const posix_spawnattr_t* attributes) {
  if (argv.empty()) throw std::invalid_argument("run_process: no program given");
  std::vector<char*> args;
  args.reserve(argv.size() + 1);
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  const int err = ::posix_spawn(&pid, argv[0].c_str(), nullptr, attributes, args.data(), environ);
  if (err != 0) {
    throw std::runtime_error("cannot start '" + argv[0] + "': " + std::strerror(err));
  }
  return pid;
}

int exit_status(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 1;
}

/// The child's signals under run_process(argv, interrupt): SIGINT, SIGTERM, SIGHUP at their
/// default action, SIGINT blocked. A Ctrl-C reaches the whole process group; blocked, it cannot
/// raise a KeyboardInterrupt traceback in a Python child: the parent, which caught it too, ends
/// the child with SIGTERM.
struct ChildSignals {
  posix_spawnattr_t attributes{};
  ChildSignals() {
    posix_spawnattr_init(&attributes);
    sigset_t defaults;
    sigemptyset(&defaults);
    for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&defaults, s);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    sigset_t mask;
    pthread_sigmask(SIG_SETMASK, nullptr, &mask);
    sigaddset(&mask, SIGINT);
    posix_spawnattr_setsigmask(&attributes, &mask);
    posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  }
  ~ChildSignals() { posix_spawnattr_destroy(&attributes); }
  ChildSignals(const ChildSignals&) = delete;
  ChildSignals& operator=(const ChildSignals&) = delete;
};

}  // namespace

int run_process(const std::vector<std::string>& argv) {
  const pid_t pid = spawn(argv, nullptr);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      throw std::runtime_error("waiting for '" + argv[0] + "' failed: " + std::strerror(errno));
    }
  }
  return exit_status(status);
}

int run_process(const std::vector<std::string>& argv, const InterruptScope& interrupt) {
  const ChildSignals signals;
  const pid_t pid = spawn(argv, &signals.attributes);
  bool passed_on = false;
  int status = 0;
  // Polled (not a blocking wait): a signal that lands just before waitpid would not wake it.
  while (true) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {
      throw std::runtime_error("waiting for '" + argv[0] + "' failed: " + std::strerror(errno));
    }
    if (interrupt.requested() && !passed_on) {
      const int signal = interrupt.signal_number();
      ::kill(pid, signal == SIGINT ? SIGTERM : signal);  // SIGINT is blocked in the child
      passed_on = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return exit_status(status);
}

}  // namespace corlab
