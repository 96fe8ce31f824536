#pragma once
// The MPI scheduler (built with SPRINGBLOCK_MPI, in library springblock_mpi so that the core
// library and its users never need MPI). Rank 0 coordinates: it keeps the queue, runs units on
// its own threads too, and answers each worker thread's request for a unit with the next one
// (dynamic load balancing, one unit at a time); a worker's request carries the record of the unit
// it just finished. Only each rank's main thread calls MPI (MPI_THREAD_FUNNELED).
#include <memory>

#include "springblock/parallel/scheduler.hpp"

namespace sb::parallel {

// Starts MPI (MPI_Init_thread); the scheduler's destructor ends it (MPI_Finalize).
std::unique_ptr<Scheduler> make_mpi_scheduler(int threads);

}  // namespace sb::parallel
