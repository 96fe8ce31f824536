#include "springblock/integrate/linear/mode_stop.hpp"

#include <cmath>
#include <stdexcept>

#include "springblock/integrate/infinity.hpp"
#include "springblock/integrate/linear/mode_zero.hpp"
#include "springblock/integrate/round_off.hpp"

namespace sb::event_detail {

// x' is monotone between consecutive zeros of x'' (itself a trajectory of the mode, with
// closed-form zeros, mode_zero.hpp), so each such interval holds at most one stop.
double first_stop_tau(const DampedMode& mode, double x0, double p0, int dir, double v_slider, double t_ref,
                      long long& evals) {
  const int d = dir;
  const double vs = v_slider, gamma = 2.0 * mode.alpha, w2 = mode.omega2;
  // x'' follows the same mode equation: its initial value and rate.
  const double a0 = -gamma * p0 - w2 * x0, j0 = -gamma * a0 - w2 * p0;
  auto g = [&](double tau, double& x, double& xd) {
    mode.eval(x0, p0, tau, x, xd);
    ++evals;
    return d * (vs + xd);
  };
  // The bracket [lo, hi] (g(lo) >= 0 >= g(hi), g monotone in it) narrowed to round-off in t,
  // as a bisection would, but by Newton's method: g' = d x'' comes with every evaluation
  // (x'' = -gamma x' - omega^2 x). Each point is the Newton point of the last evaluation aimed a
  // quarter of the final width past its root, so that once the root is known that well the
  // point lands beyond it and closes the bracket; a point outside the bracket, or two steps in a
  // row that did not halve it, give way to a bisection. (From the far side of a root, Newton's
  // point falls short of it by its curvature; the next one, from the near side, then closes
  // the bracket: first_root_newton's rule of one regula falsi step after every Newton step
  // that did not halve the bracket turned this into a bisection of the far side, ~45 points.)
  auto refine = [&](double lo, double hi, double x_hi, double xd_hi) {
    double at = hi, ga = d * (vs + xd_hi), dga = d * (-gamma * xd_hi - w2 * x_hi);
    int stalled = 0;
    for (int it = 0; it < 200; ++it) {
      const double w = hi - lo, tol = time_round_off(t_ref + hi);
      if (!(w > tol)) break;
      double next = 0.5 * (lo + hi);
      if (dga != 0 && stalled < 2) {
        const double step = -ga / dga, aim = at + step + std::copysign(0.25 * tol, step);
        if (aim > lo && aim < hi) next = aim;
      }
      double x, xd;
      ga = g(next, x, xd);
      dga = d * (-gamma * xd - w2 * x);
      at = next;
      (ga > 0 ? lo : hi) = next;
      stalled = hi - lo > 0.5 * w ? stalled + 1 : 0;
    }
    return hi;
  };
  double lo = 0, x = x0, xd = p0;
  for (int interval = 0; interval < 100000; ++interval) {
    // Moving forward faster than the mode can ever swing back: no stop, ever. A swing that would
    // reverse the velocity by less than 1e-12 v_s (a creeping block whose v only touches 0) is
    // not a stop either.
    if (d * vs > 0 && std::sqrt(xd * xd + w2 * x * x) <= d * vs * (1.0 + 1e-12)) return kInf;
    double hi = next_zero(mode, a0, j0, lo);
    if (hi == kInf) {
      // x' is monotone from here on, towards 0: g tends to d v_s.
      if (d * vs > 0) return kInf;
      double step = 1.0 / std::sqrt(w2 + mode.alpha * mode.alpha);
      hi = lo + step;
      while (g(hi, x, xd) > 0) {
        lo = hi;
        step *= 2;
        hi = lo + step;
      }
      return refine(lo, hi, x, xd);
    }
    if (g(hi, x, xd) <= 0) return refine(lo, hi, x, xd);
    // Without damping x' is periodic (two intervals per period) and its energy constant: no
    // stop within the first period means none ever (a creeping block touching v = 0 at most).
    if (mode.alpha == 0.0 && interval >= 1) return kInf;
    lo = hi;
  }
  throw std::runtime_error("uncoupled solver: no end to a sliding phase");
}

}  // namespace sb::event_detail
