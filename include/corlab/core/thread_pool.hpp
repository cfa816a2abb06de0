#pragma once
/// @file thread_pool.hpp
/// The one way corlab runs independent jobs on threads.

#include <atomic>
#include <cstddef>
#include <functional>

namespace corlab {

/// Threads to use for `jobs` (> 0: that many; 0: one per hardware thread, at least 1).
int worker_count(int jobs);

/// Runs job(0) ... job(count - 1) on min(workers, count) threads (workers as in worker_count());
/// each thread takes the next index until none is left or `cancel` is set. job must be
/// thread-safe. Waits for every thread; the first exception a job threw is then rethrown (the
/// other threads finish their current job and take no new one).
void parallel_for(std::size_t count,
                  int workers,
                  const std::function<void(std::size_t)>& job,
                  const std::atomic<bool>* cancel = nullptr);

}  // namespace corlab
