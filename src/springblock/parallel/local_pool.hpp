#pragma once
// A rank's threads: units submitted one at a time, each run on a free thread, results collected
// in finish order. Both schedulers run their units here; the calling thread only hands out work
// and collects (under MPI it is also the only thread that talks to other ranks).
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "springblock/parallel/scheduler.hpp"

namespace sb::parallel {

struct Done {
  int id = 0;
  nlohmann::json record;       // null when interrupted
  std::exception_ptr error;    // the unit threw
};

class LocalPool {
 public:
  LocalPool(int threads, UnitRunner run, const std::atomic<bool>* interrupt);
  ~LocalPool();
  LocalPool(const LocalPool&) = delete;
  LocalPool& operator=(const LocalPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()); }
  int busy() const { return busy_; }  // submitted and not yet collected
  bool has_room() const { return busy_ < threads(); }
  void submit(int id);
  // The next finished unit, waiting at most `wait`; nothing on timeout.
  std::optional<Done> collect(std::chrono::milliseconds wait);

 private:
  void work();

  UnitRunner run_;
  const std::atomic<bool>* interrupt_;
  std::mutex mu_;
  std::condition_variable todo_cv_, done_cv_;
  std::deque<int> todo_;
  std::deque<Done> done_;
  bool stop_ = false;
  int busy_ = 0;
  std::vector<std::thread> workers_;
};

// Threads for a rank: `threads`, or OpenMP's default for 0.
int resolve_threads(int threads);

}  // namespace sb::parallel
