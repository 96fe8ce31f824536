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
//
// A worker that falls silent for `silence_s` (killed, node lost: workers send a heartbeat while
// their threads run, liveness.hpp) is taken for dead: its units are dealt again to the others and
// anything it sends later is dropped, so no unit counts twice. The job outlives a dead rank only
// when mpirun lets it (Open MPI 4: mpirun --enable-recovery --mca orte_abort_on_non_zero_status 0;
// that mpirun then exits 0 whatever the ranks return); by default mpirun ends every rank, and the
// checkpoint lets --resume finish the sweep. A rank that was only stalled and speaks again while
// rank 0 deals is told to stop; one that wakes after rank 0 has finished finds no one to answer it
// and keeps the job from ending (the results are complete by then). After a lost rank the job
// ends with MPI_Abort at exit, not MPI_Finalize, whose closing fence can wait for the dead rank.
#include <memory>

#include "springblock/parallel/scheduler.hpp"

namespace sb::parallel {

// Starts MPI (MPI_Init_thread); the scheduler's destructor ends it (MPI_Finalize).
std::unique_ptr<Scheduler> make_mpi_scheduler(int threads, double batch_s, double silence_s);

}  // namespace sb::parallel
