#pragma once
// How long a run's transient lasts: a bound, from the modal coordinates at the start, on every
// row's deviation from the affine path. Written once for the quiet phase (when groove modes stop
// changing a double, or a sample) and the modal runs (when a groove run has settled); and a
// bound, for any damping, on one row's deviation at every later time (row_deviation_bound).
//
// An underdamped mode (s = omega^2 - alpha^2 > 0, w = sqrt(s)) from (q0, p0) is
//   q = e^{-alpha tau} (q0 cos w tau + (P / w) sin w tau),  P = p0 + alpha q0,
// so |q| <= e^{-alpha tau} C with C = hypot(q0, P / w), and q' is a sinusoid of amplitude
// hypot(P - alpha q0, alpha P / w + w q0) = omega C, so |q'| <= e^{-alpha tau} omega C. The rows
// mix the modes with |Q_rk| <= 1, so the sums over modes bound every row. All modes share
// alpha = gamma / 2. With no damping, or a mode not underdamped, no bound is taken.
#include <algorithm>
#include <cmath>
#include <limits>

#include "springblock/integrate/linear/run_shape.hpp"

namespace sb::event_detail {

// The scales in u and v below which a transient counts as gone (time_below's eps_u, eps_v).
struct Scales {
  double u = 0, v = 0;
};

struct TransientEnvelope {
  double u = 0, v = 0;  // bounds on every row's |u - path| and |v - drift| at tau = 0
  double alpha = 0;     // decay rate of both (0: no bound, the transient is kept for ever)

  // The time after which the bounds are below eps_u and eps_v (infinity without a bound).
  double time_below(double eps_u, double eps_v) const {
    if (!(alpha > 0) || !(eps_u > 0) || !(eps_v > 0)) return std::numeric_limits<double>::infinity();
    return std::max({0.0, std::log(u / eps_u) / alpha, std::log(v / eps_v) / alpha});
  }
};

// q0, p0: the run's modal coordinates (one per mode of b).
inline TransientEnvelope transient_envelope(const RunShape& b, const double* q0, const double* p0) {
  TransientEnvelope e;
  for (int k = 0; k < b.n; ++k) {
    const DampedMode& m = b.modes[k];
    if (!(m.alpha > 0) || !(m.s > 0)) return TransientEnvelope{};
    // sqrt of the sum of squares, not hypot (several times dearer): displacements in m and
    // velocities over rates are far from the squares' overflow and underflow.
    const double P = p0[k] + m.alpha * q0[k], Pw = P / m.w;
    const double C = std::sqrt(q0[k] * q0[k] + Pw * Pw);
    e.u += C;
    e.v += C * m.omega;
    e.alpha = m.alpha;
  }
  return e;
}

// Each mode's energy E = qd^2 + omega^2 q^2 never grows (damping only removes it, whatever its
// strength), so |q_k| <= sqrt(E_k) / omega_k at every time after the start, and row r of the run
// deviates from its affine path by at most sum_k |Q_rk| times that. From the modes (q0, p0), or
// from sqrt(E_k) per mode (sE).
inline double row_deviation_bound(const RunShape& b, int row, const double* q0, const double* p0) {
  double a = 0;
  const double* Q = b.row(row);
  for (int k = 0; k < b.n; ++k) {
    const double w2 = b.spectrum.w2[k];
    a += std::fabs(Q[k]) * std::sqrt((p0[k] * p0[k] + w2 * q0[k] * q0[k]) / w2);
  }
  return a;
}
inline double row_deviation_bound(const RunShape& b, int row, const double* sE) {
  double a = 0;
  const double* Q = b.row(row);
  for (int k = 0; k < b.n; ++k) a += std::fabs(Q[k]) * sE[k] * b.spectrum.inv_omega[k];
  return a;
}

// The same energies bound the row's derivatives: |q^(j)| <= c_j sqrt(E) (RunShape::c), so
// |u^(j)| <= sum_k |Q_rk| c_jk sqrt(E_k), j = 2 .. 5 into out[0 .. 3].
inline void row_derivative_bounds(const RunShape& b, int row, const double* sE, double out[4]) {
  double d[4] = {0, 0, 0, 0};
  const double* Q = b.row(row);
  for (int k = 0; k < b.n; ++k) {
    const double w = std::fabs(Q[k]) * sE[k];
    for (int j = 0; j < 4; ++j) d[j] += w * b.spectrum.c[j][k];
  }
  for (int j = 0; j < 4; ++j) out[j] = d[j];
}

}  // namespace sb::event_detail
