#pragma once
// Physical parameters of the spring-block model and the quantities derived from them.
// All values SI. Defaults are the paper's table of default parameters.
#include <nlohmann/json_fwd.hpp>

namespace sb {

struct MaterialParameters {
  double G_Pa = 5e6;              // shear modulus
  double E_Pa = 15e6;             // Young's modulus
  double rho_kg_per_m3 = 1200.0;  // 1.2 g/cm^3
  double P_Pa = 1e6;              // total load pressure
  double gamma_per_s = 1e4;       // viscous damping rate, 10 /ms
  double v_m_per_s = 5e-4;        // slider velocity, 0.05 cm/s
  double l_y_m = 0.01;            // transversal width, 1 cm
  double l_z_m = 0.001;           // height, 0.1 cm
};

struct ChainGeometry {
  int N = 200;          // number of blocks
  double L_x_m = 0.04;  // total length, 4.0 cm
};

// Micro-coefficient distribution: independent Gaussians, one draw per block and repetition.
struct FrictionDistribution {
  double mu_s_mean = 1.0, mu_s_sd = 0.1;
  double mu_d_mean = 0.5, mu_d_sd = 0.01;
  // What to do with a pair whose mu_d draw exceeds its mu_s draw. Kinetic friction above
  // static friction makes a block that starts to slip decelerate at once (a creep at the
  // threshold, not a slip); the paper is silent, so by default we clip mu_d to mu_s.
  enum class PairPolicy { Clip, Keep } pair_policy = PairPolicy::Clip;
};

// Stiffnesses, mass and loads that follow from the parameters (paper, section "The Model").
struct DerivedParameters {
  double l_x_m;         // L_x / N
  double K_int_N_per_m; // E (N-1) l_z l_y / L_x, times the user's k_int_scale
  double K_s_N_per_m;   // G l_y L_x / (l_z N)
  double m_kg;          // rho l_x l_y l_z
  double F_load_N;      // P L_x l_y, spread over the blocks in contact
  double omega_s;       // sqrt(K_s/m): the slider oscillation frequency of one block
  double omega_max;     // sqrt((K_s + 4 K_int)/m): highest normal-mode frequency of the chain
};

DerivedParameters derive(const MaterialParameters& mat, const ChainGeometry& geo, double k_int_scale);

// Largest RK4 step that keeps the undamped chain stable: h * omega_max <= 2*sqrt(2).
// (RK4's stability region meets the imaginary axis at |z| = 2 sqrt 2 ~ 2.83.)
double rk4_stable_dt(const DerivedParameters& d);

void to_json(nlohmann::json& j, const MaterialParameters& p);
void to_json(nlohmann::json& j, const ChainGeometry& p);
void to_json(nlohmann::json& j, const FrictionDistribution& p);
void to_json(nlohmann::json& j, const DerivedParameters& p);

}  // namespace sb
