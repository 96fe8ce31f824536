// The ensemble's job loop: every (group of scenes sharing a trajectory, repetition) is one job on
// the thread pool, dealt in scene order, so a thread that finishes its last repetition of one
// scene starts on the next scene instead of waiting for the others.
#include <algorithm>
#include <chrono>
#include <numeric>

#include "springblock/ensemble/jobs.hpp"
#include "springblock/ensemble/observation.hpp"
#include "springblock/ensemble/shared_trajectory.hpp"
#include "springblock/ensemble/statistics.hpp"
#include "springblock/pool/for_each_job.hpp"
#include "springblock/pool/thread_pool.hpp"

namespace sb {
namespace ensemble_detail {

EnsembleJobs plan_jobs(const std::vector<Scene>& scenes, std::vector<EnsembleResult>& out) {
  for (std::size_t k = 0; k < scenes.size(); ++k) out[k].runs.resize(scenes[k].reps);
  EnsembleJobs plan;
  plan.members = group_by_trajectory(scenes, out);
  for (int k = 0; k < static_cast<int>(scenes.size()); ++k)
    if (!plan.members[k].empty())
      for (int r = 0; r < scenes[k].reps; ++r) plan.jobs.push_back({k, r});
  return plan;
}

// A repetition of a scene of its own, or of a group observed on one run.
std::vector<RunResult> run_job(const std::vector<Scene>& scenes, const EnsembleJobs& plan, int j,
                               const std::atomic<bool>* interrupt, std::atomic<std::int64_t>* progress_ns) {
  const EnsembleJob job = plan.jobs[j];
  const auto& group = plan.members[job.scene];
  if (group.size() == 1) return {run_repetition(scenes[job.scene], job.rep, interrupt, progress_ns)};
  std::vector<const Scene*> views;
  for (int m : group) views.push_back(&scenes[m]);
  return run_shared_repetition(views, job.rep, interrupt, progress_ns);
}

std::vector<double> job_shares(const std::vector<Scene>& scenes, const EnsembleJobs& plan,
                               const std::vector<double>& weights) {
  std::vector<double> w(plan.jobs.size());
  for (std::size_t j = 0; j < w.size(); ++j) {
    const Scene& sc = scenes[plan.jobs[j].scene];
    w[j] = (weights.empty() ? sc.reps * sc.duration() * sc.geometry.N : weights[plan.jobs[j].scene]) / sc.reps;
  }
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  if (total > 0)
    for (double& x : w) x /= total;
  return w;
}

void store_job(const EnsembleJobs& plan, int j, std::vector<RunResult> runs, std::vector<EnsembleResult>& out) {
  const EnsembleJob job = plan.jobs[j];
  const auto& group = plan.members[job.scene];
  for (std::size_t v = 0; v < group.size(); ++v) out[group[v]].runs[job.rep] = std::move(runs[v]);
}

void finish_ensembles(const std::vector<Scene>& scenes, const EnsembleJobs& plan, const std::vector<char>& finished,
                      int threads, std::vector<EnsembleResult>& out) {
  for (std::size_t j = 0; j < plan.jobs.size(); ++j)
    for (int m : plan.members[plan.jobs[j].scene]) out[m].finished_reps += finished[j];
  for (std::size_t k = 0; k < scenes.size(); ++k) {
    EnsembleResult& e = out[k];
    e.interrupted = e.finished_reps < scenes[k].reps;
    e.threads = std::min(threads, std::max(1, scenes[k].reps));
    summarize_runs(e);
    // Pooled with other scenes, a scene has no wall time of its own: its share is its
    // repetitions' time over the threads (for a single scene, its wall time: run_ensembles).
    double rep_s = 0;
    for (const auto& r : e.runs) rep_s += r.wall_s;
    e.wall_s = rep_s / threads;
  }
}

}  // namespace ensemble_detail

namespace {

using namespace ensemble_detail;

// Threads over the jobs: the most any scene asks for (0 = all cores), at most one a job.
int pool_threads(const std::vector<Scene>& scenes, std::size_t n_jobs) {
  int threads = 1;
  for (const Scene& sc : scenes) threads = std::max(threads, resolve_threads(sc.threads));
  return std::max(1, std::min(threads, static_cast<int>(n_jobs)));
}

// Each job's weight in the overall fraction done, per simulated nanosecond of its repetition.
std::vector<double> progress_weights(const std::vector<Scene>& scenes, const EnsembleJobs& plan,
                                     const std::vector<double>& weights) {
  std::vector<double> per_ns = job_shares(scenes, plan, weights);
  for (std::size_t j = 0; j < per_ns.size(); ++j) per_ns[j] /= scenes[plan.jobs[j].scene].duration() * 1e9;
  return per_ns;
}

}  // namespace

std::vector<EnsembleResult> run_ensembles(const std::vector<Scene>& scenes, const std::atomic<bool>* interrupt,
                                          std::function<void(double, double)> progress,
                                          const std::vector<double>& weights) {
  const auto wall0 = std::chrono::steady_clock::now();
  std::vector<EnsembleResult> out(scenes.size());
  const auto plan = plan_jobs(scenes, out);
  const auto& jobs = plan.jobs;
  std::vector<std::atomic<std::int64_t>> progress_ns(jobs.size());  // simulated time done, per job
  const int threads = pool_threads(scenes, jobs.size());
  const auto job = [&](int j) {
    store_job(plan, j, run_job(scenes, plan, j, interrupt, &progress_ns[j]), out);
    return !(interrupt && interrupt->load());  // a repetition cut short is not a result
  };
  std::function<void()> report;
  if (progress)
    report = [&, per_ns = progress_weights(scenes, plan, weights)] {
      double f = 0;
      for (std::size_t j = 0; j < jobs.size(); ++j)
        f += per_ns[j] * static_cast<double>(progress_ns[j].load(std::memory_order_relaxed));
      progress(f, seconds_since(wall0));
    };
  const auto finished = for_each_job(static_cast<int>(jobs.size()), threads, job, interrupt, report);
  finish_ensembles(scenes, plan, finished, threads, out);
  if (scenes.size() == 1) out[0].wall_s = seconds_since(wall0);
  return out;
}

EnsembleResult run_ensemble(const Scene& scene, const std::atomic<bool>* interrupt,
                            std::function<void(double, double)> progress) {
  return std::move(run_ensembles({scene}, interrupt, std::move(progress)).front());
}

}  // namespace sb
