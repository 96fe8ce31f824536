#pragma once
// What a scene asks its repetition's observer to measure, and the repetition's observables read
// back off it: shared by a repetition on its own run and one observed on another scene's.
#include <atomic>
#include <chrono>
#include <cstdint>

#include "springblock/ensemble.hpp"

namespace sb::ensemble_detail {

// Repetition 0 alone keeps mu(t) and the stress snapshots, when the scene asks for them.
FrictionObserverConfig observer_config(const Scene& scene, const Chain& chain, int rep,
                                       const std::atomic<bool>* interrupt,
                                       std::atomic<std::int64_t>* progress_ns);

// The observables of one repetition; the work counters and times are the caller's.
RunResult observed(const FrictionObserver& obs, const Chain& chain, int rep);

double seconds_since(std::chrono::steady_clock::time_point t0);

// CPU seconds used by the calling thread so far (a repetition runs on one thread).
double thread_cpu_s();

}  // namespace sb::ensemble_detail
