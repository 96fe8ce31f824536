#include "springblock/sweep/units.hpp"

#include "springblock/ensemble.hpp"

namespace sb::sweep {

std::vector<Unit> make_units(const std::vector<SweepScene>& scenes) {
  std::vector<Unit> units;
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
