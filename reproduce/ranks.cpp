#include "ranks.hpp"

#include "scheduler_choice.hpp"
#include "shell/exit_codes.hpp"
#include "shell/interrupt.hpp"
#include "springblock/errors.hpp"
#include "springblock/parallel/ensembles_on_ranks.hpp"
#include "springblock/parallel/launch.hpp"

namespace repro {

bool speaking_rank() { return sb::parallel::launch_rank() == 0; }

std::unique_ptr<sb::parallel::Scheduler> target_ranks(int threads) {
  if (!sb::parallel::launched_by_mpirun()) return nullptr;
  return sb::app::make_scheduler(threads);
}

int run_worker_rank(int threads) {
  std::unique_ptr<sb::parallel::Scheduler> ranks;
  try {
    ranks = target_ranks(threads);
  } catch (const sb::InputError&) {
    return sb::shell::kBadInput;  // rank 0 refuses the same and says why
  }
  if (!ranks) return sb::shell::kOk;
  if (!ranks->agree(true)) return sb::shell::kOk;  // rank 0 refused its input: its exit code says so
  // Interrupted, this rank gives back the repetitions it holds and the others run them.
  sb::parallel::run_ensembles_on(*ranks, {}, sb::shell::catch_interrupts());
  return sb::shell::kOk;
}

std::vector<sb::EnsembleResult> run_scenes(sb::parallel::Scheduler* ranks, const std::vector<sb::Scene>& scenes,
                                           const std::atomic<bool>* interrupt,
                                           std::function<void(double, double)> progress,
                                           const std::vector<double>& weights) {
  if (!ranks) return sb::run_ensembles(scenes, interrupt, std::move(progress), weights);
  return *sb::parallel::run_ensembles_on(*ranks, scenes, interrupt, std::move(progress), weights);
}

}  // namespace repro
