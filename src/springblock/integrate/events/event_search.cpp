#include "springblock/integrate/events/event_search.hpp"

#include <cmath>

namespace sb::event_detail {

double EventSearch::locate(const Chain& c, const State& s, const Dopri5& dp, double h, const ActiveSet& active,
                           double window) {
  const int N = c.N;
  const double t = s.t;
  // At theta = 1 the continuous extension is the step's end point: read it, do not evaluate it.
  const double* u1 = dp.u1();
  const double* v1 = dp.v1();
  // Every watched block is screened at theta = 1/2: the stepped blocks' continuous extension
  // there is evaluated once, span by span (a vector loop), not block by block.
  dp.dense_spans(active.stepped(), 0.5, um_.data(), vm_.data());
  auto nb_u = [&](int j, double th) {
    switch (active.kind(j)) {
      case ActiveSet::kStepped: return th == 1.0 ? u1[j] : th == 0.5 ? um_[j] : dp.dense_u(j, th);
      case ActiveSet::kSettled: return active.settled_u(j, t + th * h);
      case ActiveSet::kModal: return active.modal_u(j, t + th * h);
      default: return s.u[j];  // a stuck neighbour does not move
    }
  };
  auto g = [&](int i, double th) {
    if (s.dir[i] != 0)
      return s.dir[i] * (th == 1.0 ? v1[i] : th == 0.5 && active.kind(i) == ActiveSet::kStepped ? vm_[i] : dp.dense_v(i, th));
    // Stuck: v_i = 0 (no damping force) and u_i does not move.
    double F = c.K_s * (c.v_slider * (t + th * h) - s.u[i]);
    if (i > 0) F += c.K_int * (nb_u(i - 1, th) - s.u[i]);
    if (i + 1 < N) F += c.K_int * (nb_u(i + 1, th) - s.u[i]);
    return c.f_static[i] - std::fabs(F);
  };
  const std::vector<int>& watched = active.watched();
  double best = 2.0;
  for (std::size_t k = 0; k < watched.size(); ++k) {
    const int i = watched[k];
    theta_[k] = 2.0;
    double lo = 0, hi = 2.0;
    if (g(i, 0.5) <= 0) hi = 0.5;
    else if (g(i, 1.0) <= 0) lo = 0.5, hi = 1.0;
    if (hi > 1.0) continue;
    // Bisection keeps g(lo) > 0 (or lo = 0, where the block has just switched), g(hi) <= 0.
    for (int it = 0; it < 100 && (hi - lo) * h > 4e-16 * std::fabs(t + hi * h); ++it) {
      const double mid = 0.5 * (lo + hi);
      (g(i, mid) > 0 ? lo : hi) = mid;
    }
    theta_[k] = hi;
    if (hi < best) best = hi;
  }
  hits_.clear();
  if (best <= 1.0)
    for (std::size_t k = 0; k < watched.size(); ++k)
      if (theta_[k] <= best + window) hits_.push_back(watched[k]);
  return best;
}

}  // namespace sb::event_detail
