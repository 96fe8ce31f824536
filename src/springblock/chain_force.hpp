#pragma once
// The chain's right-hand side, written once: the force on block i from its slider spring
// K_s (x_slider - u_i), its damping -m gamma v_i and its internal springs to the blocks beside
// it, minus a given friction force f (0 for a stuck block's driving force, its signed kinetic
// friction for a sliding one). Every user reads it from here: the switching rules and observers
// (Chain::driving_force), both steppers' accelerations (chain_accel) and RK4's switch screen.
//
// Two forms, because they round differently and each caller must stay consistent with itself:
//   force_checked   any block; each existing neighbour's spring added separately (a free chain
//                   end has one);
//   force_interior  0 < i < N - 1; the two springs as K_int (u_{i-1} - 2 u_i + u_{i+1}), one
//                   product fewer and branch-free, so the steppers' inner loops vectorise.
// Coupled / Damped drop the internal springs / the damping at compile time for a scene without
// them (the kernels are specialised on the effects present).
#include "springblock/kernel_clones.hpp"

namespace sb {

struct ForceCoefficients {
  int N;
  double K_s, K_int, m_gamma;  // m_gamma = m * gamma
};

template <bool Coupled, bool Damped>
SB_INLINE double force_checked(const ForceCoefficients& k, int i, double x_slider, const double* u, const double* v,
                               double f) {
  double F = k.K_s * (x_slider - u[i]) - f;
  if constexpr (Damped) F -= k.m_gamma * v[i];
  if constexpr (Coupled) {
    if (i > 0) F += k.K_int * (u[i - 1] - u[i]);
    if (i + 1 < k.N) F += k.K_int * (u[i + 1] - u[i]);
  }
  return F;
}

template <bool Coupled, bool Damped>
SB_INLINE double force_interior(const ForceCoefficients& k, int i, double x_slider, const double* u, const double* v,
                                double f) {
  double F = k.K_s * (x_slider - u[i]) - f;
  if constexpr (Damped) F -= k.m_gamma * v[i];
  if constexpr (Coupled) F += k.K_int * (u[i - 1] - 2.0 * u[i] + u[i + 1]);
  return F;
}

}  // namespace sb
