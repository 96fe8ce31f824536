#pragma once
// Exact solution of one normal mode q'' + gamma q' + omega^2 q = 0 from q(0) = q0, q'(0) = p0:
//   q(tau) = e^{-alpha tau} [q0 C(tau) + (p0 + alpha q0) S(tau)],  alpha = gamma / 2,
// with C, S the cos / sin-over-frequency pair of s = omega^2 - alpha^2 (cosh / sinh when the mode
// is overdamped, s < 0; 1 and tau at critical damping). One formula covers gamma = 0,
// underdamped, critical and overdamped modes without dividing by a vanishing frequency.
#include <array>
#include <cmath>
#include <limits>

#include "springblock/integrate/numerics/estrin.hpp"
#include "springblock/kernel_clones.hpp"

namespace sb::event_detail {

// A sum of modes as a Taylor polynomial about a point, c[j] = F^(j) / j!, j = 0 .. deg, F =
// sum_k w_k q_k: each mode's derivatives follow from its equation, q^(j+2) = -gamma q^(j+1) -
// omega^2 q^(j), so they cost two flops each. add_taylor adds w times mode (q, qd)'s derivatives
// to c[0 .. deg]; taylor_scale then divides c[j] by j! (c[0] and c[1] are F and F' already).
// Shared by the searches that refine a root on the polynomial (EdgeMarch, the exact stepper).
inline void add_taylor(double w, double q, double qd, double gamma, double omega2, int deg, double* c) {
  double d0 = q, d1 = qd;
  c[0] += w * d0;
  c[1] += w * d1;
  for (int j = 2; j <= deg; ++j) {
    const double d2 = -gamma * d1 - omega2 * d0;
    c[j] += w * d2;
    d0 = d1, d1 = d2;
  }
}
inline void taylor_scale(int deg, double* c) {
  double inv_fact = 1.0;
  for (int j = 2; j <= deg; ++j) inv_fact /= j, c[j] *= inv_fact;
}

// sin x and cos x for |x| <= 1 by their Taylor series to x^17 and x^18: the first omitted terms
// are below 1e-17 of the value, so this is libm's accuracy (within an ulp or two) at a fraction
// of a call's cost, and the same doubles on every machine (no FMA contraction in this library).
// The exact stepper and the searches evaluate modes mostly at such angles (tau up to one step,
// which turns the fastest mode by less than 1 rad).
inline void small_sincos(double x, double& sin_x, double& cos_x) {
  // sin x = x - x y S(y) and cos x = 1 - y C(y), y = x^2, with S(y) = 1/3! - y/5! + y^2/7! - ...
  // and C(y) = 1/2! - y/4! + y^2/6! - ..., each by Estrin's scheme in y (estrin.hpp): a mode
  // evaluation's latency is mostly these two polynomials.
  static constexpr double kS[] = {1.0 / 6.0,          -1.0 / 120.0,           1.0 / 5040.0,
                                  -1.0 / 362880.0,    1.0 / 39916800.0,       -1.0 / 6227020800.0,
                                  1.0 / 1307674368000.0, -1.0 / 355687428096000.0};
  static constexpr double kC[] = {0.5,                   -1.0 / 24.0,          1.0 / 720.0,
                                  -1.0 / 40320.0,        1.0 / 3628800.0,      -1.0 / 479001600.0,
                                  1.0 / 87178291200.0,   -1.0 / 20922789888000.0, 1.0 / 6402373705728000.0};
  const double y = x * x;
  sin_x = x - x * y * estrin<7>(kS, y);
  cos_x = 1.0 - y * estrin<8>(kC, y);
}

// sin x and cos x for |x| < 1e5: x less the nearest multiple n of pi/2 (Cody-Waite: pi/2 in two
// parts, the first with 33 significant bits so that n times it is exact), then small_sincos on
// the remainder (|r| <= pi/4) and the quadrant's swap and signs. The remainder is exact to about
// n 1e-27, far below an ulp of the results; larger x goes to libm.
inline void mode_sincos(double x, double& sin_x, double& cos_x) {
  if (std::fabs(x) <= 1.0) return small_sincos(x, sin_x, cos_x);
  if (!(std::fabs(x) < 1e5)) {
    sin_x = std::sin(x), cos_x = std::cos(x);
    return;
  }
  constexpr double kTwoOverPi = 6.36619772367581382433e-01;
  constexpr double kPio2Hi = 1.57079632673412561417e+00;  // 0x3FF921FB54400000
  constexpr double kPio2Lo = 6.07710050650619224932e-11;  // pi/2 - kPio2Hi
  const double n = std::nearbyint(x * kTwoOverPi);
  const double r = (x - n * kPio2Hi) - n * kPio2Lo;
  double s, c;
  small_sincos(r, s, c);
  switch (static_cast<long long>(n) & 3) {
    case 0: sin_x = s, cos_x = c; break;
    case 1: sin_x = c, cos_x = -s; break;
    case 2: sin_x = -s, cos_x = -c; break;
    default: sin_x = -c, cos_x = s; break;
  }
}

// The state transition of a mode over a fixed interval dt, row-major:
//   (q, q')(tau + dt) = [[P0, P1], [P2, P3]] (q, q')(tau).
using Transition = std::array<double, 4>;

// Mode k moved on by its transition, given element by element (p00[k] is mode k's P0):
// (qn, pn) = P (q, p). The one place the transition is applied; the exact stepper's grid step
// and EdgeMarch's keep their transitions in these four arrays for it.
SB_INLINE void step_mode(int k, const double* __restrict p00, const double* __restrict p01,
                         const double* __restrict p10, const double* __restrict p11, const double* __restrict q,
                         const double* __restrict p, double* __restrict qn, double* __restrict pn) {
  qn[k] = p00[k] * q[k] + p01[k] * p[k];
  pn[k] = p10[k] * q[k] + p11[k] * p[k];
}
// Modes [0, n) moved on: element-wise, so it vectorises.
SB_KERNEL_CLONES inline void step_modes(int n, const double* __restrict p00, const double* __restrict p01,
                                        const double* __restrict p10, const double* __restrict p11,
                                        const double* __restrict q, const double* __restrict p,
                                        double* __restrict qn, double* __restrict pn) {
  for (int k = 0; k < n; ++k) step_mode(k, p00, p01, p10, p11, q, p, qn, pn);
}

struct DampedMode {
  double alpha = 0;   // gamma / 2 [1/s]
  double omega2 = 0;  // omega^2 [1/s^2]
  // Derived once here rather than at every evaluation (the sqrt would sit on each evaluation's
  // critical path): s = omega^2 - alpha^2 and, for an underdamped mode, its frequency sqrt(s).
  // A mode is made by the constructor below and never changed after (nothing assigns alpha or
  // omega2 later, which would leave these stale).
  double s = 0;       // omega^2 - alpha^2 [1/s^2]: > 0 underdamped, < 0 overdamped
  double w = 0;       // sqrt(|s|) [1/s]
  double omega = 0;   // sqrt(omega^2) [1/s] (the searches' grid and bounds)
  double inv_w = 0;   // 1 / w [s] (0 when w = 0): eval_decayed multiplies by it, so no division
                      // waits for the sine at the end of an evaluation's critical path

