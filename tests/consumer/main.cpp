// A consumer of the installed library: a scene by field name, an ensemble, its results JSON and
// the theory's prediction, through the public headers only.
#include <cstdio>
#include <nlohmann/json.hpp>

#include "springblock/ensemble.hpp"
#include "springblock/errors.hpp"
#include "springblock/io.hpp"
#include "springblock/scene.hpp"
#include "springblock/scene_fields.hpp"
#include "springblock/scene_theory.hpp"

int main() {
  sb::Scene scene;
  for (auto [key, value] : {std::pair{"N", "40"}, {"pattern", "periodic:2,6"}, {"reps", "2"}, {"duration", "3t0"}})
    sb::set_scene_field(scene, key, value);
  sb::validate(scene);
  const sb::EnsembleResult result = sb::run_ensemble(scene);
  const nlohmann::json j = sb::ensemble_json(scene, result, "consumer");
  const auto theory = sb::theory::predict(scene);
  try {
    sb::set_scene_field(scene, "N", "0");
    sb::validate(scene);
    return 1;  // bad input must be refused
  } catch (const sb::InputError& e) {
    std::printf("refused: %s\n", e.what());
  }
  std::printf("mu_s = %.17g (n=%d), mu_d = %.17g, json mu_s = %.17g, theory mu_d_macro = %g\n", result.mu_s.mean,
              result.mu_s.n, result.mu_d.mean, j.at("mu_s").at("mean").get<double>(), theory.cycle.mu_d_macro);
  return result.mu_s.n == 2 && result.mu_d.n == 2 ? 0 : 1;
}
