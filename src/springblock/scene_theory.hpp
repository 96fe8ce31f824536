#pragma once
// The closed-form single-block theory (theory.hpp) applied to a scene: the block of its
// K_int = 0 limit and what the theory predicts for it. The `theory` command and the Python
// module's theory.of_scene both print this, so they cannot disagree.
#include <optional>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "springblock/scene.hpp"
#include "springblock/theory.hpp"

namespace sb::theory {

// The K_int = 0 chain whose blocks differ: each contact block is its own single block (its slider
// spring and mass, the load's share F_load / N_contact) with its own Gaussian micro coefficients.
// The blocks move independently, so the chain's friction force is the sum of theirs and its
// (mu_d)_M is the mean over the contact blocks of each block's Gaussian-averaged eq. 9. Internal
// springs, uniform or per block, are absent in this limit; damping is left out as in the
// single-block derivation.
struct ChainPrediction {
  int n_contact = 0;
  double F_n_N = 0;                      // each contact block's share of the load
  double mu_d_macro_gaussian = 0;        // the chain's: mean of block_mu_d_macro over contact blocks
  std::vector<double> block_mu_d_macro;  // one per block; 0 for a groove block (no friction)
  int quadratures = 0;                   // distinct blocks averaged (equal blocks share one)
};

struct ScenePrediction {
  SingleBlock block;          // one block's mass and slider spring, its share of the load
  double mu_s = 0, mu_d = 0;  // the micro means; mu_d clipped to mu_s as the draws are
  SingleBlockCycle cycle;     // for exactly these coefficients
  double mu_s_sd = 0, mu_d_sd = 0;  // widths of the scene's Gaussian micro coefficients
  double mu_d_macro_gaussian = 0;   // mu_d_macro averaged over those Gaussians
  // The chain block by block: set when the scene gives per-block fields (the single block above
  // is then the scene's uniform one, which its fields override).
  std::optional<ChainPrediction> chain;
};

// The single block of the K_int = 0 limit: one block's mass and slider spring, and its share of
// the load on a surface where every block is in contact. `scene` must be validated.
SingleBlock single_block(const Scene& scene);

// The chain of a validated scene, block by block. Its contact blocks are the materials' contact
// column or the pattern's mask; a random surface (a fresh mask per repetition) without a contact
// column is refused (InputError "pattern").
ChainPrediction predict_chain(const Scene& scene);

// `scene` must be validated.
ScenePrediction predict(const Scene& scene);

// The `theory --json` object.
void to_json(nlohmann::json& j, const ScenePrediction& p);

}  // namespace sb::theory
