#pragma once
// The MPI scheduler (built with SPRINGBLOCK_MPI, in library springblock_mpi so that the core
// library and its users never need MPI). Rank 0 coordinates: it keeps the queue, runs units on
// its own threads too, and answers each worker's request with the next units from the front of
// its queue (dynamic load balancing, the dearest first); a request carries the records finished
// since the last one. A worker asks for a batch sized to keep its threads busy about `batch_s`
// (from its units' measured wall time), so rank 0 answers one message per batch instead of one
// per unit; batch_s = 0 asks for one unit at a time. Results do not depend on the batching (a
// unit's result never depends on where or with what it ran). Only each rank's main thread calls
// MPI (MPI_THREAD_FUNNELED).
#include <memory>

#include "springblock/parallel/scheduler.hpp"

namespace sb::parallel {

// Starts MPI (MPI_Init_thread); the scheduler's destructor ends it (MPI_Finalize).
std::unique_ptr<Scheduler> make_mpi_scheduler(int threads, double batch_s);

}  // namespace sb::parallel
