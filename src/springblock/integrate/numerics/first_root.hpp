#pragma once
// The event search's refinement of a bracket: the crossed end of [lo, hi] of an event function g
// with g(lo) > 0 >= g(hi), narrowed until the bracket is no wider than width(hi).
//
// Regula falsi with the Anderson-Bjorck rule (the value of a bracket end that stays put twice in
// a row is scaled down, kept_scale, so neither end can stall; 5 % fewer evaluations per root of
// the exact stepper's screen than Illinois' halving, paper/choices.md), each point kept half the
// final width inside the bracket (an estimate good to that closes the bracket from the far side
// with the next point), and a bisection whenever the bracket has not halved over the last two
// evaluations, unless |g| fell eightfold over them (at most 8 points in a row): regula falsi
// closing in on a root from one side leaves the far end put, so the bracket does not halve
// although every point gains digits, and a forced bisection there is a wasted point (the
// screen's polynomials: 6.9 to 7.5 evaluations per refined root, against 8.8 to 10.0 when
// bisecting on every such pair, paper/choices.md). The result has
// what a bisection's has: g(result) <= 0 (or NaN) within the final width of a point with g > 0.
// On the continuous extension of a Dormand-Prince step, which is a quartic, it takes ~7
// evaluations per event where a bisection to round-off in t took ~29 (measured on smooth and
// periodic:10,10 chains, N = 360), and the bisection's were most of the search's time.
//
// g(lo) <= 0 is allowed where lo is the start of the step: a block that has just switched may sit
// on its threshold there (g = 0); the first point is then a bisection's, as is every point after
// a NaN. EdgeMarch refines its brackets with a slope from every evaluation (Newton's method
// first, first_root_newton below); the continuous extension has no slope at hand, so first_root
// is the derivative-free form.
#include <algorithm>
#include <cmath>

#include "springblock/infinity.hpp"

namespace sb::event_detail {

// The Anderson-Bjorck factor for the value kept at a bracket end while the other end moves a
// second time: 1 - g_new / g_old of the moving end, or the Illinois 1/2 when that is not in
// (0, 1) (the new point no closer to zero, or g_old = 0 or NaN).
inline double kept_scale(double g_new, double g_old) {
  const double m = g_old != 0 ? 1.0 - g_new / g_old : 0.0;
  return m > 0 && m < 1 ? m : 0.5;
}

// Width(hi): the largest final width of a bracket ending at hi (in the units of lo and hi).
template <class G, class Width>
double first_root(G g, double lo, double g_lo, double hi, double g_hi, Width width) {
  int moved = 0;              // the end that moved last: -1 lo, +1 hi
  double w1 = 2 * (hi - lo);  // the bracket's width one and two evaluations ago
  double w2 = w1;
  double a1 = kInf, a2 = kInf;  // |g| at the last two points (none yet)
  int slow = 0;                   // points in a row after which the bracket had not halved
  for (int it = 0; it < 200; ++it) {
    const double w = hi - lo, margin = 0.5 * width(hi);
    if (!(w > 2 * margin)) break;
    double x = lo + 0.5 * w;
    const bool halved = w <= 0.5 * w2, closing = a1 <= 0.125 * a2 && slow < 8;
    if (g_lo > 0 && g_hi <= 0 && (halved || closing))
      x = std::clamp(lo + w * (g_lo / (g_lo - g_hi)), lo + margin, hi - margin);
    slow = halved ? 0 : slow + 1;
    w2 = w1, w1 = w;
    const double gx = g(x);
    a2 = a1, a1 = std::fabs(gx);
    if (gx > 0) {
      if (moved < 0) g_hi *= kept_scale(gx, g_lo);
      lo = x, g_lo = gx;
      moved = -1;
    } else {
      if (moved > 0) g_lo *= kept_scale(gx, g_hi);
      hi = x, g_hi = gx;
      moved = 1;
    }
  }
  return hi;
}

// The same bracket [lo, hi] (g(lo) > 0 >= g(hi)) shrunk with the slope every evaluation gives:
// gd(x, g, dg) evaluates g and g' at x. The next point is Newton's from the last evaluation,
// aimed a quarter of the final width past its root estimate, so that once the estimate is that
// good the point lands on the far side and closes the bracket. A Newton point outside the
// bracket, or two Newton steps in a row that did not halve it, hand one iteration to regula falsi
// with the Illinois modification (bisection when the secant point is not well inside), which
// keeps the bracket at every iteration. One such Newton step is not enough to give up on Newton:
// a Newton point from the far side of a root falls short of it by its curvature, onto the near
// side, and the next one closes the bracket (EdgeMarch's roots: ~4.5 evaluations, against ~11
// when that next point went to regula falsi). The bracket stops when no wider than width(hi);
// the result is the crossed end hi. (x, gx, dgx): an evaluation inside the bracket to start from (x = +inf: none;
// the first point is then regula falsi's). EdgeMarch's searches use it; on the exact stepper's
// event polynomials, where the slope costs a second polynomial, it measured 1.04 to 1.12 times
// first_root's time per slip start (paper/choices.md), so the screen keeps first_root.
template <class GD, class Width>
double first_root_newton(GD gd, double lo, double glo, double hi, double ghi, Width width, double x, double gx,
                         double dgx) {
  int kept = 0;  // +1: lo kept last time, -1: hi kept last time
  int stalled = 0;  // Newton points in a row after which the bracket had not halved
  for (int it = 0; it < 200; ++it) {
    const double w = hi - lo, tol = width(hi);
    if (!(w > tol)) break;
    double mid = kInf;
    if (x != kInf && dgx != 0 && stalled < 2) {  // x, gx, dgx: the last evaluation, if any
      const double step = -gx / dgx;
      mid = x + step + std::copysign(0.25 * tol, step);
      if (!(mid > lo && mid < hi)) mid = kInf;
    }
    const bool was_newton = mid != kInf;
    if (!was_newton) {
      mid = hi - ghi * (hi - lo) / (ghi - glo);
      if (!(mid > lo + 1e-3 * w && mid < hi - 1e-3 * w)) mid = 0.5 * (lo + hi);
    }
    gd(mid, gx, dgx);
    x = mid;
    if (gx > 0) {
      lo = mid, glo = gx;
      if (kept == -1) ghi *= 0.5;
      kept = -1;
    } else {
      hi = mid, ghi = gx;
      if (kept == 1) glo *= 0.5;
      kept = 1;
    }
    stalled = was_newton && hi - lo > 0.5 * w ? stalled + 1 : 0;
  }
  return hi;
}

}  // namespace sb::event_detail
