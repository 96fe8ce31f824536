#pragma once
// sb::run_ensembles with its jobs dealt by a scheduler: under MPI, the (scene group, repetition)
// jobs go to the ranks' threads from rank 0's queue, the dearest first, as for a sweep's units.
// Each job's runs come back to rank 0 whole (ensemble_state.hpp: repetition 0's mu(t) series and
// stress snapshots included, every double to the bit) and rank 0 builds every scene's result from
// them in repetition order, so the numbers are run_ensembles' whatever the ranks and threads.
#include <atomic>
#include <functional>
#include <optional>
#include <vector>

#include "springblock/ensemble.hpp"
#include "springblock/parallel/scheduler.hpp"

namespace sb::parallel {

// Only the coordinator's `scenes` and `weights` count: the other ranks receive the scenes from it
// (they need no input files) and get nothing back. On the coordinator: each scene's result as
// run_ensembles gives it, except the resources (threads: every rank's, wall_s: its share of
// them); all of them marked interrupted when `interrupt` stopped the run. `progress` (on the
// coordinator, about 5 times a second) gets the fraction of the jobs' weight finished and the
// elapsed seconds. A job's exception ends every rank (the scheduler's run).
std::optional<std::vector<EnsembleResult>> run_ensembles_on(Scheduler& sched, const std::vector<Scene>& scenes,
                                                           const std::atomic<bool>* interrupt,
                                                           std::function<void(double, double)> progress = {},
                                                           const std::vector<double>& weights = {});

}  // namespace sb::parallel
