#pragma once
// The spring-block chain as a dynamical system (the "system" in odeint's vocabulary):
// stiffnesses, mass, per-block friction thresholds and the forces they produce.
// It knows nothing about time stepping or observation.
#include <cmath>
#include <cstdint>
#include <vector>

#include "springblock/chain_force.hpp"
#include "springblock/parameters.hpp"

namespace sb {

// Which smooth effects are present; integrators specialise their kernels on these at compile
// time so a scene pays only for the physics it contains.
struct Effects {
  bool coupled;  // K_int > 0
  bool damped;   // gamma > 0
  bool free_blocks;  // some blocks sit in grooves (never stick)
};

struct Chain {
  int N = 0;
  double K_s = 0, K_int = 0, m = 0, gamma = 0, v_slider = 0;
  double F_n = 0;       // normal force on each block in contact
  double F_load = 0;    // total normal load, N_contact * F_n
  std::vector<std::uint8_t> contact;  // 1 = pawl (frictional), 0 = groove (frictionless)
  std::vector<double> f_static;   // mu_s,i F_n: static threshold force (0 in grooves)
  std::vector<double> f_kinetic;  // mu_d,i F_n: kinetic friction force (0 in grooves)
  std::vector<double> mu_s, mu_d; // the drawn micro coefficients (0 in grooves)
  int n_contact = 0;

  Effects effects() const { return {K_int > 0, gamma > 0, n_contact < N}; }
  // sqrt((K_s + 4 K_int) / m): every run's modes are slower (its stiffness matrix's rows sum to
  // at most K_s + 4 K_int by Gershgorin). The steppers' and searches' time scale.
  double omega_max() const { return std::sqrt((K_s + 4.0 * K_int) / m); }

  // Net non-friction force on block i (slider spring + internal springs + damping) at time t.
  // Free chain ends: the end blocks have one neighbour.
  double driving_force(int i, const double* u, const double* v, double t) const {
    return force_checked<true, true>(force_coefficients(), i, v_slider * t, u, v, 0.0);
  }
  ForceCoefficients force_coefficients() const { return {N, K_s, K_int, m * gamma}; }
};

}  // namespace sb
