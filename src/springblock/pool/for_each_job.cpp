#include "springblock/pool/for_each_job.hpp"

#include <unistd.h>

#include <chrono>
#include <exception>
#include <map>
#include <memory>
#include <mutex>

#include "springblock/pool/thread_pool.hpp"

namespace sb {
namespace {

// A pool whose job is set for each call of for_each_job.
struct Team {
  explicit Team(int threads) : pool(threads, [this](int j) { return job(j); }) {}
  std::function<bool(int)> job;  // set while the pool is idle: submit orders it before any use
  ThreadPool<bool> pool;
};

// Teams kept between calls, one idle team per thread count. A process that runs many ensembles
// (a design search runs one per chunk of each stage) keeps its threads, and with them what each
// thread has cached (linear/run_shape.cpp's closed-form modes) and its warm heap, as OpenMP's
// threads were kept: new threads for every call cost a design search about 1% of its time.
// Callers at the same time (Python threads) each get a team of their own.
// A process forked from one that kept teams (Python's multiprocessing and process pools fork by
// default on Linux) inherits the teams but not their threads: a job given to them would never
// run. So the teams belong to the process that made them, and a child drops its parent's.
class IdleTeams {
 public:
  std::unique_ptr<Team> take(int threads) {
    std::lock_guard lock(mu_);
    if (owner_ != ::getpid()) forget_parents_teams();
    auto it = idle_.find(threads);
    if (it == idle_.end()) return std::make_unique<Team>(threads);
    auto team = std::move(it->second);
    idle_.erase(it);
    return team;
  }
  void give_back(std::unique_ptr<Team> team) {
    team->job = nullptr;
    std::lock_guard lock(mu_);
    idle_.try_emplace(team->pool.threads(), std::move(team));  // an extra one is ended here
  }

 private:
  void forget_parents_teams() {
    // Released, not destroyed: destroying a team joins its threads, which this process lacks.
    for (auto& [threads, team] : idle_) (void)team.release();
    idle_.clear();
    owner_ = ::getpid();
  }

  std::mutex mu_;
  std::map<int, std::unique_ptr<Team>> idle_;
  pid_t owner_ = ::getpid();
};

IdleTeams& idle_teams() {
  static IdleTeams teams;
  return teams;
}

}  // namespace

std::vector<char> for_each_job(int n_jobs, int threads, const std::function<bool(int)>& job,
                               const std::atomic<bool>* interrupt, const std::function<void()>& every_second) {
  std::vector<char> finished(n_jobs, 0);
  std::vector<std::exception_ptr> errors(n_jobs);
  std::atomic<bool> failed{false};
  const auto stopped = [&] { return (interrupt && interrupt->load()) || failed.load(); };
  std::unique_ptr<Team> team = idle_teams().take(threads);
  // After a stop the threads skip the jobs still queued; a job that throws stops the others at
  // once, not when this thread collects it.
  team->job = [&](int j) {
    if (stopped()) return false;
    try {
      return job(j);
    } catch (...) {
      failed = true;
      throw;
    }
  };
  // All queued at once, in order: a thread that finishes takes the next one without waiting for
  // this thread, which wakes only to report progress and at the end.
  std::vector<int> ids(n_jobs);
  for (int j = 0; j < n_jobs; ++j) ids[j] = j;
  ThreadPool<bool>& pool = team->pool;
  pool.submit(ids);
  while (pool.busy() > 0) {
    for (auto& d : pool.collect_all(std::chrono::seconds(1))) {
      finished[d.id] = d.result;
      errors[d.id] = d.error;
    }
    if (pool.busy() > 0 && every_second) every_second();
  }
  idle_teams().give_back(std::move(team));
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
  return finished;
}

}  // namespace sb
