#include "springblock/pool/for_each_job.hpp"

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
  // After a stop the threads skip the jobs still queued; a job that throws stops the others at
  // once, not when this thread collects it.
  ThreadPool<bool> pool(threads, [&](int j) {
    if (stopped()) return false;
    try {
      return job(j);
    } catch (...) {
      failed = true;
      throw;
    }
  });
  // All queued at once, in order: a thread that finishes takes the next one without waiting for
  // this thread, which wakes only to report progress and at the end.
  std::vector<int> ids(n_jobs);
  for (int j = 0; j < n_jobs; ++j) ids[j] = j;
  pool.submit(ids);
  while (pool.busy() > 0) {
    for (auto& d : pool.collect_all(std::chrono::seconds(1))) {
      finished[d.id] = d.result;
      errors[d.id] = d.error;
    }
    if (pool.busy() > 0 && every_second) every_second();
  }
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
  return finished;
}

}  // namespace sb
