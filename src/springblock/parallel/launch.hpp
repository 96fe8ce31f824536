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

// This process's rank as the launcher gives it, known before MPI starts (0 without mpirun): the
// ranks read the same command line, and only rank 0 need say what is wrong with it.
inline int launch_rank() {
  for (const char* v : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})
    if (const char* r = std::getenv(v)) return std::atoi(r);
  return 0;
}

}  // namespace sb::parallel
