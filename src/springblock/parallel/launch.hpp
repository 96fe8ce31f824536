#pragma once
// Whether this process was started by mpirun (Open MPI, or a PMI/PMIx launcher such as srun):
// only then does springblock start MPI, so a plain run never pays for MPI_Init.
#include <cstdlib>

namespace sb::parallel {

inline bool launched_by_mpirun() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(v)) return true;
  return false;
}

}  // namespace sb::parallel
