#include "springblock/scene_theory.hpp"

#include <algorithm>
#include <map>
#include <tuple>

#include <nlohmann/json.hpp>

#include "springblock/errors.hpp"

namespace sb::theory {

SingleBlock single_block(const Scene& scene) {
  const auto d = scene.derived();
  return {d.m_kg, d.K_s_N_per_m, scene.material.v_m_per_s, d.F_load_N / scene.geometry.N};
}

namespace {
std::vector<std::uint8_t> contact_of(const Scene& scene, const ResolvedMaterials& mat) {
  const int N = scene.geometry.N;
  if (mat.has(BlockField::Contact)) {
    std::vector<std::uint8_t> c;
    for (double x : mat.column[index_of(BlockField::Contact)]) c.push_back(x != 0.0);
    return c;
  }
  require(scene.pattern.kind != SurfaceKind::Random, "pattern",
          "the chain's theory needs fixed contact blocks: a random surface draws a new mask each repetition "
          "(give a contact column or a deterministic pattern)");
  return build_contact_mask(scene.pattern, N, 0);
}
}  // namespace

ChainPrediction predict_chain(const Scene& scene) {
  const auto d = scene.derived();
  const ResolvedMaterials mat = resolve_materials(scene);
  const auto contact = contact_of(scene, mat);
  ChainPrediction c;
  c.n_contact = static_cast<int>(std::count(contact.begin(), contact.end(), 1));
  c.F_n_N = d.F_load_N / c.n_contact;
  const auto& f = scene.friction;
  // A graded or segmented chain repeats few distinct blocks: one quadrature each.
  using Key = std::tuple<double, double, double, double, double, double>;
  std::map<Key, double> done;
  double sum = 0;
  c.block_mu_d_macro.assign(scene.geometry.N, 0.0);
  for (int i = 0; i < scene.geometry.N; ++i) {
    if (!contact[i]) continue;
    const SingleBlock b{d.m_kg * mat.at(BlockField::MassScale, i, 1.0),
                        d.K_s_N_per_m * mat.at(BlockField::KsScale, i, 1.0), scene.material.v_m_per_s, c.F_n_N};
    const Key key{b.m_kg, b.k_N_per_m, mat.at(BlockField::MuS, i, f.mu_s_mean), mat.at(BlockField::MuSSd, i, f.mu_s_sd),
                  mat.at(BlockField::MuD, i, f.mu_d_mean), mat.at(BlockField::MuDSd, i, f.mu_d_sd)};
    auto it = done.find(key);
    if (it == done.end()) {
      const auto [m, k, ms, ss, md, sd] = key;
      it = done.emplace(key, mu_d_macro_gaussian(b, ms, ss, md, sd)).first;
    }
    c.block_mu_d_macro[i] = it->second;
    sum += it->second;
  }
  c.mu_d_macro_gaussian = sum / c.n_contact;
  c.quadratures = static_cast<int>(done.size());
  return c;
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
  if (scene.materials.given()) p.chain = predict_chain(scene);
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
  if (p.chain)
    j["chain"] = {{"n_contact", p.chain->n_contact},
                  {"F_n_N", p.chain->F_n_N},
                  {"mu_d_macro_gaussian", p.chain->mu_d_macro_gaussian},
                  {"block_mu_d_macro", p.chain->block_mu_d_macro},
                  {"quadratures", p.chain->quadratures}};
}

}  // namespace sb::theory
