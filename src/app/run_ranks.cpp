#include "run_ranks.hpp"

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "scheduler_choice.hpp"
#include "shell/exit_codes.hpp"
#include "shell/progress.hpp"
#include "springblock/errors.hpp"
#include "springblock/parallel/launch.hpp"

namespace sb::app {
namespace {

nlohmann::json run_rep(const Scene& scene, int rep, const std::atomic<bool>* interrupt) {
  const RunResult r = run_repetition(scene, rep, interrupt);
  if (interrupt && interrupt->load()) return nullptr;
  nlohmann::json j = r;
  j["contact_fraction"] = r.contact_fraction;
  return j;
}

}  // namespace

std::optional<EnsembleResult> run_ensemble_on_ranks(const Scene& scene, const std::atomic<bool>* interrupt,
                                                    std::function<void(double, double)> progress) {
  if (!parallel::launched_by_mpirun()) return run_ensemble(scene, interrupt, std::move(progress));
  if (scene.observe.series || !scene.observe.stress_times_s.empty())
    throw InputError("series", "--series and stress_times keep repetition 0 in memory and are not sent between "
                               "MPI ranks; run without mpirun");
  const auto wall0 = std::chrono::steady_clock::now();
  auto sched = make_scheduler(scene.threads);
  auto unit = [&](int rep, const std::atomic<bool>* stop) { return run_rep(scene, rep, stop); };
  std::vector<int> reps;
  for (int r = 0; r < scene.reps; ++r) reps.push_back(r);
  std::vector<RunResult> runs(scene.reps);
  int finished = 0;
  parallel::Hooks hooks;
  hooks.finished = [&](int rep, int, nlohmann::json record) {
    runs[rep] = record.get<RunResult>();
    ++finished;
  };
  if (progress)
    hooks.tick = [&] {
      progress(static_cast<double>(finished) / scene.reps,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count());
    };
  const auto outcome = sched->run(reps, unit, hooks, interrupt);
  if (!sched->coordinator()) return std::nullopt;
  if (outcome.interrupted) {
    shell::end_progress_line();
    std::fprintf(stderr, "springblock: interrupted; %d of %d repetitions had finished. No output file was written "
                         "and existing files are untouched.\n", finished, scene.reps);
    std::fflush(stderr);
    sched->abort(shell::kInterrupted);
  }
  EnsembleResult e = ensemble_from_runs(std::move(runs));
  e.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  e.threads = sched->ranks() * sched->threads();
  return e;
}

}  // namespace sb::app
