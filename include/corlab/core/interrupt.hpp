// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file interrupt.hpp
/// The one interrupt handler of the CLI: SIGINT (Ctrl-C), SIGTERM (kill, job schedulers) and
/// SIGHUP (closed terminal) ask a long run to stop cleanly (finished work is kept); a second
/// signal stops the process at once (the default action).
///
///   InterruptScope interrupt;                 // installs the handlers
///   options.cancel = interrupt.flag();        // the run polls it
///   run(options);
///   if (interrupt.requested()) { print one line; return interrupt.exit_code(); }

#include <atomic>

namespace corlab {

/// While alive, SIGINT, SIGTERM and SIGHUP set flag() instead of ending the process; the first
/// signal also restores the default action, so a second one ends it at once. The destructor
/// restores the handlers that were installed before. One scope at a time (the flag is global:
/// signal handlers cannot carry state).
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;

  /// Set by the first signal; for SimulationControl::cancel, SweepOptions::cancel ...
  const std::atomic<bool>* flag() const;
  /// True once a signal arrived.
  bool requested() const;
  /// The signal that arrived (SIGINT, SIGTERM, SIGHUP), 0 if none.
  int signal_number() const;
  /// The shell's exit status for it: 128 + signal number (130 for Ctrl-C), 0 if none.
  int exit_code() const;
  /// The signal's name ("SIGINT", "SIGTERM", "SIGHUP"), "" if none.
  const char* signal_name() const;
};

}  // namespace corlab
