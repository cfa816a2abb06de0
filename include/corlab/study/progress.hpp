// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file progress.hpp
/// Progress display of a sweep on stderr: done/total, percent, elapsed time and ETA. On a
/// terminal one line is redrawn with '\r' (at most every 0.2 s); otherwise (CI logs) plain lines
/// are printed, at most one per 5 s, plus the final state.

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

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

/// Time left of a job whose runs' costs are estimated beforehand (any unit, e.g. element-steps)
/// [s]: the cost left over the rate measured so far, remaining_cost x elapsed_s / done_cost.
/// `done_cost` counts only what ran in this process (not what was found finished on disk).
/// Negative (unknown) while nothing is done; 0 when nothing remains.
double remaining_seconds(double remaining_cost, double done_cost, double elapsed_s);

/// One line of a staged job, e.g. "[########................]  34%  table2 60/165  elapsed 2m10s
/// left 4m05s"; `fraction` of the whole job's cost (clamped to 0..1), `left_s` < 0 prints "--".
std::string work_progress_text(double fraction,
                               const std::string& stage,
                               int stage_done,
                               int stage_runs,
                               double elapsed_s,
                               double left_s);

/// Progress of a job made of stages (the studies of `corlab reproduce`) whose runs' costs are
/// estimated beforehand: one line for the whole job with the fraction of its cost done, the
/// stage, the elapsed time and the time left at the measured rate (remaining_seconds).
/// Thread-safe. On a terminal the line is redrawn at every finished run and once a second (by
/// its own thread), and log lines are printed above it; otherwise (a log file, a pipe) a plain
/// line at each stage and at most every 10 s.
class WorkProgress {
 public:
  /// @param out         stream (stderr in the CLI); null disables output
  /// @param total_cost  estimated cost of every run of the job, done on disk or not [cost unit]
  /// @param terminal    redraw one line; default: isatty(out)
  WorkProgress(std::FILE* out, double total_cost, int terminal = -1);
  ~WorkProgress();
  WorkProgress(const WorkProgress&) = delete;
  WorkProgress& operator=(const WorkProgress&) = delete;

  /// Starts a stage of `runs` runs, `runs_done` of which, costing `skipped_cost`, were found done
  /// on disk; prints `line` (its title) first unless empty.
  void stage(const std::string& name,
             int runs,
             int runs_done,
             double skipped_cost,
             const std::string& line = "");
  /// One run of the stage finished: `cost` done here (`ran_here`) or found done on disk.
  void done(double cost, bool ran_here = true);
  /// Prints one line (above the progress line on a terminal).
  void log(const std::string& line);
  /// Final line; stops the redraw thread.
  void finish();

 private:
  std::FILE* out_;
  double total_;
  bool terminal_;
  std::mutex mutex_;
  std::condition_variable_any wake_;
  std::string stage_;
  int stage_runs_ = 0;
  int stage_done_ = 0;
  double done_here_ = 0.0;
  double done_disk_ = 0.0;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_{};
  bool finished_ = false;
  bool drawn_latest_ = false;  ///< the last line drawn shows every finished run
  std::jthread ticker_;
  void draw_locked();
  void print_locked(const std::string& line);
  void maybe_draw_locked(bool force);
};

}  // namespace corlab::study
