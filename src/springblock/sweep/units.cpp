#include "springblock/sweep/units.hpp"

#include <climits>

#include "springblock/ensemble.hpp"
#include "springblock/errors.hpp"

namespace sb::sweep {

std::vector<Unit> make_units(const std::vector<SweepScene>& scenes) {
  long long total = 0;
  for (const auto& s : scenes) total += s.scene.reps;
  // A unit is named by an int everywhere (checkpoint, messages between ranks).
  if (total > INT_MAX)
    throw InputError("reps", "the sweep has " + std::to_string(total) + " units (scenes x reps); at most " +
                                 std::to_string(INT_MAX));
  std::vector<Unit> units;
  units.reserve(static_cast<std::size_t>(total));
  for (int k = 0; k < static_cast<int>(scenes.size()); ++k)
    for (int r = 0; r < scenes[k].scene.reps; ++r) units.push_back({k, r});
  return units;
}

nlohmann::json run_unit(const std::vector<SweepScene>& scenes, const std::vector<Unit>& units, int id,
                        const std::atomic<bool>* interrupt) {
  const Unit u = units.at(id);
  const Scene& scene = scenes.at(u.scene).scene;
  const RunResult r = run_repetition(scene, u.rep, interrupt);
  if (interrupt && interrupt->load()) return nullptr;
  nlohmann::json j = r;
  j["unit"] = id;
  j["scene"] = u.scene;
  j["seed"] = rep_seed(scene.seed, u.rep);
  j["contact_fraction"] = r.contact_fraction;
  return j;
}

double unit_cost(const Scene& scene) { return scene.duration() * scene.geometry.N; }

}  // namespace sb::sweep
