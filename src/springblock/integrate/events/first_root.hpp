#pragma once
// The event search's refinement of a bracket: the crossed end of [lo, hi] of an event function g
// with g(lo) > 0 >= g(hi), narrowed until the bracket is no wider than width(hi).
//
// Regula falsi with the Illinois rule (the value of a bracket end that stays put twice in a row
// is halved, so neither end can stall), each point kept half the final width inside the bracket
// (an estimate good to that closes the bracket from the far side with the next point), and a
// bisection whenever the bracket has not halved over the last two evaluations. The result has
// what a bisection's has: g(result) <= 0 (or NaN) within the final width of a point with g > 0.
// On the continuous extension of a Dormand-Prince step, which is a quartic, it takes ~7
// evaluations per event where a bisection to round-off in t took ~29 (measured on smooth and
// periodic:10,10 chains, N = 360), and the bisection's were most of the search's time.
//
// g(lo) <= 0 is allowed where lo is the start of the step: a block that has just switched may sit
// on its threshold there (g = 0); the first point is then a bisection's, as is every point after
// a NaN. EdgeMarch refines its brackets with a slope from every evaluation (Newton's method
// first); the continuous extension has no slope at hand, so this is the derivative-free form.
#include <algorithm>

namespace sb::event_detail {

// Width(hi): the largest final width of a bracket ending at hi (in the units of lo and hi).
template <class G, class Width>
double first_root(G g, double lo, double g_lo, double hi, double g_hi, Width width) {
  int moved = 0;              // the end that moved last: -1 lo, +1 hi
  double w1 = 2 * (hi - lo);  // the bracket's width one and two evaluations ago
  double w2 = w1;
  for (int it = 0; it < 200; ++it) {
    const double w = hi - lo, margin = 0.5 * width(hi);
    if (!(w > 2 * margin)) break;
    double x = lo + 0.5 * w;
    if (g_lo > 0 && g_hi <= 0 && w <= 0.5 * w2) x = std::clamp(lo + w * (g_lo / (g_lo - g_hi)), lo + margin, hi - margin);
    w2 = w1, w1 = w;
    const double gx = g(x);
    if (gx > 0) {
      lo = x, g_lo = gx;
      if (moved < 0) g_hi *= 0.5;
      moved = -1;
    } else {
      hi = x, g_hi = gx;
      if (moved > 0) g_lo *= 0.5;
      moved = 1;
    }
  }
  return hi;
}

}  // namespace sb::event_detail
