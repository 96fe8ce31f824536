#pragma once
// The event method's step-size control (the "control" layer, as in GSL's odeiv2): error scales,
// the first step, and the next step after an accepted or rejected trial. Knows nothing of events
// or samples; the evolve step tells it whether the trial was clipped to a stop time.
#include <algorithm>
#include <cmath>

#include "springblock/model.hpp"

namespace sb::event_detail {

class StepControl {
 public:
  // Error scales: the spring stretch at the threshold, F_n / K_s, and the velocity of an
  // oscillation of that amplitude at the slider frequency; rtol = tol. The first step resolves
  // the fastest mode of the chain, sqrt((K_s + 4 K_int) / m), to the order-5 tolerance.
  StepControl(const Chain& c, double tol) {
    const double len = c.F_n / c.K_s, omega_s = std::sqrt(c.K_s / c.m);
    atol_u_ = tol * len, atol_v_ = tol * omega_s * len, rtol_ = tol;
    h_ = 0.5 * std::pow(tol, 0.2) / c.omega_max();
  }

  double atol_u() const { return atol_u_; }
  double atol_v() const { return atol_v_; }
  double rtol() const { return rtol_; }

  // The trial step from t: the proposed step, or less to land exactly on t_stop (clipped).
  double trial(double t, double t_stop, bool& clipped) const {
    clipped = t + h_ >= t_stop;
    return clipped ? t_stop - t : h_;
  }
  // err in units of the tolerance (accept if <= 1; NaN rejects).
  static bool acceptable(double err) { return err <= 1.0; }
  // After a rejected trial: shrink, never grow.
  void rejected(double h_try, double err) { h_ = h_try * std::min(factor(err), 1.0); }
  // After an accepted trial: grow or shrink by the error; a trial clipped to a stop time says
  // little about the step the dynamics allows, so it never shrinks the proposal.
  void accepted(double h_try, double err, bool clipped) {
    const double f = factor(err);
    h_ = clipped ? std::max(h_, h_try * f) : h_try * f;
  }

 private:
  // Order-5 controller with safety 0.9, limited to [0.2, 5]. The limits bind for err below
  // (0.9 / 5)^5 = 1.89e-4 and above (0.9 / 0.2)^5 = 1845; outside a margin around those the pow
  // (2 to 3 per cent of a smooth chain's run, perf) is not taken, and the factor is the same
  // double either way.
  static double factor(double err) {
    if (err < 1.8e-4) return 5.0;
    if (err > 2000.0) return 0.2;
    return std::clamp(0.9 * std::pow(err, -0.2), 0.2, 5.0);
  }

  double atol_u_, atol_v_, rtol_, h_;
};

}  // namespace sb::event_detail
