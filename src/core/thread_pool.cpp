// SPDX-License-Identifier: BSD-3-Clause
#include "corlab/core/thread_pool.hpp"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace corlab {

WorkerThreads::WorkerThreads(std::size_t threads, const std::function<void()>& work) {
  threads_.reserve(threads);
  for (std::size_t t = 0; t < threads; ++t) threads_.emplace_back(work);
}

WorkerThreads::~WorkerThreads() { join(); }

void WorkerThreads::join() {
  for (auto& thread : threads_) {
    if (thread.joinable()) thread.join();
  }
}

int worker_count(int jobs) {
  if (jobs > 0) return jobs;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void parallel_for(std::size_t count,
                  int workers,
                  const std::function<void(std::size_t)>& job,
                  const std::atomic<bool>* cancel) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  const auto stop = [&] { return failed.load() || (cancel != nullptr && cancel->load()); };
  const auto work = [&] {
    for (std::size_t i = next++; i < count && !stop(); i = next++) {
      try {
        job(i);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        failed.store(true);
      }
    }
  };
  const auto threads = std::min(static_cast<std::size_t>(worker_count(workers)), count);
  WorkerThreads pool(threads > 0 ? threads - 1 : 0, work);
  work();  // this thread is one of the workers
  pool.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace corlab
