#pragma once
// Scenes that see the same trajectory (equal TrajectorySpec: they differ only in extraction
// rules, run length or kept observables) are simulated once, by their longest member, and every
// member observes that one run behind a FanOut (observe/fan_out.hpp).
#include <atomic>
#include <cstdint>
#include <vector>

#include "springblock/ensemble.hpp"

namespace sb::ensemble_detail {

// Returns, for each scene k, its group, longest first (the first of the longest on a tie), when k
// leads it, and nothing for the other members; their trajectory_from in `out` names the leader.
// A scene without a trajectory spec is a group of its own.
std::vector<std::vector<int>> group_by_trajectory(const std::vector<Scene>& scenes, std::vector<EnsembleResult>& out);

// Repetition `rep` of a group: simulated once, to the longest duration, with one observer per
// scene. scenes[0] is the longest; it is charged the wall time, CPU time and work profile, the
// others record 0 (their cost is in its run) and their counters up to their own last sample.
std::vector<RunResult> run_shared_repetition(const std::vector<const Scene*>& scenes, int rep,
                                             const std::atomic<bool>* interrupt,
                                             std::atomic<std::int64_t>* progress_ns);

}  // namespace sb::ensemble_detail
