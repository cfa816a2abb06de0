// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Long C++ work that Ctrl-C can stop: run without the GIL in a thread while this thread checks
// Python's signals every 100 ms.

#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <future>

namespace corlab::python {

/// Runs `work()` (which must not touch Python objects) in a thread with the GIL released; a
/// pending signal (Ctrl-C: KeyboardInterrupt) sets `cancel`, which the work polls. Returns the
/// work's result, or raises KeyboardInterrupt once cancelled (after the work has stopped).
/// Exceptions of the work propagate (InputError as ValueError).
template <class Work>
auto run_interruptible(std::atomic<bool>& cancel, Work work) -> decltype(work()) {
  namespace py = pybind11;
  std::future<decltype(work())> done;
  {
    py::gil_scoped_release release;
    done = std::async(std::launch::async, work);
    while (done.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) {
        cancel.store(true);
        PyErr_Clear();
      }
    }
  }
  auto result = done.get();
  if (cancel.load()) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  return result;
}

}  // namespace corlab::python
