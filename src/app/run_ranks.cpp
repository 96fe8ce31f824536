#include "run_ranks.hpp"

#include <cstdio>
#include <vector>

#include "scheduler_choice.hpp"
#include "shell/exit_codes.hpp"
#include "shell/progress.hpp"
#include "springblock/parallel/ensembles_on_ranks.hpp"
#include "springblock/parallel/launch.hpp"

namespace sb::app {

std::optional<EnsembleResult> run_ensemble_on_ranks(const Scene& scene, const std::atomic<bool>* interrupt,
                                                    std::function<void(double, double)> progress) {
  if (!parallel::launched_by_mpirun()) return run_ensemble(scene, interrupt, std::move(progress));
  auto sched = make_scheduler(scene.threads);
  // Rank 0's scene is the one run (the others' copies are not read): its repetitions go out as
  // jobs and come back as exact states, repetition 0's series and stress snapshots included.
  const std::vector<Scene> given = sched->coordinator() ? std::vector<Scene>{scene} : std::vector<Scene>{};
  auto results = parallel::run_ensembles_on(*sched, given, interrupt, std::move(progress));
  if (!results) return std::nullopt;
  EnsembleResult e = std::move(results->front());
  if (e.interrupted) {
    shell::end_progress_line();
    std::fprintf(stderr, "springblock: interrupted. No output file was written and existing files are untouched.\n");
    std::fflush(stderr);
    sched->abort(shell::kInterrupted);
  }
  return e;
}

}  // namespace sb::app
