#pragma once
// The root refinement shared by the event searches (events/event_search.cpp in a step's
// continuous extension, linear/edge_march.cpp in closed-form modes): a bracket [lo, hi] with the
// event function g > 0 at lo (nothing has happened) and g <= 0 at hi is shrunk until done(lo, hi),
// and the crossed end hi is returned, so that a switch applied there sees its event.
//
// Regula falsi with the Illinois modification: when the same end is kept twice its g is halved,
// which restores superlinear convergence where plain regula falsi stalls on one side. Whenever
// the secant point is not well inside the bracket the step is a bisection instead, so the bracket
// shrinks at every iteration and never loses the root; a g(lo) that is not known (NaN: a block
// that has just switched sits on its threshold at lo) forces bisection until lo has moved.
// A smooth g needs ~10 evaluations to round-off in t, where bisection needs ~50.
namespace sb::event_detail {

template <class G, class Done>
double refine_bracket(G&& g, double lo, double glo, double hi, double ghi, Done&& done, int max_iter) {
  int kept = 0;  // +1: lo kept last time, -1: hi kept last time
  for (int it = 0; it < max_iter && !done(lo, hi); ++it) {
    double mid = hi - ghi * (hi - lo) / (ghi - glo);
    const double w = hi - lo;
    if (!(mid > lo + 1e-3 * w && mid < hi - 1e-3 * w)) mid = 0.5 * (lo + hi);
    const double gm = g(mid);
    if (gm > 0) {
      lo = mid, glo = gm;
      if (kept == -1) ghi *= 0.5;
      kept = -1;
    } else {
      hi = mid, ghi = gm;
      if (kept == 1) glo *= 0.5;
      kept = 1;
    }
  }
  return hi;
}

}  // namespace sb::event_detail
