#pragma once
// The one thread pool: the repetitions of an ensemble (for_each_job.hpp) and the units of a
// sweep (parallel/) both run on it. Jobs are numbered; the calling thread submits them one at a
// time and collects each result, in finish order, with any exception the job threw. Submitting a
// job only when a thread is free (has_room) is what deals them dynamically and in the caller's
// order: a thread that finishes takes the next job.
//
// Plain std::thread workers rather than an OpenMP loop: the sweep schedulers need jobs handed in
// one at a time as they arrive (from another MPI rank, say), which a parallel-for cannot do, and
// an exception may not leave an OpenMP region (std::terminate), while here it comes back with
// its job. submit, collect and busy are for one calling thread; the workers only run jobs.
#include <chrono>
#include <condition_variable>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <vector>

namespace sb {

// Threads for a request: `threads` if positive; 0 means all cores, OpenMP's default
// (OMP_NUM_THREADS if set, else every hardware thread this process may run on).
int resolve_threads(int threads);

template <class Result>
class ThreadPool {
 public:
  using Job = std::function<Result(int id)>;
  struct Done {
    int id = 0;
    Result result{};
    std::exception_ptr error;  // the job threw (result then holds nothing)
  };

  ThreadPool(int threads, Job job) : job_(std::move(job)) {
    if (threads < 1) throw std::invalid_argument("a thread pool needs at least one thread");
    workers_.reserve(threads);
    for (int t = 0; t < threads; ++t) workers_.emplace_back([this] { work(); });
  }
  // Jobs still queued are dropped (the run ended, or a job threw); running ones finish first.
  ~ThreadPool() {
    {
      std::lock_guard lock(mu_);
      stop_ = true;
    }
    todo_cv_.notify_all();
    for (auto& w : workers_) w.join();
  }
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()); }
  int busy() const { return busy_; }  // submitted and not yet collected
  bool has_room() const { return busy_ < threads(); }

  void submit(int id) {
    {
      std::lock_guard lock(mu_);
      todo_.push_back(id);
      ++busy_;
    }
    todo_cv_.notify_one();
  }

  // The next finished job, waiting at most `wait`; nothing on timeout.
  std::optional<Done> collect(std::chrono::milliseconds wait) {
    std::unique_lock lock(mu_);
    if (!done_cv_.wait_for(lock, wait, [&] { return !done_.empty(); })) return std::nullopt;
    Done d = std::move(done_.front());
    done_.pop_front();
    --busy_;
    return d;
  }

 private:
  void work() {
    for (;;) {
      Done d;
      {
        std::unique_lock lock(mu_);
        todo_cv_.wait(lock, [&] { return stop_ || !todo_.empty(); });
        if (stop_) return;
        d.id = todo_.front();
        todo_.pop_front();
      }
      try {
        d.result = job_(d.id);
      } catch (...) {
        d.error = std::current_exception();
      }
      {
        std::lock_guard lock(mu_);
        done_.push_back(std::move(d));
      }
      done_cv_.notify_one();
    }
  }

  Job job_;
  std::mutex mu_;
  std::condition_variable todo_cv_, done_cv_;
  std::deque<int> todo_;
  std::deque<Done> done_;
  bool stop_ = false;
  int busy_ = 0;
  std::vector<std::thread> workers_;
};

}  // namespace sb
