#include "springblock/pool/for_each_job.hpp"

#include <algorithm>
#include <chrono>
#include <exception>

#include "springblock/pool/thread_pool.hpp"

namespace sb {

std::vector<char> for_each_job(int n_jobs, int threads, const std::function<bool(int)>& job,
                               const std::atomic<bool>* interrupt, const std::function<void()>& every_second) {
  std::vector<char> finished(n_jobs, 0);
  std::vector<std::exception_ptr> errors(n_jobs);
  std::atomic<bool> failed{false};
  const auto stopped = [&] { return (interrupt && interrupt->load()) || failed.load(); };
  // A job dealt just before the stop is skipped by its thread, as if never dealt; a job that
  // throws stops the others at once, not when the calling thread collects it.
  ThreadPool<bool> pool(threads, [&](int j) {
    if (stopped()) return false;
    try {
      return job(j);
    } catch (...) {
      failed = true;
      throw;
    }
  });
  using clock = std::chrono::steady_clock;
  auto next_report = clock::now() + std::chrono::seconds(1);
  int next = 0;
  while ((next < n_jobs && !stopped()) || pool.busy() > 0) {
    while (next < n_jobs && !stopped() && pool.has_room()) pool.submit(next++);
    const auto wait = std::chrono::duration_cast<std::chrono::milliseconds>(next_report - clock::now());
    if (auto d = pool.collect(std::max(wait, std::chrono::milliseconds(0)))) {
      finished[d->id] = d->result;
      if (d->error) errors[d->id] = d->error;
    }
    if (clock::now() < next_report) continue;
    if (every_second) every_second();
    next_report = clock::now() + std::chrono::seconds(1);
  }
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
  return finished;
}

}  // namespace sb
