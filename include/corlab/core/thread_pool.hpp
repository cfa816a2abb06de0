// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/// @file thread_pool.hpp
/// The one way corlab runs independent jobs on threads: WorkerThreads owns the threads;
/// parallel_for (wait for all jobs) and StreamingPool (take each result as it finishes, for the
/// sweep's one writer) are built on it.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <iterator>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

namespace corlab {

/// Threads to use for `jobs` (> 0: that many; 0: one per hardware thread, at least 1).
int worker_count(int jobs);

/// `threads` threads that each run `work()` once; joined by join() or the destructor (never
/// detached). `work` must not throw (wrap the jobs it runs).
class WorkerThreads {
 public:
  WorkerThreads(std::size_t threads, const std::function<void()>& work);
  ~WorkerThreads();
  WorkerThreads(const WorkerThreads&) = delete;
  WorkerThreads& operator=(const WorkerThreads&) = delete;
  void join();

 private:
  std::vector<std::thread> threads_;
};

/// Runs job(0) ... job(count - 1) on min(workers, count) threads (workers as in worker_count());
/// each thread takes the next index until none is left or `cancel` is set. job must be
/// thread-safe. Waits for every thread; the first exception a job threw is then rethrown (the
/// other threads finish their current job and take no new one).
void parallel_for(std::size_t count,
                  int workers,
                  const std::function<void(std::size_t)>& job,
                  const std::atomic<bool>* cancel = nullptr);

/// Worker threads that each take a job index from `next` (thread-safe; nullopt = stop), run it
/// and queue its result, which the owning thread takes as they finish (take()). `run` must not
/// throw (a sweep turns a failure into a row).
template <class Result>
class StreamingPool {
 public:
  using Source = std::function<std::optional<std::size_t>()>;
  using Run = std::function<Result(std::size_t)>;

  StreamingPool(int threads, const Source& next, const Run& run)
      : running_(threads), workers_(static_cast<std::size_t>(threads), [this, next, run] {
          while (const auto index = next()) {
            Result result = run(*index);
            const std::lock_guard lock(mutex_);
            results_.push_back(std::move(result));
            ready_.notify_all();
          }
          const std::lock_guard lock(mutex_);
          --running_;
          ready_.notify_all();
        }) {}

  /// Results queued so far (waits up to `timeout` for the first one).
  std::vector<Result> take(std::chrono::milliseconds timeout) {
    std::unique_lock lock(mutex_);
    ready_.wait_for(lock, timeout, [this] { return !results_.empty() || running_ == 0; });
    std::vector<Result> taken(std::make_move_iterator(results_.begin()),
                              std::make_move_iterator(results_.end()));
    results_.clear();
    return taken;
  }
  /// All workers have stopped (their results may still be queued).
  bool stopped() const {
    const std::lock_guard lock(mutex_);
    return running_ == 0;
  }
  void join() { workers_.join(); }

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<Result> results_;
  int running_;
  WorkerThreads workers_;  // last: its threads start once the members above exist
};

}  // namespace corlab
