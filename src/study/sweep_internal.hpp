// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private machinery shared by the local (sweep.cpp) and the MPI (sweep_mpi.cpp) sweep drivers.

#include <cstdio>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "corlab/core/thread_pool.hpp"
#include "corlab/study/progress.hpp"
#include "corlab/study/results_table.hpp"
#include "corlab/study/sweep.hpp"

namespace corlab::study::detail {

/// What running one case produced.
struct Outcome {
  std::size_t index = 0;  ///< into the expanded case list
  std::string status;     ///< ok | failed | not_separated | interrupted (not recorded)
  std::string line;       ///< the CSV row (empty when interrupted)
  double wall_s = 0.0;    ///< measured wall time of the run [s]
};

inline constexpr std::string_view kInterrupted = "interrupted";

/// Runs case `index` with `runner` (never throws; a failure becomes a `failed` row); `spare`:
/// the pool's threads with no case left (SimulationControl::spare_threads), or null.
Outcome execute_case(const std::vector<SweepCase>& cases,
                     std::size_t index,
                     const std::vector<std::string>& swept_keys,
                     const CaseRunner& runner,
                     const std::atomic<bool>* cancel,
                     std::atomic<int>* spare = nullptr);

/// `Outcome` as one message for MPI ("index\tstatus\twall\tline") and back.
std::string serialize(const Outcome& outcome);
Outcome deserialize(std::string_view message);

/// The sweep's workers: each runs cases and queues the outcomes for the one writer thread.
using WorkerPool = StreamingPool<Outcome>;

/// Hands out the pending case indices in order; stops when cancelled. A worker that finds no
/// case left stops: it counts as a spare thread (spare()) that the running cases' error-bar
/// companions may use (simulate_with_error_estimate).
class CaseQueue {
 public:
  CaseQueue(std::vector<std::size_t> pending, const std::atomic<bool>* cancel)
      : pending_(std::move(pending)), cancel_(cancel) {}
  std::optional<std::size_t> next();
  std::atomic<int>* spare() { return &spare_; }

 private:
  std::atomic<int> spare_{0};
  std::mutex mutex_;
  std::vector<std::size_t> pending_;
  std::size_t next_ = 0;
  const std::atomic<bool>* cancel_;
};

/// The plan of a sweep in out_dir: every case, what is already done, what is pending.
struct Plan {
  std::vector<SweepCase> cases;
  std::vector<std::string> swept_keys;
  std::vector<std::string> header;
  std::vector<std::size_t> pending;
  int already_done = 0;
  std::vector<std::size_t> selected;  ///< the cases this sweep runs (SweepOptions::only or all)
};

/// Expands the spec (every process) and applies the options' case selection and order.
Plan make_plan(const SweepSpec& spec, const SweepOptions& options);
/// Orders plan.pending by decreasing estimated cost (fem::estimate_run_cost), so that a sweep
/// does not end waiting for one long run (longest-processing-time-first scheduling).
void longest_first(Plan& plan);
/// Creates out_dir if needed; InputError if that fails.
void ensure_directory(const std::filesystem::path& out_dir);
/// Prepares out_dir for writing (writer only): directory, spec.toml, resume of results.csv,
/// fills plan.pending / plan.already_done, longest first unless options.spec_order.
void prepare_output(const SweepSpec& spec,
                    const std::filesystem::path& out_dir,
                    const SweepOptions& options,
                    Plan& plan);

/// Throws InputError unless `out_dir` holds no study or this one (same name and [base]; cases
/// and grid values may have been added). Call before spec.toml is overwritten.
void check_same_study(const SweepSpec& spec, const std::filesystem::path& out_dir);

/// Throws InputError naming the case ids that appear more than once in results.csv.
void check_no_duplicate_rows(const std::filesystem::path& csv, const ExistingResults& existing);

/// Exclusive lock on <out_dir>/.sweep.lock for the writer's lifetime (one sweep per directory).
class DirectoryLock {
 public:
  explicit DirectoryLock(const std::filesystem::path& out_dir);
  ~DirectoryLock();
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

 private:
  int fd_ = -1;
};

/// The one writer: appends rows, counts, draws progress.
class Recorder {
 public:
  Recorder(const std::filesystem::path& csv, const Plan& plan, int workers, bool progress);
  void record(const Outcome& outcome);
  /// Lets a terminal progress bar advance its clock between finished cases.
  void tick();
  void finish();
  SweepSummary summary(double wall_s, bool cancelled) const;

 private:
  CsvAppender appender_;
  int total_;
  int already_done_;
  int workers_;
  int ran_ = 0;
  int failed_ = 0;
  int not_separated_ = 0;
  int interrupted_ = 0;
  double wall_sum_ = 0.0;
  std::unique_ptr<ProgressBar> progress_;
};

#ifdef CORLAB_WITH_MPI
/// The distributed driver (sweep_mpi.cpp).
SweepSummary run_sweep_mpi(const SweepSpec& spec,
                           const std::filesystem::path& out_dir,
                           const SweepOptions& options,
                           const CaseRunner& runner,
                           const std::atomic<bool>* cancel);
#endif

}  // namespace corlab::study::detail
