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
//
// A chain whose blocks differ in slider spring, mass or internal springs reads them per block
// (BlockForceCoefficients, overloads of the same two forms); a uniform chain's kernels never see
// those arrays, so they stay what they are.
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

// Per-block coefficients: K_s[i], m_gamma[i] = m_i gamma, and K_int[i] the spring between blocks
// i and i + 1.
struct BlockForceCoefficients {
  int N;
  const double* K_s;
  const double* K_int;
  const double* m_gamma;
};

template <bool Coupled, bool Damped>
SB_INLINE double force_checked(const BlockForceCoefficients& k, int i, double x_slider, const double* u,
                               const double* v, double f) {
  double F = k.K_s[i] * (x_slider - u[i]) - f;
  if constexpr (Damped) F -= k.m_gamma[i] * v[i];
  if constexpr (Coupled) {
    if (i > 0) F += k.K_int[i - 1] * (u[i - 1] - u[i]);
    if (i + 1 < k.N) F += k.K_int[i] * (u[i + 1] - u[i]);
  }
  return F;
}

// force_checked on an interior block (0 < i < N - 1) without its end tests: the same additions,
// so the same doubles, in a loop that vectorises (the friction observer's stuck forces).
template <bool Damped>
SB_INLINE double force_checked_interior(const BlockForceCoefficients& k, int i, double x_slider, const double* u,
                                        const double* v, double f) {
  double F = k.K_s[i] * (x_slider - u[i]) - f;
  if constexpr (Damped) F -= k.m_gamma[i] * v[i];
  F += k.K_int[i - 1] * (u[i - 1] - u[i]);
  F += k.K_int[i] * (u[i + 1] - u[i]);
  return F;
}

template <bool Coupled, bool Damped>
SB_INLINE double force_interior(const BlockForceCoefficients& k, int i, double x_slider, const double* u,
                                const double* v, double f) {
  double F = k.K_s[i] * (x_slider - u[i]) - f;
  if constexpr (Damped) F -= k.m_gamma[i] * v[i];
  if constexpr (Coupled) F += k.K_int[i - 1] * (u[i - 1] - u[i]) + k.K_int[i] * (u[i + 1] - u[i]);
  return F;
}

}  // namespace sb
