// Distributed sweep over MPI ranks (compiled with CORLAB_WITH_MPI).
//
// Design (MPI_THREAD_FUNNELED: only each rank's main thread calls MPI):
//  - rank 0 is coordinator and the only writer. It owns the queue of pending case indices, runs
//    `jobs` cases itself in worker threads, answers work requests of the other ranks with the next
//    index (or -1 = no more) and appends every finished row (its own and received ones) to
//    results.csv through one Recorder.
//  - every other rank runs `jobs` worker threads fed by its main thread, which requests one index
//    at a time from rank 0 whenever a thread is idle and sends each outcome back as a string.
//  - dynamic distribution: a rank asks for the next case when it is free, so slow and fast
//    cases balance themselves.
// SPDX-License-Identifier: BSD-3-Clause
#ifdef CORLAB_WITH_MPI

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <deque>

#include "corlab/core/error.hpp"
#include "sweep_internal.hpp"

namespace corlab::study::detail {
namespace {

enum Tag : int { kRequest = 1, kAssign = 2, kResult = 3, kWorkerDone = 4 };
constexpr auto kPoll = std::chrono::milliseconds(5);
using Clock = std::chrono::steady_clock;

void ensure_mpi() {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (initialized != 0) {
    int finalized = 0;
    MPI_Finalized(&finalized);
    if (finalized != 0)
      throw std::runtime_error("MPI was finalised: one distributed sweep per process");
    return;
  }
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  if (provided < MPI_THREAD_FUNNELED) {
    throw std::runtime_error("the MPI library does not support MPI_THREAD_FUNNELED");
  }
  std::atexit([] {
    int done = 0;
    MPI_Finalized(&done);
    if (done == 0) MPI_Finalize();
  });
}

void bcast_string(std::string& text) {
  int size = static_cast<int>(text.size());
  MPI_Bcast(&size, 1, MPI_INT, 0, MPI_COMM_WORLD);
  text.resize(static_cast<std::size_t>(size));
  if (size > 0) MPI_Bcast(text.data(), size, MPI_CHAR, 0, MPI_COMM_WORLD);
}

/// Work fed to a worker rank's threads by its main thread.
class Feed {
 public:
  std::optional<std::size_t> next() {
    std::unique_lock lock(mutex_);
    ++waiting_;
    ready_.wait(lock, [this] { return !queue_.empty() || closed_; });
    --waiting_;
    if (queue_.empty()) return std::nullopt;
    const std::size_t index = queue_.front();
    queue_.pop_front();
    return index;
  }
  void push(std::size_t index) {
    const std::lock_guard lock(mutex_);
    queue_.push_back(index);
    ready_.notify_one();
  }
  void close() {
    const std::lock_guard lock(mutex_);
    closed_ = true;
    ready_.notify_all();
  }
  /// More threads idle than queued indices.
  bool wants_work() {
    const std::lock_guard lock(mutex_);
    return waiting_ > static_cast<int>(queue_.size());
  }

