#pragma once
// The one thread pool: the repetitions of an ensemble (for_each_job.hpp) and the units of a
// sweep (parallel/) both run on it. Jobs are numbered and queued in the caller's order; a thread
// that finishes a job takes the next in the queue, so they are dealt dynamically and in order.
// The caller collects each result, in finish order, with any exception the job threw. A sweep
// submits a unit only when a thread is free (has_room), as units come in; an ensemble queues all
// its repetitions at once and collects them in batches (collect_all), so that many short jobs
// cost the threads no hand-over with the caller.
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
#include <iterator>
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
    try {
      for (int t = 0; t < threads; ++t) workers_.emplace_back([this] { work(); });
    } catch (...) {  // the system refused a thread: end those started, then say why
      stop_and_join();
      throw;
    }
  }
  // Jobs still queued are dropped (the run ended, or a job threw); running ones finish first.
  ~ThreadPool() { stop_and_join(); }
  ThreadPool(const ThreadPool&) = delete;
  ThreadPool& operator=(const ThreadPool&) = delete;

  int threads() const { return static_cast<int>(workers_.size()); }
  int busy() const { return busy_; }
  bool has_room() const { return busy_ < threads(); }

  void submit(int id) { enqueue(&id, &id + 1); }
  // Queues `ids` in this order, behind the jobs already queued.
  void submit(const std::vector<int>& ids) { enqueue(ids.data(), ids.data() + ids.size()); }

  // The next finished job, waiting at most `wait`; nothing on timeout.
  std::optional<Done> collect(std::chrono::milliseconds wait) {
    std::unique_lock lock(mu_);
    wake_on_each_ = true;
    if (!done_cv_.wait_for(lock, wait, [&] { return !done_.empty(); })) return std::nullopt;
    Done d = std::move(done_.front());
    done_.pop_front();
    --busy_;
    return d;
  }

  // The finished jobs, in finish order, once every submitted job has finished or `wait` has
  // passed. The caller is woken once, not at each job.
  std::vector<Done> collect_all(std::chrono::milliseconds wait) {
    std::unique_lock lock(mu_);
    wake_on_each_ = false;
    done_cv_.wait_for(lock, wait, [&] { return running_ == 0; });
    std::vector<Done> out(std::make_move_iterator(done_.begin()), std::make_move_iterator(done_.end()));
    done_.clear();
    busy_ -= static_cast<int>(out.size());
    return out;
  }

 private:
  void stop_and_join() {
    {
      std::lock_guard lock(mu_);
      stop_ = true;
    }
    todo_cv_.notify_all();
    for (auto& w : workers_) w.join();
  }

  void enqueue(const int* first, const int* last) {
    const int n = static_cast<int>(last - first);
    {
      std::lock_guard lock(mu_);
      todo_.insert(todo_.end(), first, last);
      running_ += n;
    }
    busy_ += n;
    if (n == 1) todo_cv_.notify_one();
    else todo_cv_.notify_all();
  }

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
      bool wake = false;
      {
        std::lock_guard lock(mu_);
        done_.push_back(std::move(d));
        --running_;
        wake = wake_on_each_ || running_ == 0;
      }
      if (wake) done_cv_.notify_one();
    }
  }

  Job job_;
  std::mutex mu_;
  std::condition_variable todo_cv_, done_cv_;
  std::deque<int> todo_;
  std::deque<Done> done_;
  bool stop_ = false;
  bool wake_on_each_ = true;  // the caller waits in collect, not collect_all
  int running_ = 0;           // submitted and not yet finished (under mu_)
  int busy_ = 0;              // submitted and not yet collected (the caller's own count)
  std::vector<std::thread> workers_;
};

}  // namespace sb
