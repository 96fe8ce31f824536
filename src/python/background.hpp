#pragma once
// Long library calls from Python (run, sweep, design) run on a thread of their own while the
// calling thread, without the GIL, wakes every 0.1 s to take the GIL, let Python handle signals
// and report progress. So other Python threads go on, Ctrl-C stops the work cleanly (the library
// polls the interrupt flag and returns what it finished), and a progress callback runs on the
// Python thread that made the call, with the GIL held: never on a worker thread.
#include <atomic>
#include <chrono>
#include <exception>
#include <future>
#include <mutex>
#include <optional>

#include "bindings.hpp"

namespace sb::python {

// The latest progress a worker thread posted, taken by the Python thread (each value once).
template <class T>
class Latest {
 public:
  void post(T value) {
    std::lock_guard<std::mutex> lock(mutex_);
    value_ = std::move(value);
  }
  std::optional<T> take() {
    std::lock_guard<std::mutex> lock(mutex_);
    auto out = std::move(value_);
    value_.reset();
    return out;
  }

 private:
  std::mutex mutex_;
  std::optional<T> value_;
};

// Runs `work(interrupt)` in the background and returns its result. `poll()` is called with the GIL
// held at every wake-up and once at the end; a Python exception it raises (a progress callback's)
// sets the interrupt like Ctrl-C does. Either way the exception is raised here once the work has
// stopped, so what it finished (a sweep's checkpoint) is in place.
template <class Work, class Poll>
auto in_background(Work work, Poll poll) {
  std::atomic<bool> interrupt{false};
  std::optional<py::error_already_set> raised;
  decltype(work(&interrupt)) out;
  auto check = [&] {
    if (raised) return;
    try {
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      poll();
    } catch (py::error_already_set& e) {
      raised.emplace(std::move(e));
      interrupt = true;
    }
  };
  {
    py::gil_scoped_release release;
    auto job = std::async(std::launch::async, [&] { return work(&interrupt); });
    while (job.wait_for(std::chrono::milliseconds(100)) != std::future_status::ready) {
      py::gil_scoped_acquire acquire;
      check();
    }
    out = job.get();
  }
  check();
  if (raised) throw std::move(*raised);
  return out;
}

template <class Work>
auto in_background(Work work) {
  return in_background(work, [] {});
}

}  // namespace sb::python
