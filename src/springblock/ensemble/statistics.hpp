#pragma once
// The statistics of an ensemble from its repetitions (the public summarize() is in ensemble.hpp).
#include "springblock/ensemble.hpp"

namespace sb::ensemble_detail {

// Every observable's statistic over out.runs, in repetition order (so the same doubles whichever
// thread ran which repetition), and the surface's contact fraction.
void summarize_runs(EnsembleResult& out);

}  // namespace sb::ensemble_detail
