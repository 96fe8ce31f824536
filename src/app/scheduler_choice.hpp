#pragma once
// Which scheduler a command runs its work units on: MPI when this build has it and mpirun
// started the process, else this process's threads.
#include <memory>

#include "springblock/parallel/scheduler.hpp"

namespace sb::app {

// Starts MPI when it chooses it. Throws InputError when mpirun started several copies of a build
// without MPI (each would run everything).
std::unique_ptr<parallel::Scheduler> make_scheduler(int threads);

}  // namespace sb::app
