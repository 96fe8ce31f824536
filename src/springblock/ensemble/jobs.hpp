#pragma once
// The jobs of run_ensembles, for a caller that deals them itself (to MPI ranks:
// parallel/ensembles_on_ranks.hpp) and must get run_ensembles' results from the same runs. A job
// is a (group of scenes sharing a trajectory, repetition); its runs are that repetition of every
// member of the group. Every rank plans the same jobs from the same scenes, so a job's index means
// the same job on every rank.
#include <atomic>
#include <cstdint>
#include <vector>

#include "springblock/ensemble.hpp"

namespace sb::ensemble_detail {

struct EnsembleJob {
  int scene, rep;  // the scene leads its group (group_by_trajectory)
};

struct EnsembleJobs {
  std::vector<std::vector<int>> members;  // scene -> its group when it leads one, else empty
  std::vector<EnsembleJob> jobs;          // in scene order, each scene's repetitions in order
};

// The jobs of `scenes`; sizes each scene's runs in `out` and names the scene a member was
// observed on (trajectory_from).
EnsembleJobs plan_jobs(const std::vector<Scene>& scenes, std::vector<EnsembleResult>& out);

// Each job's share of the whole work, for progress: its scene's weight (`weights`, or by default
// reps x duration x N) over the scene's repetitions, over the total.
std::vector<double> job_shares(const std::vector<Scene>& scenes, const EnsembleJobs& plan,
                               const std::vector<double>& weights);

// Job `j`'s runs, one per member of its group, in the group's order.
std::vector<RunResult> run_job(const std::vector<Scene>& scenes, const EnsembleJobs& plan, int j,
                               const std::atomic<bool>* interrupt, std::atomic<std::int64_t>* progress_ns);

// Puts job `j`'s runs (as run_job returned them) in their scenes' results, at their repetition.
void store_job(const EnsembleJobs& plan, int j, std::vector<RunResult> runs, std::vector<EnsembleResult>& out);

// Counts, statistics (in repetition order) and wall-time shares of every scene once its jobs
// are done; `finished[j]` says whether job j finished, `threads` is how many ran them.
void finish_ensembles(const std::vector<Scene>& scenes, const EnsembleJobs& plan, const std::vector<char>& finished,
                      int threads, std::vector<EnsembleResult>& out);

}  // namespace sb::ensemble_detail
