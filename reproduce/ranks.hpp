#pragma once
// A target under mpirun: rank 0 reads the options, plans the scenes, deals their repetitions to
// every rank's threads (the sweep's dealer: parallel/ensembles_on_ranks.hpp), gathers them and
// alone writes the document; the other ranks only run what rank 0 deals them, and say nothing
// (rank 0 says what went wrong). Without mpirun nothing here is used: sb::run_ensembles runs the
// scenes on this process's threads, with the same numbers.
#include <atomic>
#include <functional>
#include <memory>
#include <vector>

#include "springblock/ensemble.hpp"
#include "springblock/parallel/scheduler.hpp"

namespace repro {

// Whether this process is rank 0 of its job, or runs alone: the one that speaks and writes.
bool speaking_rank();

// The ranks of a target started by mpirun (MPI starts here), with `threads` threads each; none
// without mpirun. Throws sb::InputError when mpirun started several copies of a build without MPI.
std::unique_ptr<sb::parallel::Scheduler> target_ranks(int threads);

// A rank other than 0, its thread count read from the same command line: waits for rank 0's
// verdict on its input, then runs the repetitions dealt to it. Returns the exit code.
int run_worker_rank(int threads);

// The pool's scenes on `ranks` (rank 0) or, without, on this process's threads.
std::vector<sb::EnsembleResult> run_scenes(sb::parallel::Scheduler* ranks, const std::vector<sb::Scene>& scenes,
                                           const std::atomic<bool>* interrupt,
                                           std::function<void(double, double)> progress,
                                           const std::vector<double>& weights);

}  // namespace repro
