#include "springblock/scene_theory.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

namespace sb::theory {

SingleBlock single_block(const Scene& scene) {
  const auto d = scene.derived();
  return {d.m_kg, d.K_s_N_per_m, scene.material.v_m_per_s, d.F_load_N / scene.geometry.N};
}

ScenePrediction predict(const Scene& scene) {
  const auto& f = scene.friction;
  ScenePrediction p;
  p.block = single_block(scene);
  p.mu_s = f.mu_s_mean;
  p.mu_d = std::min(f.mu_d_mean, f.mu_s_mean);
  p.mu_s_sd = f.mu_s_sd;
  p.mu_d_sd = f.mu_d_sd;
  p.cycle = cycle(p.block, p.mu_s, p.mu_d);
  p.mu_d_macro_gaussian = theory::mu_d_macro_gaussian(p.block, f.mu_s_mean, f.mu_s_sd, f.mu_d_mean, f.mu_d_sd);
  return p;
}

void to_json(nlohmann::json& j, const ScenePrediction& p) {
  const auto& b = p.block;
  const auto& c = p.cycle;
  j = {{"block", {{"m_kg", b.m_kg}, {"k_N_per_m", b.k_N_per_m}, {"v_m_per_s", b.v_m_per_s}, {"F_n_N", b.F_n_N}}},
       {"mu_s", p.mu_s}, {"mu_d", p.mu_d},
       {"omega_rad_per_s", c.omega}, {"r0_m", c.r0_m}, {"T_d_s", c.T_d_s},
       {"delta_r_m", c.delta_r_m}, {"T_s_s", c.T_s_s},
       {"F_stat_mean_over_Fn", c.F_stat_mean_over_Fn}, {"mu_d_macro", c.mu_d_macro},
       {"mu_d_macro_gaussian", p.mu_d_macro_gaussian},
       {"gaussian", {{"mu_s_sd", p.mu_s_sd}, {"mu_d_sd", p.mu_d_sd}}}};
}

}  // namespace sb::theory
