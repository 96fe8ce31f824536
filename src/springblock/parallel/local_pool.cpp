#include "springblock/parallel/local_pool.hpp"

#include <omp.h>

namespace sb::parallel {

int resolve_threads(int threads) { return threads > 0 ? threads : std::max(1, omp_get_max_threads()); }

LocalPool::LocalPool(int threads, UnitRunner run, const std::atomic<bool>* interrupt)
    : run_(std::move(run)), interrupt_(interrupt) {
  for (int t = 0; t < resolve_threads(threads); ++t) workers_.emplace_back([this] { work(); });
}

LocalPool::~LocalPool() {
  {
    std::lock_guard lock(mu_);
    stop_ = true;
  }
  todo_cv_.notify_all();
  for (auto& w : workers_) w.join();
}

void LocalPool::submit(int id) {
  {
    std::lock_guard lock(mu_);
    todo_.push_back(id);
    ++busy_;
  }
  todo_cv_.notify_one();
}

std::optional<Done> LocalPool::collect(std::chrono::milliseconds wait) {
  std::unique_lock lock(mu_);
  if (!done_cv_.wait_for(lock, wait, [&] { return !done_.empty(); })) return std::nullopt;
  Done d = std::move(done_.front());
  done_.pop_front();
  --busy_;
  return d;
}

void LocalPool::work() {
  for (;;) {
    int id = 0;
    {
      std::unique_lock lock(mu_);
      todo_cv_.wait(lock, [&] { return stop_ || !todo_.empty(); });
      if (stop_) return;  // the run ended (done, or an error): queued units stay unrun
      id = todo_.front();
      todo_.pop_front();
    }
    Done d{id, nullptr, nullptr};
    try {
      d.record = run_(id, interrupt_);
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

}  // namespace sb::parallel
