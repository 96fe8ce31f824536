#pragma once
// The closed-form single-block theory (theory.hpp) applied to a scene: the block of its
// K_int = 0 limit and what the theory predicts for it. The `theory` command and the Python
// module's theory.of_scene both print this, so they cannot disagree.
#include <nlohmann/json_fwd.hpp>

#include "springblock/scene.hpp"
#include "springblock/theory.hpp"

namespace sb::theory {

struct ScenePrediction {
  SingleBlock block;          // one block's mass and slider spring, its share of the load
  double mu_s = 0, mu_d = 0;  // the micro means; mu_d clipped to mu_s as the draws are
  SingleBlockCycle cycle;     // for exactly these coefficients
  double mu_s_sd = 0, mu_d_sd = 0;  // widths of the scene's Gaussian micro coefficients
  double mu_d_macro_gaussian = 0;   // mu_d_macro averaged over those Gaussians
};

// The single block of the K_int = 0 limit: one block's mass and slider spring, and its share of
// the load on a surface where every block is in contact. `scene` must be validated.
SingleBlock single_block(const Scene& scene);

// `scene` must be validated.
ScenePrediction predict(const Scene& scene);

// The `theory --json` object.
void to_json(nlohmann::json& j, const ScenePrediction& p);

}  // namespace sb::theory
