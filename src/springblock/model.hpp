#pragma once
// The spring-block chain as a dynamical system (the "system" in odeint's vocabulary):
// stiffnesses, mass, per-block friction thresholds and the forces they produce.
// It knows nothing about time stepping or observation.
#include <algorithm>
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

// The slider springs, masses and internal springs of a chain whose blocks differ in them; empty on
// a uniform chain, which reads Chain::K_s, K_int and m. Damping keeps the form m_i gamma v_i.
struct BlockMechanics {
  std::vector<double> K_s;      // slider spring of block i
  std::vector<double> K_int;    // spring between blocks i and i + 1 (the last entry, 0, has no spring)
  std::vector<double> m;        // mass of block i
  std::vector<double> m_gamma;  // m_i gamma
  std::vector<double> inv_m;    // 1 / m_i: the steppers multiply, a division costs several times more
  bool uniform() const { return K_s.empty(); }
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
  BlockMechanics blocks;  // per-block springs and masses; empty when the chain is uniform

  Effects effects() const { return {K_int > 0, gamma > 0, n_contact < N}; }
  bool uniform() const { return blocks.uniform(); }
  // Block i's slider spring and mass, and the spring between blocks i and i + 1: the chain's own
  // values on a uniform chain (the same doubles), the block's where they differ.
  double k_s(int i) const { return blocks.uniform() ? K_s : blocks.K_s[i]; }
  double mass(int i) const { return blocks.uniform() ? m : blocks.m[i]; }
  double spring(int i) const { return blocks.uniform() ? K_int : blocks.K_int[i]; }
  // The spring between neighbours i and j = i +- 1.
  double spring_between(int i, int j) const { return spring(i < j ? i : j); }
  // sqrt((K_s + 4 K_int) / m): every run's modes are slower (its stiffness matrix's rows sum to
  // at most K_s + 4 K_int by Gershgorin). The steppers' and searches' time scale. Per block, the
  // largest sqrt((K_s,i + 2 K_int,i-1 + 2 K_int,i) / m_i), by Gershgorin on M^-1 K.
  double omega_max() const {
    if (blocks.uniform()) return std::sqrt((K_s + 4.0 * K_int) / m);
    double w2 = 0;
    for (int i = 0; i < N; ++i)
      w2 = std::max(w2, (blocks.K_s[i] + 2.0 * (i > 0 ? blocks.K_int[i - 1] : 0.0) + 2.0 * blocks.K_int[i]) / blocks.m[i]);
    return std::sqrt(w2);
  }

  // Net non-friction force on block i (slider spring + internal springs + damping) at time t.
  // Free chain ends: the end blocks have one neighbour.
  double driving_force(int i, const double* u, const double* v, double t) const {
    if (!blocks.uniform()) return force_checked<true, true>(block_force_coefficients(), i, v_slider * t, u, v, 0.0);
    return force_checked<true, true>(force_coefficients(), i, v_slider * t, u, v, 0.0);
  }
  ForceCoefficients force_coefficients() const { return {N, K_s, K_int, m * gamma}; }
  BlockForceCoefficients block_force_coefficients() const {
    return {N, blocks.K_s.data(), blocks.K_int.data(), blocks.m_gamma.data()};
  }
};

}  // namespace sb
