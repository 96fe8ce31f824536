#include "springblock/integrate/linear/mode_stop.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "springblock/integrate/numerics/first_root.hpp"
#include "springblock/infinity.hpp"
#include "springblock/integrate/numerics/round_off.hpp"

namespace sb::event_detail {
namespace {

// First zero strictly after `from` of the damped-mode trajectory with q(0) = q0, q'(0) = p0
// (infinity if none). Underdamped: q = e^{-alpha tau} R cos(w tau - phi), zeros every pi / w.
// Critical and overdamped: at most one zero, from q0 + P tau = 0 or tanh(k tau) = -q0 k / P.
double next_zero(const DampedMode& m, double q0, double p0, double from) {
  constexpr double kPi = std::numbers::pi;
  const double a = m.alpha, s = m.s, P = p0 + a * q0;
  if (q0 == 0.0 && P == 0.0) return kInf;
  if (s > 0) {
    const double w = m.w;
    const double phi = std::atan2(P / w, q0);
    const double k = std::ceil((w * from - phi - 0.5 * kPi) / kPi);
    double tau = (phi + 0.5 * kPi + k * kPi) / w;
    while (tau <= from) tau += kPi / w;
    return tau;
  }
  if (P == 0.0) return kInf;
  double tau;
  if (s == 0) {
    tau = -q0 / P;
  } else {
    const double k = m.w, r = -q0 * k / P;
    if (!(r > -1.0 && r < 1.0)) return kInf;
    tau = std::atanh(r) / k;
  }
  return tau > from ? tau : kInf;
}

}  // namespace

// x' is monotone between consecutive zeros of x'' (itself a trajectory of the mode, with
// closed-form zeros, next_zero), so each such interval holds at most one stop.
double first_stop_tau(const DampedMode& mode, double x0, double p0, int dir, double v_slider, double t_ref,
                      long long& evals) {
  const double gamma = 2.0 * mode.alpha, w2 = mode.omega2;
  // x'' follows the same mode equation: its initial value and rate.
  const double a0 = -gamma * p0 - w2 * x0, j0 = -gamma * a0 - w2 * p0;
  auto g = [&](double tau, double& x, double& xd) {
    mode.eval(x0, p0, tau, x, xd);
    ++evals;
    return dir * (v_slider + xd);
  };
  // The bracket [lo, hi] (g(lo) >= 0 >= g(hi), g monotone in it) narrowed to round-off in t by
  // first_root_newton: g' = dir x'' comes with every evaluation (x'' = -gamma x' - omega^2 x), so
  // Newton's method converges in a few points where a bisection took ~45 (each an exponential, a
  // sine and a cosine). It starts from hi, the end of an interval between zeros of x''.
  auto slope = [&](double x, double xd) { return dir * (-gamma * xd - w2 * x); };
  auto refine = [&](double lo, double g_lo, double hi, double g_hi, double x_hi, double xd_hi) {
    auto gd = [&](double tau, double& gv, double& dg) {
      double x, xd;
      gv = g(tau, x, xd);
      dg = slope(x, xd);
    };
    return first_root_newton(gd, lo, g_lo, hi, g_hi, [&](double h) { return time_round_off(t_ref + h); }, hi, g_hi,
                             slope(x_hi, xd_hi));
  };
  double lo = 0, x = x0, xd = p0, g_lo = dir * (v_slider + p0);
  for (int interval = 0; interval < 100000; ++interval) {
    // Moving forward faster than the mode can ever swing back (its energy bound sqrt(x'^2 + omega^2 x^2)
    // never increases): no stop, ever. A swing that would reverse the velocity by less than
    // kStopMargin v_s (a creeping block whose v only touches 0) is not a stop either.
    if (dir * v_slider > 0 && std::sqrt(xd * xd + w2 * x * x) <= dir * v_slider * (1.0 + kStopMargin)) return kInf;
    double hi = next_zero(mode, a0, j0, lo);
    if (hi == kInf) {
      // x' is monotone from here on, towards 0: g tends to dir v_s.
      if (dir * v_slider > 0) return kInf;
      double step = 1.0 / std::sqrt(w2 + mode.alpha * mode.alpha);
      hi = lo + step;
      double g_hi;
      while ((g_hi = g(hi, x, xd)) > 0) {
        lo = hi, g_lo = g_hi;
        step *= 2;
        hi = lo + step;
      }
      return refine(lo, g_lo, hi, g_hi, x, xd);
    }
    const double g_hi = g(hi, x, xd);
    if (g_hi <= 0) return refine(lo, g_lo, hi, g_hi, x, xd);
    // Without damping x' is periodic (two intervals per period) and its energy constant: no
    // stop within the first period means none ever (a creeping block touching v = 0 at most).
    if (mode.alpha == 0.0 && interval >= 1) return kInf;
    lo = hi, g_lo = g_hi;
  }
  throw std::runtime_error("uncoupled solver: no end to a sliding phase");
}

}  // namespace sb::event_detail
