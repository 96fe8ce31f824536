#include "springblock/pool/thread_pool.hpp"

#include <omp.h>

#include <algorithm>

namespace sb {

// The count is asked of the OpenMP run-time, which no longer runs any loop here, so that 0 keeps
// meaning what the documentation says: OMP_NUM_THREADS (with its list and limit rules) if set,
// else the processors this process may run on.
int resolve_threads(int threads) { return threads > 0 ? threads : std::max(1, omp_get_max_threads()); }

}  // namespace sb
