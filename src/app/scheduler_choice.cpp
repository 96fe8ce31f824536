#include "scheduler_choice.hpp"

#include <cstdlib>

#include "springblock/errors.hpp"
#include "springblock/parallel/launch.hpp"
#ifdef SPRINGBLOCK_HAVE_MPI
#include "springblock/parallel/mpi/mpi_scheduler.hpp"
#endif

namespace sb::app {

std::unique_ptr<parallel::Scheduler> make_scheduler(int threads, double batch_s, double silence_s) {
#ifdef SPRINGBLOCK_HAVE_MPI
  if (parallel::launched_by_mpirun()) return parallel::make_mpi_scheduler(threads, batch_s, silence_s);
#else
  (void)batch_s;
  (void)silence_s;
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  if (size && std::atoi(size) > 1)
    throw InputError("mpirun", "this springblock was built without MPI (SPRINGBLOCK_MPI=OFF): every rank would "
                               "run everything; run it without mpirun, or rebuild with MPI");
#endif
  return parallel::make_thread_scheduler(threads);
}

}  // namespace sb::app
