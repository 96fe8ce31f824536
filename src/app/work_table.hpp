#pragma once
// springblock run --profile: where the repetitions' time went, as a table on stderr.
#include "springblock/ensemble.hpp"

namespace sb::app {

void print_work_table(const EnsembleResult& result);

}  // namespace sb::app
