// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file progress.hpp
/// Progress display of a sweep on stderr: done/total, percent, elapsed time and ETA. On a
/// terminal one line is redrawn with '\r' (at most every 0.2 s); otherwise (CI logs) plain lines
/// are printed, at most one per 5 s, plus the final state.

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>

namespace corlab::study {

/// Remaining time estimate [s]: mean wall time of the finished cases x remaining cases / workers.
/// Returns a negative value when nothing has finished yet (unknown).
double eta_seconds(double mean_case_wall_s, int remaining, int workers);

/// "1h02m", "3m05s", "12s", "--" for a negative value.
std::string format_duration(double seconds);

/// One progress text, e.g. "[#####.....] 12/24  50%  elapsed 3m05s  ETA 3m05s  (1 failed)".
std::string progress_text(int done, int total, double elapsed_s, double eta_s, int failed);

/// Progress of one run as a callback taking the fraction done (0..1): on a terminal one line
/// redrawn with carriage returns (at most every 0.5 s); otherwise (a log file, a pipe) plain lines
/// "<label>: 42.0 %" at most every 10 s, so that logs hold no control characters.
std::function<void(double)> fraction_progress(std::FILE* out, std::string label);

class ProgressBar {
 public:
  /// @param out       stream (stderr in the CLI); null disables output
  /// @param total     number of cases in the sweep (finished ones included)
  /// @param workers   cases run at the same time, for the ETA
  /// @param terminal  redraw one line; default: isatty(out)
  ProgressBar(std::FILE* out, int total, int workers, int terminal = -1);
  /// Records `done` finished cases (already-finished ones included), `failed` of them failed,
  /// the mean wall time [s] of the cases run here; redraws if due (or if `force`).
  void update(int done, int failed, double mean_case_wall_s, bool force = false);
  /// Redraws a terminal line once a second so that the elapsed time moves between cases.
  void tick();
  /// Final redraw and a line break on a terminal.
  void finish();

 private:
  std::FILE* out_;
  int total_;
  int workers_;
  bool terminal_;
  int done_ = 0;
  int failed_ = 0;
  double mean_wall_ = -1.0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_{};
  bool drawn_ = false;
  void draw();
};

}  // namespace corlab::study
