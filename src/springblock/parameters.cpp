#include "springblock/parameters.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

namespace sb {

DerivedParameters derive(const MaterialParameters& mat, const ChainGeometry& geo, double k_int_scale) {
  DerivedParameters d{};
  const double N = geo.N;
  d.l_x_m = geo.L_x_m / N;
  // N-1 springs in series must reproduce the bar stiffness E l_y l_z / L_x.
  d.K_int_N_per_m = k_int_scale * mat.E_Pa * (N - 1.0) * mat.l_z_m * mat.l_y_m / geo.L_x_m;
  // Shear stiffness of one block: G times its base area l_x l_y over its height l_z.
  d.K_s_N_per_m = mat.G_Pa * mat.l_y_m * geo.L_x_m / (mat.l_z_m * N);
  d.m_kg = mat.rho_kg_per_m3 * d.l_x_m * mat.l_y_m * mat.l_z_m;
  d.F_load_N = mat.P_Pa * geo.L_x_m * mat.l_y_m;
  d.omega_s = std::sqrt(d.K_s_N_per_m / d.m_kg);
  // Gershgorin bound of the stiffness matrix: K_s + 4 K_int (attained as N -> infinity).
  d.omega_max = std::sqrt((d.K_s_N_per_m + (geo.N > 1 ? 4.0 : 0.0) * d.K_int_N_per_m) / d.m_kg);
  return d;
}

double rk4_stable_dt(const DerivedParameters& d) { return 2.0 * std::sqrt(2.0) / d.omega_max; }

void to_json(nlohmann::json& j, const MaterialParameters& p) {
  j = {{"G_Pa", p.G_Pa},       {"E_Pa", p.E_Pa},   {"rho_kg_per_m3", p.rho_kg_per_m3},
       {"P_Pa", p.P_Pa},       {"gamma_per_s", p.gamma_per_s},
       {"v_m_per_s", p.v_m_per_s}, {"l_y_m", p.l_y_m}, {"l_z_m", p.l_z_m}};
}
void to_json(nlohmann::json& j, const ChainGeometry& p) { j = {{"N", p.N}, {"L_x_m", p.L_x_m}}; }
void to_json(nlohmann::json& j, const FrictionDistribution& p) {
  j = {{"mu_s_mean", p.mu_s_mean}, {"mu_s_sd", p.mu_s_sd}, {"mu_d_mean", p.mu_d_mean},
       {"mu_d_sd", p.mu_d_sd},
       {"pair_policy", p.pair_policy == FrictionDistribution::PairPolicy::Clip ? "clip" : "keep"},
       {"truncation", "draws below 0 are redrawn (Gaussian truncated at 0)"}};
}
void to_json(nlohmann::json& j, const DerivedParameters& p) {
  j = {{"l_x_m", p.l_x_m}, {"K_int_N_per_m", p.K_int_N_per_m}, {"K_s_N_per_m", p.K_s_N_per_m},
       {"m_kg", p.m_kg},   {"F_load_N", p.F_load_N},           {"omega_s_rad_per_s", p.omega_s},
       {"omega_max_rad_per_s", p.omega_max}};
}

}  // namespace sb
