// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/interrupt.hpp"

#include <array>
#include <csignal>

namespace corlab {
namespace {

constexpr std::array kSignals{SIGINT, SIGTERM, SIGHUP};

std::atomic<bool> g_requested{false};
std::atomic<int> g_signal{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "signal handlers may only touch lock-free atomics");
std::array<struct sigaction, kSignals.size()> g_previous{};

extern "C" void on_signal(int signal_number) {
  g_signal.store(signal_number);
  g_requested.store(true);
  // The next signal of this kind ends the process (the run stops at its next poll otherwise).
  std::signal(signal_number, SIG_DFL);
}

}  // namespace

InterruptScope::InterruptScope() {
  g_requested.store(false);
  g_signal.store(0);
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    sigaction(kSignals[i], &action, &g_previous[i]);
  }
}

InterruptScope::~InterruptScope() {
  for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
}

const std::atomic<bool>* InterruptScope::flag() const { return &g_requested; }

bool InterruptScope::requested() const { return g_requested.load(); }

int InterruptScope::signal_number() const { return g_signal.load(); }

int InterruptScope::exit_code() const { return requested() ? 128 + signal_number() : 0; }

const char* InterruptScope::signal_name() const {
  switch (signal_number()) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "";
  }
}

}  // namespace corlab
