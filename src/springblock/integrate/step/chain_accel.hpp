#pragma once
// Acceleration of blocks lo..hi-1 for the event-driven integrator, with the contact phase frozen:
// a stuck block has mobile = 0 (it neither accelerates nor moves), a sliding block feels its
// signed kinetic friction f_kin. Specialised at compile time on the smooth effects present so a
// scene without internal springs or damping does not pay for them. The neighbours lo-1 and hi
// are read from u (they are stuck blocks while the span is stepped). The chain's free ends are
// peeled off so the interior loop has no branch and vectorises.
#include "springblock/chain_force.hpp"
#include "springblock/kernel_clones.hpp"
#include "springblock/model.hpp"

namespace sb::event_detail {

// PerBlock: a chain whose blocks differ in slider spring, mass or internal springs, each block's
// force over its own mass; otherwise the uniform chain's coefficients and one mass.
template <bool Coupled, bool Damped, bool PerBlock>
SB_INLINE void chain_accel(const Chain& c, int lo, int hi, const double* __restrict u, const double* __restrict v,
                           double t, const double* __restrict mobile, const double* __restrict f_kin,
                           double* __restrict a) {
  const int N = c.N;
  const auto k = [&c] {
    if constexpr (PerBlock) return c.block_force_coefficients();
    else return c.force_coefficients();
  }();
  const double* __restrict inv_m = c.blocks.inv_m.data();  // PerBlock only
  const double inv_m0 = 1.0 / c.m, slider = c.v_slider * t;
  auto one = [&](int i) {  // with the end checks
    a[i] = mobile[i] * (PerBlock ? inv_m[i] : inv_m0) * force_checked<Coupled, Damped>(k, i, slider, u, v, f_kin[i]);
  };
  int first = lo, last = hi;
  if (first == 0 && first < last) one(first++);
  if (last == N && first < last) one(--last);
  for (int i = first; i < last; ++i)
    a[i] = mobile[i] * (PerBlock ? inv_m[i] : inv_m0) * force_interior<Coupled, Damped>(k, i, slider, u, v, f_kin[i]);
}

// Either, as the chain is: the steppers of the event method, which step a few spans per stage.
template <bool Coupled, bool Damped>
SB_INLINE void chain_accel_of(const Chain& c, int lo, int hi, const double* __restrict u, const double* __restrict v,
                              double t, const double* __restrict mobile, const double* __restrict f_kin,
                              double* __restrict a) {
  if (c.uniform()) chain_accel<Coupled, Damped, false>(c, lo, hi, u, v, t, mobile, f_kin, a);
  else chain_accel<Coupled, Damped, true>(c, lo, hi, u, v, t, mobile, f_kin, a);
}

}  // namespace sb::event_detail
