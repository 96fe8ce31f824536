#pragma once
// Which scheduler a command runs its work units on: MPI when this build has it and mpirun
// started the process, else this process's threads.
#include <memory>

#include "springblock/parallel/scheduler.hpp"

namespace sb::app {

// Starts MPI when it chooses it; `batch_s` is the MPI workers' target time per batch of units
// (0: one unit per request; threads in one process need no batches); a worker rank silent for
// `silence_s` is taken for dead and its units dealt again (mpi_scheduler.hpp). Throws InputError when mpirun started several copies of a build
// without MPI (each would run everything).
std::unique_ptr<parallel::Scheduler> make_scheduler(int threads, double batch_s = 0.05, double silence_s = 10);

}  // namespace sb::app