 private:
  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::size_t> queue_;
  bool closed_ = false;
  int waiting_ = 0;
};

SweepSummary coordinate(const Plan& plan,
                        const std::filesystem::path& out_dir,
                        const SweepOptions& options,
                        const CaseRunner& runner,
                        const std::atomic<bool>* cancel,
                        int jobs,
                        int size,
                        Clock::time_point start) {
  Recorder recorder(out_dir / "results.csv", plan, jobs * size, options.progress);
  CaseQueue queue(plan.pending, cancel);
  int outstanding = 0;  // cases handed to other ranks and not yet reported
  int workers_done = 0;
  {
    WorkerPool pool(
        plan.pending.empty() ? 0 : std::min(jobs, static_cast<int>(plan.pending.size())),
        [&queue] { return queue.next(); },
        [&](std::size_t index) {
          return execute_case(plan.cases, index, plan.swept_keys, runner, cancel);
        });
    while (true) {
      int flag = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      const bool message = flag != 0;
      while (flag != 0) {
        const int source = status.MPI_SOURCE;
        if (status.MPI_TAG == kRequest) {
          int unused = 0;
          MPI_Recv(&unused, 1, MPI_INT, source, kRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          const auto index = queue.next();
          long long assigned = index ? static_cast<long long>(*index) : -1;
          MPI_Send(&assigned, 1, MPI_LONG_LONG, source, kAssign, MPI_COMM_WORLD);
          if (index) ++outstanding;
        } else if (status.MPI_TAG == kResult) {
          int count = 0;
          MPI_Get_count(&status, MPI_CHAR, &count);
          std::string text(static_cast<std::size_t>(count), '\0');
          MPI_Recv(text.data(), count, MPI_CHAR, source, kResult, MPI_COMM_WORLD,
                   MPI_STATUS_IGNORE);
          recorder.record(deserialize(text));
          --outstanding;
        } else if (status.MPI_TAG == kWorkerDone) {
          int unused = 0;
          MPI_Recv(&unused, 1, MPI_INT, source, kWorkerDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          ++workers_done;
        } else {
          throw std::runtime_error(fmt::format("unexpected MPI tag {}", status.MPI_TAG));
        }
        MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
      }
      const bool stopped = pool.stopped();  // before take(): no local outcome is missed
      const auto outcomes = pool.take(message ? std::chrono::milliseconds(0) : kPoll);
      for (const auto& outcome : outcomes) recorder.record(outcome);
      recorder.tick();
      if (stopped && workers_done == size - 1 && outstanding == 0) break;
      if (stopped && !message && outcomes.empty()) std::this_thread::sleep_for(kPoll);
    }
    pool.join();
  }
  recorder.finish();
  return recorder.summary(std::chrono::duration<double>(Clock::now() - start).count(),
                          cancel->load());
}

void work(const Plan& plan, const CaseRunner& runner, const std::atomic<bool>* cancel, int jobs) {
  Feed feed;
  bool exhausted = false;
  bool in_flight = false;
  {
    WorkerPool pool(
        jobs, [&feed] { return feed.next(); },
        [&](std::size_t index) {
          return execute_case(plan.cases, index, plan.swept_keys, runner, cancel);
        });
    while (true) {
      const bool stopped = pool.stopped();
      for (const auto& outcome : pool.take(kPoll)) {
        const std::string text = serialize(outcome);
        MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kResult, MPI_COMM_WORLD);
      }
      if (cancel->load() && !exhausted) {
        exhausted = true;
        feed.close();
      }
      if (!exhausted && !in_flight && feed.wants_work()) {
        int unused = 0;
        MPI_Send(&unused, 1, MPI_INT, 0, kRequest, MPI_COMM_WORLD);
        in_flight = true;
      }
      if (in_flight) {
        int flag = 0;
        MPI_Iprobe(0, kAssign, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
        if (flag != 0) {
          long long assigned = -1;
          MPI_Recv(&assigned, 1, MPI_LONG_LONG, 0, kAssign, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          in_flight = false;
          if (assigned < 0) {
            exhausted = true;
            feed.close();
          } else if (exhausted) {  // cancelled meanwhile: give the case back unrun
            Outcome outcome;
            outcome.index = static_cast<std::size_t>(assigned);
            outcome.status = kInterrupted;
            const std::string text = serialize(outcome);
            MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, kResult,
                     MPI_COMM_WORLD);
          } else {
            feed.push(static_cast<std::size_t>(assigned));
          }
        }
      }
      if (exhausted && !in_flight && stopped) break;
    }
    pool.join();
  }
  int unused = 0;
  MPI_Send(&unused, 1, MPI_INT, 0, kWorkerDone, MPI_COMM_WORLD);
}

}  // namespace

SweepSummary run_sweep_mpi(const SweepSpec& spec,
                           const std::filesystem::path& out_dir,
                           const SweepOptions& options,
                           const CaseRunner& runner,
                           const std::atomic<bool>* cancel) {
  const auto start = Clock::now();
  ensure_mpi();
  int rank = 0;
  int size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const int jobs = options.jobs > 0 ? options.jobs : 1;  // one run per rank by default

  Plan plan = make_plan(spec, options);
  // Every rank must have expanded the same cases (same spec file on every node).
  std::string ids;
  for (const auto& c : plan.cases) ids += c.id;
  std::string root_ids = ids;
  bcast_string(root_ids);
  int mismatch = root_ids == ids ? 0 : 1;
  MPI_Allreduce(MPI_IN_PLACE, &mismatch, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  if (mismatch != 0) {
    throw InputError(
        fmt::format("invalid spec {}: must be the same file on every MPI rank", spec.origin));
  }

  // Rank 0 prepares the output; every rank learns whether that worked.
  std::unique_ptr<DirectoryLock> lock;
  std::string error;
  if (rank == 0) {
    try {
      ensure_directory(out_dir);
      lock = std::make_unique<DirectoryLock>(out_dir);
      prepare_output(spec, out_dir, options, plan);
    } catch (const std::exception& err) {
      error = err.what();
    }
  }
  bcast_string(error);
  if (!error.empty()) throw InputError(error);

  SweepSummary summary;
  try {
    if (rank == 0) {
      summary = coordinate(plan, out_dir, options, runner, cancel, jobs, size, start);
    } else {
      work(plan, runner, cancel, jobs);
    }
  } catch (const std::exception& err) {
    std::fprintf(stderr, "corlab: rank %d: %s\n", rank, err.what());
    MPI_Abort(MPI_COMM_WORLD, 3);
  }
  double fields[9] = {
      double(summary.total),           double(summary.already_done),  double(summary.ran),
      double(summary.failed),          double(summary.not_separated), summary.wall_s,
      summary.interrupted ? 1.0 : 0.0, double(summary.workers),       0.0};
  MPI_Bcast(fields, 9, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  summary.total = static_cast<int>(fields[0]);
  summary.already_done = static_cast<int>(fields[1]);
  summary.ran = static_cast<int>(fields[2]);
  summary.failed = static_cast<int>(fields[3]);
  summary.not_separated = static_cast<int>(fields[4]);
  summary.wall_s = fields[5];
  summary.interrupted = fields[6] != 0.0;
  summary.workers = static_cast<int>(fields[7]);
  summary.rank = rank;
  summary.ranks = size;
  return summary;
}

}  // namespace corlab::study::detail

#endif  // CORLAB_WITH_MPI