  DampedMode() = default;
  DampedMode(double alpha_, double omega2_)
      : alpha(alpha_), omega2(omega2_), s(omega2_ - alpha_ * alpha_), w(std::sqrt(std::fabs(s))),
        omega(std::sqrt(omega2_)), inv_w(w > 0 ? 1.0 / w : 0.0) {}
  // The largest |eigenvalue| of q'' + 2 alpha q' + omega^2 q = 0: omega when the mode oscillates
  // or is critical, alpha + sqrt(alpha^2 - omega^2) when it is overdamped.
  double fastest_rate() const { return s < 0 ? alpha + w : omega; }

  // q and q' at tau >= 0.
  void eval(double q0, double p0, double tau, double& q, double& qd) const {
    eval_decayed(q0, p0, tau, decay(tau), q, qd);
  }
  // e^{-alpha tau}: the modes of one run share alpha (damping proportional to mass), so a caller
  // evaluating several of them at one tau takes it once and passes it to eval_decayed, which
  // gives eval's doubles exactly.
  double decay(double tau) const { return std::exp(-alpha * tau); }
  void eval_decayed(double q0, double p0, double tau, double e, double& q, double& qd) const {
    const double x = s * tau * tau;
    double eC, eS;  // e^{-alpha tau} C, e^{-alpha tau} S
    if (std::fabs(x) < 1e-5) {
      // Series: avoids sin(w tau)/w with w -> 0 (near-critical modes, tau -> 0). Products by
      // the reciprocals, not quotients: three divisions were most of this branch's latency.
      eC = e * (1.0 - x * 0.5 + x * x * (1.0 / 24.0));
      eS = e * tau * (1.0 - x * (1.0 / 6.0) + x * x * (1.0 / 120.0));
    } else if (s > 0) {
      const double wt = w * tau;
      double sin_wt, cos_wt;
      mode_sincos(wt, sin_wt, cos_wt);
      eC = e * cos_wt;
      eS = sin_wt * (e * inv_w);
    } else {
      // Overdamped: the two real exponentials taken separately so that neither overflows;
      // the slow rate w - alpha is written as -omega^2 / (alpha + w) (no cancellation).
      const double slow = std::exp(-omega2 / (alpha + w) * tau), fast = std::exp(-(alpha + w) * tau);
      eC = 0.5 * (slow + fast);
      eS = 0.5 * (slow - fast) / w;
    }
    const double P = p0 + alpha * q0;
    q = q0 * eC + P * eS;
    qd = -alpha * q + (P * eC - s * q0 * eS);
  }

  // Modes k in [0, n) at one tau; e^{-alpha tau} is taken once per run of equal alpha.
  template <class Mode, class Out>
  static void eval_all(int n, const Mode& mode, double tau, const Out& out) {
    double alpha_seen = std::numeric_limits<double>::quiet_NaN(), e = 0;
    for (int k = 0; k < n; ++k) {
      const DampedMode& m = mode(k);
      if (!(m.alpha == alpha_seen)) e = m.decay(tau), alpha_seen = m.alpha;
      out(k, m, e);
    }
  }

  // The transition over dt: its columns are the solutions from (1, 0) and from (0, 1).
  Transition transition(double dt) const {
    Transition P;
    eval(1.0, 0.0, dt, P[0], P[2]);
    eval(0.0, 1.0, dt, P[1], P[3]);
    return P;
  }
};

}  // namespace sb::event_detail
