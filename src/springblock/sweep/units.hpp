#pragma once
// Work units of a sweep: one (scene, repetition) pair each, numbered scene by scene. A unit's
// result depends only on its scene and repetition (rep_seed), never on the rank or thread that
// runs it, and travels as a JSON record whose doubles round-trip exactly (nlohmann prints the
// shortest text that reads back to the same double), so results are bit-identical in every mode.
#include <atomic>
#include <nlohmann/json.hpp>
#include <vector>

#include "springblock/sweep/expand.hpp"

namespace sb::sweep {

struct Unit {
  int scene = 0;
  int rep = 0;
};

// Throws InputError("reps") when the units would not fit an int.
std::vector<Unit> make_units(const std::vector<SweepScene>& scenes);

// Runs unit `id` and returns its record: unit, scene, rep, seed, the observables (null where
// undefined), work counters, wall and CPU seconds. A null record when `interrupt` cut it short.
nlohmann::json run_unit(const std::vector<SweepScene>& scenes, const std::vector<Unit>& units, int id,
                        const std::atomic<bool>* interrupt);

// A rough relative cost of each unit (simulated seconds x blocks): the coordinator hands out the
// dearest first, so a long unit does not start last and leave the other ranks idle.
double unit_cost(const Scene& scene);

}  // namespace sb::sweep
