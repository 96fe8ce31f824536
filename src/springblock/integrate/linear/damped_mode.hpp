#pragma once
// Exact solution of one normal mode q'' + gamma q' + omega^2 q = 0 from q(0) = q0, q'(0) = p0:
//   q(tau) = e^{-alpha tau} [q0 C(tau) + (p0 + alpha q0) S(tau)],  alpha = gamma / 2,
// with C, S the cos / sin-over-frequency pair of s = omega^2 - alpha^2 (cosh / sinh when the mode
// is overdamped, s < 0; 1 and tau at critical damping). One formula covers gamma = 0,
// underdamped, critical and overdamped modes without dividing by a vanishing frequency.
#include <array>
#include <cmath>
#include <limits>

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

// The state transition of a mode over a fixed interval dt, row-major:
//   (q, q')(tau + dt) = [[P0, P1], [P2, P3]] (q, q')(tau).
using Transition = std::array<double, 4>;

struct DampedMode {
  double alpha = 0;   // gamma / 2 [1/s]
  double omega2 = 0;  // omega^2 [1/s^2]

  // q and q' at tau >= 0.
  void eval(double q0, double p0, double tau, double& q, double& qd) const {
    eval_decayed(q0, p0, tau, decay(tau), q, qd);
  }
  // e^{-alpha tau}: the modes of one run share alpha (damping proportional to mass), so a caller
  // evaluating several of them at one tau takes it once and passes it to eval_decayed, which
  // gives eval's doubles exactly.
  double decay(double tau) const { return std::exp(-alpha * tau); }
  void eval_decayed(double q0, double p0, double tau, double e, double& q, double& qd) const {
    const double s = omega2 - alpha * alpha;
    const double x = s * tau * tau;
    double eC, eS;  // e^{-alpha tau} C, e^{-alpha tau} S
    if (std::fabs(x) < 1e-5) {
      // Series: avoids sin(w tau)/w with w -> 0 (near-critical modes, tau -> 0).
      eC = e * (1.0 - x / 2.0 + x * x / 24.0);
      eS = e * tau * (1.0 - x / 6.0 + x * x / 120.0);
    } else if (s > 0) {
      const double w = std::sqrt(s);
      eC = e * std::cos(w * tau);
      eS = e * std::sin(w * tau) / w;
    } else {
      // Overdamped: the two real exponentials taken separately so that neither overflows;
      // the slow rate kappa - alpha is written as -omega^2 / (alpha + kappa) (no cancellation).
      const double k = std::sqrt(-s);
      const double slow = std::exp(-omega2 / (alpha + k) * tau), fast = std::exp(-(alpha + k) * tau);
      eC = 0.5 * (slow + fast);
      eS = 0.5 * (slow - fast) / k;
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
