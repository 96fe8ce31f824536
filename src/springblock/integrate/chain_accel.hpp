#pragma once
// Acceleration of every block for the event-driven integrator, with the contact phase frozen:
// a stuck block has mobile = 0 (it neither accelerates nor moves), a sliding block feels its
// signed kinetic friction f_kin. Specialised at compile time on the smooth effects present so
// a scene without internal springs or damping does not pay for them.
#include "springblock/model.hpp"

namespace sb::event_detail {

template <bool Coupled, bool Damped>
inline void chain_accel(const Chain& c, const double* __restrict u, const double* __restrict v, double t,
                        const double* __restrict mobile, const double* __restrict f_kin,
                        double* __restrict a) {
  const int N = c.N;
  const double Ks = c.K_s, Ki = c.K_int, mg = c.m * c.gamma, inv_m = 1.0 / c.m;
  const double slider = c.v_slider * t;
  for (int i = 0; i < N; ++i) {
    double f = Ks * (slider - u[i]) - f_kin[i];
    if constexpr (Damped) f -= mg * v[i];
    if constexpr (Coupled) {
      // Free chain ends: an end block has a single internal spring.
      if (i > 0) f += Ki * (u[i - 1] - u[i]);
      if (i + 1 < N) f += Ki * (u[i + 1] - u[i]);
    }
    a[i] = mobile[i] * inv_m * f;
  }
}

}  // namespace sb::event_detail
