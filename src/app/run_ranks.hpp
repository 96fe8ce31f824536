#pragma once
// `springblock run` under mpirun: the repetitions of its one scene are work units dealt to the
// ranks' threads like a sweep's, and the ensemble rank 0 assembles is what run_ensemble would
// return (same seeds, repetition r at index r), so the output is the same numbers.
#include <atomic>
#include <functional>
#include <optional>

#include "springblock/ensemble.hpp"

namespace sb::app {

// Without mpirun: sb::run_ensemble. Under mpirun: the ensemble on rank 0 and nothing on the
// other ranks (they print nothing). An interrupt on rank 0 says so and ends every rank (exit 130).
std::optional<EnsembleResult> run_ensemble_on_ranks(const Scene& scene, const std::atomic<bool>* interrupt,
                                                    std::function<void(double, double)> progress);

}  // namespace sb::app
